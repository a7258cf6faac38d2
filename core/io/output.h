// Outputs that are written completely or not at all, and the standard output checked at exit
// (docs/ERRORS.md, exit 8 "write-failed").
#pragma once
#include <memory>
#include <ostream>
#include <string>

#include "geometry/status.h"

namespace flood {

// One output of a command: `path`, or stdout for "-". A regular file (existing or new) is
// written to a temporary file beside it (same directory, so the rename cannot cross file
// systems) and renamed over `path` only once every write and the close succeeded: a full disk
// or a file-size limit leaves the old file as it was. A path that exists and is no regular
// file (/dev/null, a pipe, a terminal) is written in place: renaming over it would replace it.
class Output {
public:
    explicit Output(std::string path);
    ~Output();  // removes the temporary file of an output that was not committed
    Output(const Output&) = delete;
    Output& operator=(const Output&) = delete;

    std::ostream& stream();
    // True when this output goes to a temporary file that commit() renames into place: what
    // is written may still be discarded unseen (by not committing), so it can be written
    // before it is known to be wanted. False for stdout and outputs written in place.
    bool discardable() const;
    // Whether Output(path) would be discardable, asked before opening it (a pipe is not
    // opened until it is wanted: opening blocks until a reader comes).
    static bool discardable(const std::string& path);
    // Flushes, closes and renames. On failure prints "error: PATH: cannot write: REASON"
    // (the system's reason), removes the temporary and returns WriteFailed. With `message`
    // the line goes there instead of stderr (the viewer shows it in its status line).
    Status commit(std::string* message = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// True when both name the same existing file (device and inode: "a.json", "./a.json" and a
// symlink to it are one file); "-" is the file on stdin or stdout.
bool sameFile(const std::string& input, const std::string& output);

// Routes std::cout through a buffer that keeps the reason of a failed write; call first.
void takeOverStdout();

// Flushes std::cout and stdout; if anything written there was lost, prints "error: cannot
// write standard output: REASON" and returns `code`, or WriteFailed when `code` was 0.
int finishStdout(int code);

}  // namespace flood
