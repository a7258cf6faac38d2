// Writing triangles as a GIS layer (for QGIS and the like), in any vector format GDAL creates:
// one Polygon feature per triangle, or one MultiPolygon per source feature, its corners the
// exact doubles of the polygon's vertices; with the source layer's CRS and fields copied, and
// each source feature's FID and attribute values (as ogr2ogr copies them).
//
// The dataset is made in a hidden folder beside the file it replaces (core/output.h: the end of
// OUT's symbolic links), under OUT's own name (drivers choose by the extension, and a
// Shapefile's side files take its stem), with its side files (a GeoPackage's -journal,
// FlatGeobuf's _temp.fgb, a Shapefile's .dbf, .shx, .prj) kept in there too; once closed each
// file is given the old file's permissions and renamed beside it, the main file last. An
// existing GeoPackage is copied there first and only its layer "triangles" is replaced, so its
// other layers stay. Anything that fails leaves the old files as they were, and
// SIGINT/SIGTERM remove the folder.
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
#include <memory>
#include <unordered_map>
#include <vector>

#include "flood/io/output.h"
#include "io/gdal/gdal_handles.h"
#include "io/gdal/gdal_module.h"

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

// "gpkg", "GeoJSON", "esri shapefile" == "ESRI Shapefile": driver names are case-blind.
bool sameName(const std::string& a, const char* b) { return EQUAL(a.c_str(), b); }

// Whether `ext` is one of a driver's extensions ("gpkg", "shp", ...; DMD_EXTENSIONS lists them
// separated by spaces).
bool hasExtension(GDALDriver& d, const std::string& ext) {
    const char* list = d.GetMetadataItem(GDAL_DMD_EXTENSIONS);
    if (!list) list = d.GetMetadataItem(GDAL_DMD_EXTENSION);
    if (!list || ext.empty()) return false;
    const CPLStringList words(CSLTokenizeString2(list, " ", 0));
    for (int i = 0; i < words.size(); ++i)
        if (sameName(ext, words[i])) return true;
    return false;
}

// The files a driver makes beside `file` (removed on a signal); those named by the stem
// (".prj") that the new dataset lacks are removed from beside OUT at the rename, so an old
// .prj never describes the new layer.
std::vector<std::string> sideSuffixes(const std::string& driver) {
    if (driver == "GPKG" || driver == "SQLite") return {"-journal", "-wal", "-shm"};
    if (driver == "FlatGeobuf") return {"_temp.fgb"};
    if (driver == "ESRI Shapefile") return {".shx", ".dbf", ".prj", ".cpg"};
    if (driver == "CSV") return {".csvt", ".prj"};
    return {};
}

std::string stemOf(const std::string& file) {
    size_t slash = file.rfind('/'), dot = file.rfind('.');
    return dot == std::string::npos || (slash != std::string::npos && dot < slash)
               ? file
               : file.substr(0, dot);
}

