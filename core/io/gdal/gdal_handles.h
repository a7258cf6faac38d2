// Owning handles for GDAL's C++ objects, which are freed by GDAL's own calls (internal to the
// plug-in: its reader and writer).
#pragma once
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <memory>

namespace flood::gdal::direct {

struct DatasetCloser {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

struct FeatureCloser {
    void operator()(OGRFeature* f) const { OGRFeature::DestroyFeature(f); }
};
using FeaturePtr = std::unique_ptr<OGRFeature, FeatureCloser>;

}  // namespace flood::gdal::direct
