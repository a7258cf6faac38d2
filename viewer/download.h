// Saving in the page (docs/WEB.md): a file the user asked for is written, as on the desktop,
// into the program's file system, which in a browser is in memory and out of the user's reach;
// offerDownload hands it over to the browser as a download. On the desktop it does nothing:
// the file is where the user said.
#pragma once
#include <string>

namespace flood::view {

// A written file as a download gives it: its bytes and its name without the folders.
struct Download {
    std::string name;
    std::string bytes;
};

// Reads the whole of `path` back (what the user will get). False and `error` naming the file
// when it cannot be opened or read.
bool readDownload(const std::string& path, Download& out, std::string* error);

// The web: `path` read back and offered as a download of its own name (a Blob, an object URL,
// a temporary <a download> clicked); false and `error` when it cannot be read back. The
// desktop: true, nothing done.
bool offerDownload(const std::string& path, std::string* error);

}  // namespace flood::view
