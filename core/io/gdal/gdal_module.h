// The GDAL module (flood-gdal.so) as its loader sees it. Linking GDAL and its ~110 libraries
// cost every run of `flood` about 170 million instructions of loading and relocation before
// main(), thousands of times a small triangulation, so only a run that opens or writes a GIS
// dataset loads them: the module is opened with dlopen() on first use (gdal_load.cpp) and
// gives this table.
// Internal to core/io/gdal/.
#pragma once
#include "flood/io/gdal/gdal_io.h"

namespace flood::gdal {

// The functions of gdal_io.h that need GDAL, defined in the module.
namespace direct {
DatasetRead readFeatures(const std::string& path, const Selection& s);
ReadResult readPolygon(const std::string& path, const Selection& s);
std::string outputDriver(const std::string& format, const std::string& path);
Diagnostic writeLayers(const std::string& path, const DatasetOutput& o,
                       const std::vector<GisLayer>& layers, std::vector<std::string>& warnings);
// The dataset `file` read back as a user's tool reads it, opened once: "" when each layer
// (name, features written; the only layer of a one-layer format) gives every one of its
// features without an error, else what is wrong ("reading it back gives 12 of 16 features").
// A writer's check: GDAL does not always report a failed write.
std::string readBackProblem(const std::string& file,
                            const std::vector<std::pair<std::string, long long>>& layers);
}  // namespace direct

struct ModuleTable {
    int version;  // kModuleVersion: a module from another build is refused
    DatasetRead (*readFeatures)(const std::string&, const Selection&);
    ReadResult (*readPolygon)(const std::string&, const Selection&);
    std::string (*outputDriver)(const std::string&, const std::string&);
    Diagnostic (*writeLayers)(const std::string&, const DatasetOutput&,
                              const std::vector<GisLayer>&, std::vector<std::string>&);
};
constexpr int kModuleVersion = 3;

}  // namespace flood::gdal

// The module's one exported symbol.
extern "C" const flood::gdal::ModuleTable* flood_gdal_module();
