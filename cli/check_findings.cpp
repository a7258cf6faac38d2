// `flood check --findings OUT` and `--extract DIR` of GIS features (cli/check_rows.h): what
// check found, written through GDAL's writer (core/io/gdal/gdal_write.cpp) for a GIS user to
// load over the data.
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>

#include "check_rows.h"
#include "flood/io/gdal/gdal_io.h"
#include "triangulate_gis.h"
#include "verbosity.h"

namespace flood::cli {

int findingsFormat(const std::string& out) {
    std::string format, driver;
    return gisFormat("--findings", out, format, driver);
}

#ifdef FLOOD_GDAL
namespace {

namespace fs = std::filesystem;

// One finding of a failing row: one of its findings, or, for a row without (malformed,
// forbidden, rejected by the checker), the row itself at its place.
struct Item {
    const Row* row;
    const Finding* finding;  // null: the row itself
};

std::vector<Item> itemsOf(const std::vector<Row*>& rows) {
    std::vector<Item> items;
    for (const Row* r : rows) {
        if (r->verdict == Verdict::Ok) continue;
        for (const Finding& f : r->findings) items.push_back({r, &f});
        if (r->findings.empty()) items.push_back({r, nullptr});
    }
    return items;
}

gdal::GisValue text(const std::string& s) {
    return s.empty() ? gdal::GisValue{} : gdal::GisValue{s};
}
gdal::GisValue ordinal(Index i) {
    return i == kNone ? gdal::GisValue{} : gdal::GisValue{int64_t(i)};
}

// The fields both layers share, a finding's key (`finding`: its number, from 1, in "findings").
const std::vector<gdal::GisField> kKeys = {{"finding", true}, {"file"},       {"layer"},
                                           {"fid", true},     {"name"},       {"status"},
                                           {"reason"},        {"ring", true}, {"vertex", true}};

std::vector<gdal::GisValue> keys(size_t number, const Item& item, Index ring, Index vertex) {
    const Row& r = *item.row;
    const std::string& reason = item.finding ? item.finding->reason : r.reason;
    return {
        int64_t(number + 1), r.file == "-" ? std::string("<stdin>") : r.file,
        text(r.layer),       r.wholeFile ? gdal::GisValue{} : gdal::GisValue{int64_t(r.feature)},
        text(r.name),        std::string(verdictName(r.verdict)),
        text(reason),        ordinal(ring),
        ordinal(vertex)};
}

}  // namespace

int writeFindings(const std::vector<Row*>& rows, const std::string& out) {
    std::string format, driver;
    if (int c = gisFormat("--findings", out, format, driver)) return c;
    std::vector<Item> items = itemsOf(rows);
    // FlatGeobuf keeps no feature without a geometry (GDAL drops it): those are left out, said.
    if (driver == "FlatGeobuf") {
        const size_t all = items.size();
        items.erase(std::remove_if(items.begin(), items.end(),
                                   [](const Item& i) {
                                       return !(i.finding ? *i.finding : i.row->place).located;
                                   }),
                    items.end());
        if (items.size() < all)
            warning() << out << ": " << all - items.size()
                      << " findings without a location (a file or feature that cannot be read, "
                         "a rejected triangulation) are left out: FlatGeobuf holds no feature "
                         "without a geometry (the table lists them)\n";
    }
    gdal::GisLayer points;
    points.name = "findings";
    points.geometry = gdal::GisGeometry::Point;
    points.fields = kKeys;
    points.fields.push_back({"message"});
    points.count = items.size();
    points.feature = [&](size_t i, gdal::GisFeature& g) {
        const Item& item = items[i];
        const Finding& f = item.finding ? *item.finding : item.row->place;
        g.values = keys(i, item, f.ring, f.vertex);
        const Row& r = *item.row;
        g.values.push_back(
            item.finding ? text(f.message)
                         : text((r.file == "-" ? "<stdin>" : r.file) +
                                (r.wholeFile ? "" : ": feature " + std::to_string(r.feature)) +
                                (r.at.empty() ? "" : ": " + r.at) + ": " + r.reason));
        if (f.located) g.parts = {{{f.x, f.y}}};  // else a null geometry (nothing to point at)
    };
    // Each culprit edge: which finding it is of, and the edge's own ring and first vertex.
    std::vector<std::pair<size_t, const FindingEdge*>> edgeList;
    for (size_t i = 0; i < items.size(); ++i)
        if (items[i].finding)
            for (const FindingEdge& e : items[i].finding->edges) edgeList.emplace_back(i, &e);
    gdal::GisLayer edges;
    edges.name = "finding_edges";
    edges.geometry = gdal::GisGeometry::LineString;
    edges.fields = kKeys;
    edges.count = edgeList.size();
    edges.feature = [&](size_t i, gdal::GisFeature& g) {
        const auto& [k, e] = edgeList[i];
        g.values = keys(k, items[k], e->ring, e->vertex);
        g.parts = {{e->a, e->b}};
    };
    // The CRS of the layers the findings are in (the one they agree on).
    gdal::DatasetOutput o;
    o.driver = driver;
    o.format = format;
    std::set<std::pair<std::string, std::string>> seen;
    for (const Item& item : items)
        if (seen.insert({item.row->file, item.row->layer}).second)
            o.sources.push_back({item.row->file, gdal::Selection{item.row->layer, -1, ""}});
    // A format of one layer a file: the edges beside OUT, as OUT_edges.EXT.
    std::string edgesOut;
    std::vector<gdal::GisLayer> layers = {points};
    if (gdal::severalLayers(driver)) {
        layers.push_back(edges);
    } else {
        const fs::path p(out);
        edgesOut =
            (p.parent_path() / (p.stem().string() + "_edges" + p.extension().string())).string();
    }
    // The edges first: a failure of either leaves OUT as it was.
    std::vector<std::string> warnings;
    Diagnostic d;
    if (!edgesOut.empty()) d = gdal::writeLayers(edgesOut, o, {edges}, warnings);
    if (d.ok()) {
        // What the first write said of its file (a CRS not agreed on) is not said again.
        std::vector<std::string> more;
        d = gdal::writeLayers(out, o, layers, more);
        for (const std::string& w : more)
            if (edgesOut.empty() ||
                std::find(warnings.begin(), warnings.end(),
                          edgesOut + w.substr(std::min(w.size(), out.size()))) == warnings.end())
                warnings.push_back(w);
    }
    for (const std::string& w : warnings) warning() << w << "\n";
    if (!d.ok()) {
        std::cerr << "error: " << d.message << "\n";
        return int(d.status);
    }
    note() << "check: wrote " << grouped(items.size())
           << (items.size() == 1 ? " finding" : " findings") << " to " << out
           << " (layer findings) and " << grouped(edgeList.size())
           << (edgeList.size() == 1 ? " culprit edge" : " culprit edges") << " to "
           << (edgesOut.empty() ? out + " (layer finding_edges)" : edgesOut) << "\n";
    return 0;
}

bool extractGis(Row& row, const std::string& dir, const std::string& stem) {
    // The input's own format where GDAL writes it (by its extension), else GeoJSON.
    std::string ext = fs::path(row.file).extension().string();
    std::string driver = gdal::outputDriver("", row.file);
    if (driver.empty()) driver = gdal::outputDriver("", "x.geojson"), ext = ".geojson";
    std::string base = stem;
    if (row.severalLayers) base += "_" + row.layer;
    base = (fs::path(dir) / (base + "_feature" + std::to_string(row.feature))).string();
    // The first free name, its side files too (a Shapefile's .dbf, ...): never over a file.
    std::string path;
    for (int k = 1; k <= 10000 && path.empty(); ++k) {
        const std::string stemK = base + (k == 1 ? "" : "-" + std::to_string(k));
        bool taken = false;
        struct stat st;
        for (const char* side : {"", ".shx", ".dbf", ".prj", ".cpg"})
            taken |= ::lstat((stemK + (*side ? side : ext)).c_str(), &st) == 0;
        if (!taken) path = stemK + ext;
    }
    if (path.empty()) {
        std::cerr << "error: " << base + ext << ": 10000 names taken, nothing extracted\n";
        return false;
    }
    gdal::GisLayer layer;
    layer.name = row.layer.empty() ? fs::path(row.file).stem().string() : row.layer;
    layer.geometry = gdal::GisGeometry::Source;
    layer.sourceFields = true;
    layer.count = 1;
    layer.feature = [&](size_t, gdal::GisFeature& g) { g.source = g.fid = row.feature; };
    gdal::DatasetOutput o;
    o.driver = driver;
    o.format = ext.substr(1);
    o.sources = {{row.file, gdal::Selection{row.layer, -1, ""}}};
    o.noReplace = true;
    std::vector<std::string> warnings;
    Diagnostic d = gdal::writeLayers(path, o, {layer}, warnings);
    for (const std::string& w : warnings) warning() << w << "\n";
    if (!d.ok()) {
        std::cerr << "error: " << d.message << "\n";
        return false;
    }
    row.extracted = path;
    return true;
}

#else
int writeFindings(const std::vector<Row*>&, const std::string& out) {
    return findingsFormat(out);  // refused before checking: never here
}
bool extractGis(Row&, const std::string&, const std::string&) { return false; }
#endif

}  // namespace flood::cli
