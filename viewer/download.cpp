#include "download.h"

#include <filesystem>
#include <fstream>
#include <iterator>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>

// The bytes are copied out of the wasm heap into a Blob; the object URL is revoked once the
// browser has had time to start the download (revoking it at once can cancel it).
// clang-format off
EM_JS(void, flood_web_download, (const char* name, const char* bytes, size_t size), {
    const file = UTF8ToString(name);
    const ext = file.slice(file.lastIndexOf(".") + 1).toLowerCase();
    const type = {png: "image/png", svg: "image/svg+xml", gif: "image/gif",
                  json: "application/geo+json", geojson: "application/geo+json"}[ext] ||
                 "application/octet-stream";
    const url = URL.createObjectURL(new Blob([HEAPU8.slice(bytes, bytes + size)], {type}));
    const a = document.createElement("a");
    a.href = url;
    a.download = file;
    a.style.display = "none";
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 60000);
});
// clang-format on
#endif

namespace flood::view {

bool readDownload(const std::string& path, Download& out, std::string* error) {
    std::error_code ec;
    std::ifstream in;
    if (std::filesystem::is_regular_file(path, ec)) in.open(path, std::ios::binary);
    if (in) out.bytes.assign(std::istreambuf_iterator<char>(in), {});
    if (!in.is_open() || in.bad()) {
        if (error) *error = "error: " + path + ": cannot read it back to download it";
        return false;
    }
    const size_t slash = path.find_last_of('/');
    out.name = slash == std::string::npos ? path : path.substr(slash + 1);
    return true;
}

bool offerDownload(const std::string& path, std::string* error) {
#ifdef __EMSCRIPTEN__
    Download d;
    if (!readDownload(path, d, error)) return false;
    flood_web_download(d.name.c_str(), d.bytes.data(), d.bytes.size());
#else
    (void)path, (void)error;
#endif
    return true;
}

}  // namespace flood::view
