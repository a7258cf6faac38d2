// The module's entry point: the table of its functions (gdal_module.h).
#include "io/gdal/gdal_module.h"

extern "C" __attribute__((visibility("default"))) const flood::gdal::ModuleTable*
flood_gdal_module() {
    using namespace flood::gdal;
    static const ModuleTable table{kModuleVersion, direct::readFeatures, direct::readPolygon,
                                   direct::outputDriver, direct::writeLayers};
    return &table;
}
