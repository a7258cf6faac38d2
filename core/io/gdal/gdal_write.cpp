// Writing triangles as a GIS layer (for QGIS and the like): one Polygon feature per triangle,
// its three corners as the exact doubles of the polygon's vertices.
//
// The dataset is made in a hidden folder beside the file it replaces (core/output.h: the end of
// OUT's symbolic links), under the format's extension (drivers choose by it), with its side
// files (a GeoPackage's -journal, FlatGeobuf's _temp.fgb) kept in there too; once closed it is
// given the old file's permissions and renamed over it. An existing GeoPackage is copied there
// first and only its layer "triangles" is replaced, so its other layers stay. Anything that
// fails leaves the old file as it was, and SIGINT/SIGTERM remove the folder.
#include <cpl_error.h>
#include <fcntl.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "io/gdal/gdal_module.h"
#include "io/output.h"

namespace flood::gdal::direct {
namespace {

constexpr const char* kLayer = "triangles";

// A byte copy of `from` as the new file `to`; 0 or the errno of what failed.
int copyFile(const std::string& from, const std::string& to) {
    int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) return errno;
    int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (out < 0) {
        int e = errno;
        ::close(in);
        return e;
    }
    std::vector<char> buf(1 << 16);
    int error = 0;
    for (;;) {
        ssize_t n = ::read(in, buf.data(), buf.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n < 0) error = errno;
            break;
        }
        for (ssize_t done = 0; !error && done < n;) {
            ssize_t k = ::write(out, buf.data() + done, size_t(n - done));
            if (k < 0 && errno == EINTR) continue;
            if (k < 0) error = errno;
            else done += k;
        }
        if (error) break;
    }
    ::close(in);
    if (::close(out) != 0 && !error) error = errno;
    return error;
}

// Whether `file` is a GeoPackage GDAL can open: then Flood adds its layer to it.
bool isGeoPackage(const std::string& file) {
    const char* const drivers[] = {"GPKG", nullptr};
    GDALDataset* ds = static_cast<GDALDataset*>(
        GDALOpenEx(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers, nullptr, nullptr));
    if (!ds) return false;
    GDALClose(ds);
    return true;
}

}  // namespace

Diagnostic writeTriangles(const std::string& path, const std::string& format, const Polygon& p,
                          const std::vector<Triangle>& triangles) {
    GDALAllRegister();
    CPLSetErrorHandler(CPLQuietErrorHandler);
    const bool gpkg = format == "gpkg";
    auto cannot = [&](const std::string& why) {
        return Diagnostic{Status::WriteFailed, path + ": cannot write: " + why};
    };
    auto failed = [&](const std::string& why) {
        std::string m = CPLGetLastErrorMsg();
        std::replace(m.begin(), m.end(), '\n', ' ');  // one line, as every diagnostic
        return cannot(why + (m.empty() ? "" : ": " + m));
    };
    // A device, a FIFO or a socket cannot be renamed over (that would replace it, /dev/null
    // by a regular file) nor written in place (the formats seek): refused, never touched.
    const OutputTarget target = outputTarget(path);
    if (target.error) return cannot(std::strerror(target.error));
    if (target.directory()) return cannot(std::strerror(EISDIR));
    if (target.exists && !target.regular())
        return cannot(std::string("--format ") + format + " needs a regular file, and " +
                      (target.file == path ? path : target.file) + " is " + target.kind() +
                      " (it was left untouched; write to a file)");
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(gpkg ? "GPKG" : "FlatGeobuf");
    if (!driver)
        return failed(std::string("GDAL has no ") + (gpkg ? "GPKG" : "FlatGeobuf") + " driver");
    // An existing GeoPackage keeps its other layers; its write-ahead log, if not empty, holds
    // changes a copy of the file would lose (another program has it open).
    const bool update = gpkg && target.regular() && isGeoPackage(target.file);
    struct stat wal;
    if (update && ::stat((target.file + "-wal").c_str(), &wal) == 0 && wal.st_size > 0)
        return cannot("the GeoPackage has a write-ahead log (" + target.file +
                      "-wal): another program has it open; close it and try again");

    namespace fs = std::filesystem;
    std::string folder = temporaryPattern(target.file);
    RemovedOnSignal guard;
    if (!guard.makeFolder(folder)) return cannot(std::strerror(errno));
    const std::string file = folder + "/" + kLayer + (gpkg ? ".gpkg" : ".fgb");
    for (const char* side : {"", "-journal", "-wal", "-shm"}) guard.add(file + side);
    guard.add(folder + "/" + kLayer + "_temp.fgb");
    std::error_code ec;
    auto removeFolder = [&] {
        fs::remove_all(folder, ec);
        guard.forget();
    };

    CPLErrorReset();
    GDALDataset* ds = nullptr;
    if (update) {
        if (int e = copyFile(target.file, file)) {
            removeFolder();
            return cannot("copying the GeoPackage to add the layer: " +
                          std::string(std::strerror(e)));
        }
        const char* const drivers[] = {"GPKG", nullptr};
        ds = static_cast<GDALDataset*>(
            GDALOpenEx(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE, drivers, nullptr, nullptr));
    } else {
        ds = driver->Create(file.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
    }
    if (!ds) {
        Diagnostic d = failed(update ? "cannot open the GeoPackage to add the layer"
                                     : "cannot create the dataset");
        removeFolder();
        return d;
    }
    auto discard = [&](const std::string& why) {
        Diagnostic d = failed(why);
        GDALClose(ds);
        removeFolder();
        return d;
    };
    for (int k = 0; update && k < ds->GetLayerCount(); ++k)
        if (std::string(ds->GetLayer(k)->GetName()) == kLayer) {
            if (ds->DeleteLayer(k) != OGRERR_NONE)
                return discard("cannot replace the layer " + std::string(kLayer));
            break;
        }
    OGRLayer* layer = ds->CreateLayer(kLayer, nullptr, wkbPolygon, nullptr);
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
        removeFolder();
        return d;
    }
    // FlatGeobuf does not check the close of its files, where stdio writes its last buffer: a
    // full disk there went unnoticed (tests/cli/write_faults_test.cpp). Read back, it shows.
    if (std::string problem = readBackProblem(file, kLayer, (long long)triangles.size());
        !problem.empty()) {
        removeFolder();
        return cannot("GDAL reported no error, but the dataset written is incomplete: " + problem);
    }
    int e = adoptPermissions(-1, file, target);
    if (!e && ::rename(file.c_str(), target.file.c_str()) != 0) e = errno;
    removeFolder();
    if (e) return cannot(std::strerror(e));
    return {};
}

}  // namespace flood::gdal::direct
