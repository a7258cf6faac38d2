// gdal_io.h's GDAL functions, forwarded to the module loaded on first use (gdal_module.h).
// Where it is looked for: $FLOOD_GDAL_MODULE when set, and nowhere else; otherwise beside an
// installed executable (BIN/../LIBDIR/flood/), then where this build made it. A run that cannot load it gets one message
// naming the file it was reading or writing and every place tried.
#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <mutex>

#include "io/gdal/gdal_module.h"

namespace flood::gdal {
namespace {

struct Loaded {
    const ModuleTable* table = nullptr;
    std::string why;  // what failed, when table is null
};

std::string executableDir() {
    char buf[4096];
    ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) return "";
    std::string exe(buf, size_t(n));
    return exe.substr(0, exe.find_last_of('/'));
}

const Loaded& module() {
    static Loaded loaded;
    static std::once_flag once;
    std::call_once(once, [] {
        std::vector<std::string> places;
        if (const char* env = std::getenv("FLOOD_GDAL_MODULE"); env && *env) {
            places.emplace_back(env);  // given: the only place
        } else {
            if (std::string dir = executableDir(); !dir.empty())
                places.push_back(dir + "/../" FLOOD_GDAL_MODULE_LIBDIR "/flood/flood-gdal.so");
            places.emplace_back(FLOOD_GDAL_MODULE_BUILT);
        }
        for (const std::string& place : places) {
            void* h = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
            const char* err = h ? nullptr : dlerror();
            auto entry =
                h ? reinterpret_cast<const ModuleTable* (*)()>(dlsym(h, "flood_gdal_module"))
                  : nullptr;
            const ModuleTable* t = entry ? entry() : nullptr;
            if (t && t->version == kModuleVersion) {
                loaded.table = t;
                return;
            }
            loaded.why +=
                (loaded.why.empty() ? "" : "; ") +
                (err ? std::string(err) : place + ": not a flood-gdal module of this version");
        }
    });
    return loaded;
}

}  // namespace

std::string unavailable(const std::string& path) {
    if (module().table) return "";
    return path + ": GIS datasets need Flood's GDAL module, which could not be loaded (" +
           module().why + ")";
}

DatasetRead readFeatures(const std::string& path, const Selection& s) {
    if (const ModuleTable* t = module().table) return t->readFeatures(path, s);
    DatasetRead whole;
    whole.features.emplace_back();
    whole.features.back().read.diagnostic = {Status::Malformed, unavailable(path)};
    return whole;
}

ReadResult readPolygon(const std::string& path, const Selection& s) {
    if (const ModuleTable* t = module().table) return t->readPolygon(path, s);
    ReadResult rr;
    rr.diagnostic = {Status::Malformed, unavailable(path)};
    return rr;
}

std::string outputDriver(const std::string& format, const std::string& path) {
    if (const ModuleTable* t = module().table) return t->outputDriver(format, path);
    return "";
}

Diagnostic writeLayers(const std::string& path, const DatasetOutput& o,
                       const std::vector<GisLayer>& layers, std::vector<std::string>& warnings) {
    if (const ModuleTable* t = module().table) return t->writeLayers(path, o, layers, warnings);
    return {Status::WriteFailed, unavailable(path)};
}

}  // namespace flood::gdal
