// Writing triangles as a GIS layer (for QGIS and the like): one Polygon feature per triangle,
// its three corners as the exact doubles of the polygon's vertices.
#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "io/gdal/gdal_module.h"

namespace flood::gdal::direct {

Diagnostic writeTriangles(const std::string& path, const std::string& format, const Polygon& p,
                          const std::vector<Triangle>& triangles) {
    GDALAllRegister();
    CPLSetErrorHandler(CPLQuietErrorHandler);
    const bool gpkg = format == "gpkg";
    auto failed = [&](const std::string& why) {
        std::string m = CPLGetLastErrorMsg();
        std::replace(m.begin(), m.end(), '\n', ' ');  // one line, as every diagnostic
        return Diagnostic{Status::WriteFailed,
                          path + ": cannot write: " + why + (m.empty() ? "" : ": " + m)};
    };
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(gpkg ? "GPKG" : "FlatGeobuf");
    if (!driver)
        return failed(std::string("GDAL has no ") + (gpkg ? "GPKG" : "FlatGeobuf") + " driver");
    // Written beside the target under a temporary name with the format's extension (drivers
    // choose by it), renamed over `path` once closed: a failure leaves any old file as it was.
    namespace fs = std::filesystem;
    fs::path target(path);
    fs::path tmp = target.parent_path() / ("." + target.filename().string() + ".tmp" +
                                           std::to_string(::getpid()) + (gpkg ? ".gpkg" : ".fgb"));
    std::error_code ec;
    fs::remove(tmp, ec);
    CPLErrorReset();
    GDALDataset* ds = driver->Create(tmp.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
    if (!ds) return failed("cannot create the dataset");
    auto discard = [&](const std::string& why) {
        Diagnostic d = failed(why);
        GDALClose(ds);
        fs::remove(tmp, ec);
        return d;
    };
    OGRLayer* layer = ds->CreateLayer("triangles", nullptr, wkbPolygon, nullptr);
    if (!layer) return discard("cannot create the layer");
    OGRFieldDefn field("triangle", OFTInteger64);
    if (layer->CreateField(&field) != OGRERR_NONE) return discard("cannot create the field");
    // One transaction: GeoPackage otherwise commits every feature on its own.
    const bool transaction = ds->StartTransaction() == OGRERR_NONE;
    for (size_t i = 0; i < triangles.size(); ++i) {
        OGRLinearRing ring;
        for (int k = 0; k < 4; ++k) {
            const Point& v = p.vertices[triangles[i][k % 3]];
            ring.addPoint(v.x, v.y);
        }
        OGRPolygon tri;
        tri.addRing(&ring);
        OGRFeature* f = OGRFeature::CreateFeature(layer->GetLayerDefn());
        f->SetField(0, GIntBig(i));
        f->SetGeometry(&tri);
        OGRErr e = layer->CreateFeature(f);
        OGRFeature::DestroyFeature(f);
        if (e != OGRERR_NONE) return discard("triangle " + std::to_string(i));
    }
    if (transaction && ds->CommitTransaction() != OGRERR_NONE) return discard("commit");
    CPLErrorReset();
    GDALClose(ds);
    if (CPLGetLastErrorType() >= CE_Failure) {
        Diagnostic d = failed("closing the dataset");
        fs::remove(tmp, ec);
        return d;
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        Diagnostic d{Status::WriteFailed, path + ": cannot write: " + ec.message()};
        fs::remove(tmp, ec);
        return d;
    }
    return {};
}

}  // namespace flood::gdal::direct
