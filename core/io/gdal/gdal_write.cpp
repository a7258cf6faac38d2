// Writing Flood's layers (triangles, findings, a kept feature) in any vector format GDAL
// creates, for QGIS and the like: points, lines and polygons at the exact doubles given, with
// the sources' CRS and, where asked, the source layer's fields and each source feature's values
// (as ogr2ogr copies them).
//
// The dataset is made in a hidden folder beside the file it replaces (core/output.h: the end of
// OUT's symbolic links), under OUT's own name (drivers choose by the extension, and a
// Shapefile's side files take its stem), with its side files (a GeoPackage's -journal,
// FlatGeobuf's _temp.fgb, a Shapefile's .dbf, .shx, .prj) kept in there too; once closed each
// file is given the old file's permissions and renamed beside it, the main file last. An
// existing GeoPackage is copied there first and only the layers written are replaced, so its
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
#include <unordered_set>
#include <vector>

#include "flood/io/output.h"
#include "io/gdal/gdal_handles.h"
#include "io/gdal/gdal_module.h"

namespace flood::gdal::direct {
namespace {

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

// A source layer (LayerSource): the layer read, with the same filter, so it lists the same
// features. No layer when GDAL cannot open it: a ring array or WKT has no CRS and no fields.
struct Source {
    DatasetPtr ds;
    OGRLayer* layer = nullptr;
    explicit Source(const LayerSource& s) {
        if (s.file.empty() || s.file == "-") return;
        ds.reset(static_cast<GDALDataset*>(GDALOpenEx(
            s.file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
        if (!ds) return;
        layer = s.selection.layer.empty() ? (ds->GetLayerCount() == 1 ? ds->GetLayer(0) : nullptr)
                                          : ds->GetLayerByName(s.selection.layer.c_str());
        if (layer && !s.selection.where.empty() &&
            layer->SetAttributeFilter(s.selection.where.c_str()) != OGRERR_NONE)
            layer = nullptr;
    }
};

// The CRS the sources agree on (a clone, or null); when they disagree, null and a warning.
OGRSpatialReference* agreedCrs(const std::vector<LayerSource>& sources, const std::string& out,
                               std::vector<std::string>& warnings) {
    std::vector<std::pair<std::string, std::unique_ptr<OGRSpatialReference>>> seen;
    bool differ = false;
    for (const LayerSource& s : sources) {
        Source source(s);
        const OGRSpatialReference* crs = source.layer ? source.layer->GetSpatialRef() : nullptr;
        if (!crs) continue;
        if (!seen.empty() && !crs->IsSame(seen.front().second.get())) differ = true;
        const std::string name =
            s.file + (s.selection.layer.empty() ? "" : " (layer " + s.selection.layer + ")");
        if (seen.empty() || !crs->IsSame(seen.back().second.get()))
            seen.emplace_back(name, std::unique_ptr<OGRSpatialReference>(crs->Clone()));
    }
    CPLErrorReset();  // a source GDAL cannot open (a ring array) is no failure of the writing
    if (!differ) return seen.empty() ? nullptr : seen.front().second.release();
    std::string list;
    for (auto& [name, crs] : seen) {
        crs->AutoIdentifyEPSG();
        const char* code = crs->GetAuthorityCode(nullptr);
        list += (list.empty() ? "" : ", ") + name + ": " +
                (code ? "EPSG:" + std::string(code) : std::string(crs->GetName()));
    }
    warnings.push_back(out + ": the inputs have different CRSs (" + list +
                       "): the layers are written without one");
    return nullptr;
}

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

namespace {

OGRGeometry* geometryOf(GisGeometry type, const GisFeature& f) {
    if (f.parts.empty() || f.parts[0].empty()) return nullptr;
    auto points = [](OGRSimpleCurve* c, const std::vector<Point>& ps, bool close) {
        for (const Point& p : ps) c->addPoint(p.x, p.y);
        if (close && !(ps.front() == ps.back())) c->addPoint(ps.front().x, ps.front().y);
        return c;
    };
    switch (type) {
        case GisGeometry::Point: return new OGRPoint(f.parts[0][0].x, f.parts[0][0].y);
        case GisGeometry::LineString: return points(new OGRLineString, f.parts[0], false);
        case GisGeometry::Polygon: {
            auto* poly = new OGRPolygon;
            for (const auto& ring : f.parts)
                poly->addRingDirectly(
                    static_cast<OGRLinearRing*>(points(new OGRLinearRing, ring, true)));
            return poly;
        }
        case GisGeometry::MultiPolygon: {
            auto* mp = new OGRMultiPolygon;
            for (const auto& ring : f.parts) {
                auto* poly = new OGRPolygon;
                poly->addRingDirectly(
                    static_cast<OGRLinearRing*>(points(new OGRLinearRing, ring, true)));
                mp->addGeometryDirectly(poly);
            }
            return mp;
        }
        case GisGeometry::Source: break;
    }
    return nullptr;
}

OGRwkbGeometryType ogrType(GisGeometry type, OGRLayer* source) {
    switch (type) {
        case GisGeometry::Point: return wkbPoint;
        case GisGeometry::LineString: return wkbLineString;
        case GisGeometry::Polygon: return wkbPolygon;
        case GisGeometry::MultiPolygon: return wkbMultiPolygon;
        case GisGeometry::Source: break;
    }
    return source ? source->GetGeomType() : wkbUnknown;
}

}  // namespace

Diagnostic writeLayers(const std::string& path, const DatasetOutput& o,
                       const std::vector<GisLayer>& layers, std::vector<std::string>& warnings) {
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
    if (o.noReplace && target.exists) return cannot(std::strerror(EEXIST));
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
    for (const GisLayer& l : layers)
        for (int k = 0; update && k < ds->GetLayerCount(); ++k)
            if (l.name == ds->GetLayer(k)->GetName()) {
                if (ds->DeleteLayer(k) != OGRERR_NONE)
                    return discard("cannot replace the layer " + l.name);
                break;
            }
    std::unique_ptr<Source> source =
        std::make_unique<Source>(o.sources.empty() ? LayerSource{} : o.sources.front());
    std::unique_ptr<OGRSpatialReference, void (*)(OGRSpatialReference*)> crs(
        agreedCrs(o.sources, path, warnings), [](OGRSpatialReference* c) {
            if (c) c->Release();
        });
    CPLErrorReset();  // a source GDAL cannot open (a ring array) is no failure of the writing
    OGRFeatureDefn* from = source->layer ? source->layer->GetLayerDefn() : nullptr;
    // CSV keeps the geometry only as a WKT column when asked.
    CPLStringList options;
    if (o.driver == "CSV") {
        options.SetNameValue("GEOMETRY", "AS_WKT");
        options.SetNameValue("CREATE_CSVT", "YES");  // the fields' types, for readers
    }
    std::vector<std::pair<std::string, long long>> written;  // each layer's name and features
    // One transaction per layer: GeoPackage otherwise commits every feature on its own.
    for (const GisLayer& l : layers) {
        // A field "fid" (flood check's findings) is no GeoPackage FID column: that is named
        // ogc_fid then (as SQLite names it).
        CPLStringList layerOptions(options);
        for (const GisField& field : l.fields)
            if (gpkg && EQUAL(field.name.c_str(), "fid"))
                layerOptions.SetNameValue("FID", "ogc_fid");
        OGRLayer* layer = ds->CreateLayer(l.name.c_str(), crs.get(),
                                          ogrType(l.geometry, source->layer), layerOptions.List());
        if (!layer) return discard("cannot create the layer " + l.name);
        // The source's fields, then Flood's; each found by where it was added (a Shapefile
        // cuts names to 10 bytes; KML has fields of its own first).
        auto addField = [&](OGRFieldDefn* field) {
            OGRFeatureDefn* defn = layer->GetLayerDefn();
            const int before = defn->GetFieldCount();
            if (layer->CreateField(field, TRUE) != OGRERR_NONE) return -1;
            return defn->GetFieldCount() == before + 1 ? before : -1;
        };
        const OGRFeatureDefn* copied = l.sourceFields ? from : nullptr;
        const int fieldCount = copied ? copied->GetFieldCount() : 0;
        std::vector<int> map;
        for (int i = 0; i < fieldCount; ++i) {
            map.push_back(addField(from->GetFieldDefn(i)));
            if (map.back() < 0)
                return discard(std::string("cannot create the field ") +
                               from->GetFieldDefn(i)->GetNameRef());
        }
        std::vector<int> own;
        for (const GisField& field : l.fields) {
            OGRFieldDefn defn(freeName(copied, field.name.c_str()).c_str(),
                              field.integer ? OFTInteger64 : OFTString);
            own.push_back(addField(&defn));
            if (own.back() < 0) return discard("cannot create the field " + field.name);
        }
        const bool transaction = ds->StartTransaction() == OGRERR_NONE;
        GisFeature g;
        auto write = [&](size_t i, OGRFeature* src) -> bool {
            g.clear();
            l.feature(i, g);
            FeaturePtr f(OGRFeature::CreateFeature(layer->GetLayerDefn()));
            if (src && copied && f->SetFieldsFrom(src, map.data(), TRUE) != OGRERR_NONE)
                return false;
            for (size_t k = 0; k < own.size() && k < g.values.size(); ++k) {
                if (const auto* n = std::get_if<int64_t>(&g.values[k]))
                    f->SetField(own[k], GIntBig(*n));
                else if (const auto* t = std::get_if<std::string>(&g.values[k]))
                    f->SetField(own[k], t->c_str());
                else f->SetFieldNull(own[k]);
            }
            if (l.geometry == GisGeometry::Source) {
                if (src && src->GetGeometryRef()) f->SetGeometry(src->GetGeometryRef());
            } else if (OGRGeometry* geometry = geometryOf(l.geometry, g)) {
                f->SetGeometryDirectly(geometry);
            }
            f->SetFID(g.fid >= 0 ? g.fid : OGRNullFID);  // kept where the format can
            OGRErr e = layer->CreateFeature(f.get());
            if (e != OGRERR_NONE && g.fid >= 0) {  // the FID taken or refused: a new one
                f->SetFID(OGRNullFID);
                e = layer->CreateFeature(f.get());
            }
            return e == OGRERR_NONE;
        };
        // Features copying a source feature in the source's order, each with its values;
        // those the source does not list (a ring array has no fields) after, without.
        std::unordered_map<int64_t, std::vector<size_t>> bySource;
        std::vector<bool> done(l.count);
        if (source->layer && (copied || l.geometry == GisGeometry::Source))
            for (size_t i = 0; i < l.count; ++i) {
                g.clear();
                l.feature(i, g);
                if (g.source >= 0) bySource[g.source].push_back(i);
            }
        // Features kept as they were (--extract: one of a layer of any size): each read by
        // its FID, in the order given, not the whole layer.
        if (!bySource.empty() && l.geometry == GisGeometry::Source &&
            source->layer->TestCapability(OLCRandomRead)) {
            std::unordered_set<int64_t> fetched;
            for (size_t i = 0; i < l.count; ++i) {
                g.clear();
                l.feature(i, g);
                if (g.source < 0 || !fetched.insert(g.source).second) continue;
                const int64_t fid = g.source;
                FeaturePtr src(source->layer->GetFeature(fid));
                for (size_t k : bySource[fid])
                    if (src && !(done[k] = write(k, src.get())))
                        return discard(l.name + ": feature " + std::to_string(fid));
            }
        } else if (!bySource.empty()) {
            source->layer->ResetReading();
            for (FeaturePtr src; (src.reset(source->layer->GetNextFeature()), src);) {
                auto it = bySource.find(src->GetFID());
                if (it == bySource.end()) continue;
                if (done[it->second.front()]) {
                    warnings.push_back(o.sources.front().file + ": FID " +
                                       std::to_string(src->GetFID()) + " is not unique: its " +
                                       l.name + " carry the first one's fields");
                    continue;
                }
                for (size_t i : it->second) {
                    done[i] = true;
                    if (!write(i, src.get()))
                        return discard(l.name + ": feature " + std::to_string(src->GetFID()));
                }
            }
        }
        for (size_t i = 0; i < l.count; ++i)
            if (!done[i] && l.geometry == GisGeometry::Source)
                return discard(l.name + ": feature " + std::to_string(i) +
                               ": its source feature is not found");
            else if (!done[i] && !write(i, nullptr))
                return discard(l.name + ": feature " + std::to_string(i));
        if (transaction && ds->CommitTransaction() != OGRERR_NONE) return discard("commit");
        written.emplace_back(l.name, (long long)l.count);
    }
    source.reset();
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
        if (side[0] == '.' && !o.noReplace) {
            const std::string old = stemOf(target.file) + side;
            if (std::find(made.begin(), made.end(), fs::path(old).filename().string()) ==
                    made.end() &&
                ::unlink(old.c_str()) != 0 && errno != ENOENT)
                e = errno;
        }
    made.push_back(base);
    // FlatGeobuf does not check the close of its files, where stdio writes its last buffer: a
    // full disk there went unnoticed (tests/cli/write_faults_test.cpp). Read back, it shows.
    if (std::string problem = readBackProblem(folder + "/" + base, written); !problem.empty()) {
        removeFolder();
        return cannot("GDAL reported no error, but the dataset written is incomplete: " + problem);
    }
    // Without replacing: each name linked (which fails on a name taken), the folder's names
    // removed with it; a failure unlinks what was linked.
    std::vector<std::string> linked;
    for (const std::string& name : made) {
        if (e) break;
        e = adoptPermissions(-1, folder + "/" + name, target);
        if (e) break;
        if (o.noReplace) {
            if (::link((folder + "/" + name).c_str(), (dir + name).c_str()) != 0) e = errno;
            else linked.push_back(dir + name);
        } else if (::rename((folder + "/" + name).c_str(), (dir + name).c_str()) != 0) {
            e = errno;
        }
    }
    if (e)
        for (const std::string& name : linked) ::unlink(name.c_str());
    removeFolder();
    if (e) return cannot(std::strerror(e));
    return {};
}

}  // namespace flood::gdal::direct