// The source layer whose CRS, fields and attribute values are copied: the layer read, with
// the same filter, so it lists the same features. Null (nothing copied) when GDAL cannot open
// the source: a ring array or WKT has no CRS and no fields.
struct Source {
    DatasetPtr ds;
    OGRLayer* layer = nullptr;
    Source(const LayerOutput& o) {
        if (o.source.empty() || o.source == "-") return;
        ds.reset(static_cast<GDALDataset*>(GDALOpenEx(
            o.source.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
        if (!ds) return;
        layer = o.selection.layer.empty() ? (ds->GetLayerCount() == 1 ? ds->GetLayer(0) : nullptr)
                                          : ds->GetLayerByName(o.selection.layer.c_str());
        if (layer && !o.selection.where.empty() &&
            layer->SetAttributeFilter(o.selection.where.c_str()) != OGRERR_NONE)
            layer = nullptr;
    }
};

// The name of a field Flood adds: `want`, or "flood_" + want when the source has a field so
// named.
std::string freeName(const OGRFeatureDefn* defn, const char* want) {
    return defn && defn->GetFieldIndex(want) >= 0 ? std::string("flood_") + want : want;
}

}  // namespace

std::string outputDriver(const std::string& format, const std::string& path) {
    GDALAllRegister();
    CPLSetErrorHandler(CPLQuietErrorHandler);
    std::string ext = format;
    if (ext.empty()) {
        size_t slash = path.rfind('/'), dot = path.rfind('.');
        if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
        ext = path.substr(dot + 1);
    }
    // Drivers that create vector datasets: the one so named, else the one whose own extension
    // it is (.gpkg is GPKG's, though SQLite lists it too), else the first that lists it.
    std::vector<GDALDriver*> drivers;
    GDALDriverManager* m = GetGDALDriverManager();
    for (int i = 0; i < m->GetDriverCount(); ++i)
        if (GDALDriver* d = m->GetDriver(i);
            d->GetMetadataItem(GDAL_DCAP_VECTOR) && d->GetMetadataItem(GDAL_DCAP_CREATE))
            drivers.push_back(d);
    for (GDALDriver* d : drivers)
        if (!format.empty() && sameName(format, d->GetDescription())) return d->GetDescription();
    for (GDALDriver* d : drivers)
        if (const char* own = d->GetMetadataItem(GDAL_DMD_EXTENSION); own && sameName(ext, own))
            return d->GetDescription();
    for (GDALDriver* d : drivers)
        if (hasExtension(*d, ext)) return d->GetDescription();
    return "";
}

Diagnostic writeLayer(const std::string& path, const LayerOutput& o,
                      const std::vector<TriangulatedFeature>& features,
                      std::vector<std::string>& warnings) {
    GDALAllRegister();
    CPLSetErrorHandler(CPLQuietErrorHandler);
    const bool gpkg = o.driver == "GPKG";
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
        return cannot(std::string("--format ") + o.format + " needs a regular file, and " +
                      (target.file == path ? path : target.file) + " is " + target.kind() +
                      " (it was left untouched; write to a file)");
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(o.driver.c_str());
    if (!driver) return failed("GDAL has no " + o.driver + " driver");
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
    const std::string base = fs::path(target.file).filename().string();
    const std::string file = folder + "/" + base;
    guard.add(file);
    for (const std::string& side : sideSuffixes(o.driver))
        guard.add(side[0] == '.' ? stemOf(file) + side : file + side);
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
    Source source(o);
    CPLErrorReset();  // a source GDAL cannot open (a ring array) is no failure of the writing
    OGRFeatureDefn* from = source.layer ? source.layer->GetLayerDefn() : nullptr;
    const OGRSpatialReference* sourceCrs = source.layer ? source.layer->GetSpatialRef() : nullptr;
    OGRSpatialReference* crs = sourceCrs ? sourceCrs->Clone() : nullptr;
    // CSV keeps the geometry only as a WKT column when asked.
    CPLStringList options;
    if (o.driver == "CSV") {
        options.SetNameValue("GEOMETRY", "AS_WKT");
        options.SetNameValue("CREATE_CSVT", "YES");  // the fields' types, for readers
    }
    OGRLayer* layer =
        ds->CreateLayer(kLayer, crs, o.multipolygon ? wkbMultiPolygon : wkbPolygon, options.List());
    if (crs) crs->Release();  // the layer holds its own reference
    if (!layer) return discard("cannot create the layer");
    // The source's fields, then the source FID, then the triangle's number in its feature;
    // each found by where it was added (a Shapefile cuts names to 10 bytes; KML has fields of
    // its own first).
    auto addField = [&](OGRFieldDefn* field) {
        OGRFeatureDefn* defn = layer->GetLayerDefn();
        const int before = defn->GetFieldCount();
        if (layer->CreateField(field, TRUE) != OGRERR_NONE) return -1;
        return defn->GetFieldCount() == before + 1 ? before : -1;
    };
    const int fieldCount = from ? from->GetFieldCount() : 0;
    std::vector<int> map;
    for (int i = 0; i < fieldCount; ++i) {
        map.push_back(addField(from->GetFieldDefn(i)));
        if (map.back() < 0)
            return discard(std::string("cannot create the field ") +
                           from->GetFieldDefn(i)->GetNameRef());
    }
    OGRFieldDefn fidDefn(freeName(from, "src_fid").c_str(), OFTInteger64);
    OGRFieldDefn triDefn(freeName(from, "triangle").c_str(), OFTInteger64);
    const int fidField = addField(&fidDefn);
    const int triField = o.multipolygon ? 0 : addField(&triDefn);
    if (fidField < 0 || triField < 0) return discard("cannot create the fields");

    // One transaction: GeoPackage otherwise commits every feature on its own.
    const bool transaction = ds->StartTransaction() == OGRERR_NONE;
    auto ring = [&](const Polygon& p, const Triangle& t) {
        auto* r = new OGRLinearRing;
        for (int k = 0; k < 4; ++k) r->addPoint(p.vertices[t[k % 3]].x, p.vertices[t[k % 3]].y);
        auto* tri = new OGRPolygon;
        tri->addRingDirectly(r);
        return tri;
    };
    auto write = [&](const TriangulatedFeature& tf, OGRFeature* src) -> bool {
        FeaturePtr f(OGRFeature::CreateFeature(layer->GetLayerDefn()));
        if (src && f->SetFieldsFrom(src, map.data(), TRUE) != OGRERR_NONE) return false;
        f->SetField(fidField, GIntBig(tf.fid));
        if (o.multipolygon) {
            auto* mp = new OGRMultiPolygon;
            for (const Triangle& t : tf.triangles) mp->addGeometryDirectly(ring(*tf.polygon, t));
            f->SetGeometryDirectly(mp);
            f->SetFID(tf.fid);  // kept where the format can (ogr2ogr -preserve_fid)
            OGRErr e = layer->CreateFeature(f.get());
            if (e != OGRERR_NONE) {  // the FID taken or refused: a new one
                f->SetFID(OGRNullFID);
                e = layer->CreateFeature(f.get());
            }
            return e == OGRERR_NONE;
        }
        for (size_t i = 0; i < tf.triangles.size(); ++i) {
            f->SetField(triField, GIntBig(i));
            f->SetGeometryDirectly(ring(*tf.polygon, tf.triangles[i]));
            f->SetFID(OGRNullFID);
            if (layer->CreateFeature(f.get()) != OGRERR_NONE) return false;
        }
        return true;
    };
    // In the source's order, each with its own attributes; features the source does not list
    // (a ring array has no fields) after, without.
    std::unordered_map<int64_t, size_t> byFid;
    for (size_t i = 0; i < features.size(); ++i) byFid.emplace(features[i].fid, i);
    std::vector<bool> done(features.size());
    if (source.layer) {
        source.layer->ResetReading();
        for (FeaturePtr src; (src.reset(source.layer->GetNextFeature()), src);) {
            auto it = byFid.find(src->GetFID());
            if (it == byFid.end()) continue;
            if (done[it->second]) {
                warnings.push_back(o.source + ": FID " + std::to_string(src->GetFID()) +
                                   " is not unique: its triangles carry the first one's fields");
                continue;
            }
            done[it->second] = true;
            if (!write(features[it->second], src.get()))
                return discard("feature " + std::to_string(src->GetFID()));
        }
    }
    for (size_t i = 0; i < features.size(); ++i)
        if (!done[i] && !write(features[i], nullptr))
            return discard("feature " + std::to_string(features[i].fid));
    if (transaction && ds->CommitTransaction() != OGRERR_NONE) return discard("commit");
    CPLErrorReset();
    GDALClose(ds);
    if (CPLGetLastErrorType() >= CE_Failure) {
        Diagnostic d = failed("closing the dataset");
        removeFolder();
        return d;
    }
    // Side files first, the main file last: it is what a reader opens.
    const std::string dir = target.file.substr(0, target.file.size() - base.size());
    std::vector<std::string> made;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.path().filename() != base) made.push_back(entry.path().filename().string());
    int e = 0;
    for (const std::string& side : sideSuffixes(o.driver))
        if (side[0] == '.') {
            const std::string old = stemOf(target.file) + side;
            if (std::find(made.begin(), made.end(), fs::path(old).filename().string()) ==
                    made.end() &&
                ::unlink(old.c_str()) != 0 && errno != ENOENT)
                e = errno;
        }
    made.push_back(base);
    // FlatGeobuf does not check the close of its files, where stdio writes its last buffer: a
    // full disk there went unnoticed (tests/cli/write_faults_test.cpp). Read back, it shows.
    long long written = 0;
    for (const TriangulatedFeature& tf : features)
        written += o.multipolygon ? 1 : (long long)tf.triangles.size();
    if (std::string problem = readBackProblem(folder + "/" + base, kLayer, written);
        !problem.empty()) {
        removeFolder();
        return cannot("GDAL reported no error, but the dataset written is incomplete: " + problem);
    }
    for (const std::string& name : made) {
        if (e) break;
        e = adoptPermissions(-1, folder + "/" + name, target);
        if (!e && ::rename((folder + "/" + name).c_str(), (dir + name).c_str()) != 0) e = errno;
    }
    removeFolder();
    if (e) return cannot(std::strerror(e));
    return {};
}

}  // namespace flood::gdal::direct
