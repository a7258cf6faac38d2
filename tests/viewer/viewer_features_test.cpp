// The viewer's model without a window: shrinking in the background, the features of a
// collection and their verdicts, a GIS dataset opened like a polygon, the teaching gallery.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include "viewer_model_support.h"  // the model, the tests' helpers

// ----------------------------------------------------------------------------------------
// Shrink from the viewer, and the features of a collection.
namespace {

// A 300-vertex valid star with one vertex moved through the centre: the ring crosses itself.
Polygon buriedCrossing() {
    Polygon star = generate("star", 5, 300);
    std::vector<Point> ring(star.vertices.begin(), star.vertices.begin() + star.rings[0].count);
    Point& v = ring[ring.size() / 2];
    v = {-v.x * 3, -v.y * 3};
    Polygon p;
    p.addRing(ring, true);
    return p;
}

std::string scratchDir(const std::string& name) {
    std::string dir = std::string(::testing::TempDir()) + "flood-viewer-" + name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string mixedPath() {
    return std::string(FLOOD_SOURCE_DIR) + "/polygons/datasets/mixed.geojson";
}

}  // namespace

TEST(ViewerShrink, BackgroundShrinkFinishesSmallerFailingTheSameWayAndOpensBesideTheOriginal) {
    const std::string dir = scratchDir("shrink");
    const std::string file = dir + "/crossing.json";
    ASSERT_TRUE(saveGeoJson(buriedCrossing(), file).ok());
    Model m;
    m.open(file);
    ASSERT_TRUE(m.failed());
    const size_t before = m.polygon().vertices.size();
    ASSERT_GE(before, 250u);
    ShrinkOptions o;
    o.fork = false;  // no crash or hang to survive here; keeps the test light
    const Failure original = classify(m.polygon(), o);
    ASSERT_EQ(original.kind, Failure::Kind::Forbidden) << original.message;

    ShrinkJob job;
    job.start(m.polygon(), o);
    job.wait();
    ASSERT_TRUE(job.done());
    const ShrinkResult& r = job.result();
    EXPECT_FALSE(r.cancelled);
    EXPECT_LE(r.polygon.vertices.size(), 12u);
    EXPECT_TRUE(r.failure.sameClass(original)) << r.failure.message;
    EXPECT_TRUE(classify(r.polygon, o).sameClass(original));
    EXPECT_EQ(job.tries(), r.tries - 1) << "progress is the tries made before the last";

    m.openShrunk(r);
    EXPECT_TRUE(m.shrunk());
    EXPECT_EQ(m.polygon().vertices.size(), r.polygon.vertices.size());
    EXPECT_NE(m.path().find("(shrunk)"), std::string::npos) << m.path();
    EXPECT_TRUE(m.failed());
    ASSERT_FALSE(m.recentFiles().empty());
    EXPECT_EQ(m.recentFiles().front(), std::filesystem::absolute(file).lexically_normal().string());

    // Saved as GeoJSON, atomically: the file reads back, nothing else is left in the folder.
    const std::string repro = dir + "/crossing-shrunk.geojson";
    ASSERT_TRUE(saveGeoJson(m.polygon(), repro).ok());
    ReadResult back = readPolygonFile(repro);
    ASSERT_TRUE(back.diagnostic.ok()) << back.diagnostic.message;
    EXPECT_EQ(back.polygon.vertices.size(), r.polygon.vertices.size());
    EXPECT_TRUE(classify(back.polygon, o).sameClass(original));
    size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 2u);

    m.openOrigin();  // one click back
    EXPECT_FALSE(m.shrunk());
    EXPECT_EQ(m.polygon().vertices.size(), before);
}

TEST(ViewerShrink, CancelStopsAtTheNextTry) {
    ShrinkOptions o;
    o.fork = false;
    ShrinkJob job;
    size_t calls = 0;
    // The test's hook asks for the cancel at try 5, from the shrinking thread itself.
    o.onTry = [&](size_t tries, size_t) {
        ++calls;
        if (tries == 5) job.requestCancel();
        return true;
    };
    Polygon p = buriedCrossing();
    job.start(p, o);
    job.wait();
    ASSERT_TRUE(job.done());
    EXPECT_TRUE(job.result().cancelled);
    EXPECT_EQ(calls, 5u) << "not one classification after the cancel";
    EXPECT_EQ(job.result().tries, 5u);
    // What it found until then still fails the same way.
    EXPECT_TRUE(job.result().failure.sameClass(classify(p, o)));
    EXPECT_LT(job.result().polygon.vertices.size(), p.vertices.size());
}

TEST(ViewerShrink, SavingToAnUnwritablePlaceFailsAndLeavesNothing) {
    const std::string dir = scratchDir("unwritable");
    Diagnostic d = saveGeoJson(buriedCrossing(), dir + "/no-such-folder/x.geojson");
    EXPECT_EQ(d.status, Status::WriteFailed);
    EXPECT_NE(d.message.find("no-such-folder/x.geojson"), std::string::npos) << d.message;
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(ViewerFeatures, OpenFeatureNOpensThatFeature) {
    Model m;
    ASSERT_TRUE(m.openFeature(mixedPath(), 7));  // "two holes": 4 + 4 + 4 vertices
    EXPECT_EQ(m.feature(), 7u);
    EXPECT_EQ(m.polygon().vertices.size(), 12u);
    EXPECT_EQ(m.polygon().rings.size(), 3u);
    EXPECT_FALSE(m.failed());
    EXPECT_EQ(m.path(), mixedPath() + "#7");
    ASSERT_TRUE(m.openFeature(mixedPath(), 1));  // the bow-tie crosses itself
    EXPECT_EQ(m.polygon().vertices.size(), 4u);
    EXPECT_TRUE(m.failed());
    EXPECT_EQ(m.exitCode(), 4);
}

TEST(ViewerFeatures, OutOfRangeOrNotACollectionIsAClearFailureKeepingWhatWasLoaded) {
    Model m;
    ASSERT_TRUE(m.openFeature(mixedPath(), 8));
    const size_t loaded = m.polygon().vertices.size();
    EXPECT_FALSE(m.openFeature(mixedPath(), 99));
    EXPECT_EQ(m.openDiagnostic().status, Status::Usage);
    EXPECT_NE(m.openDiagnostic().message.find("mixed.geojson"), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_NE(m.openDiagnostic().message.find("99"), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_NE(m.openDiagnostic().message.find("0..9"), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_EQ(m.polygon().vertices.size(), loaded);
    EXPECT_EQ(m.feature(), 8u);

    EXPECT_FALSE(m.openFeature(mixedPath(), 6));  // a LineString: no polygon to open
    EXPECT_EQ(m.openDiagnostic().status, Status::Usage);
    EXPECT_FALSE(m.openFeature(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json", 0));
    EXPECT_NE(m.openDiagnostic().message.find("not a FeatureCollection"), std::string::npos);
    EXPECT_EQ(m.polygon().vertices.size(), loaded);
}

TEST(ViewerFeatures, ListShowsVerdictsFailingFirst) {
    FeatureScan scan;
    scan.start(mixedPath());
    scan.wait();
    ASSERT_TRUE(scan.done());
    EXPECT_TRUE(scan.diagnostic().ok()) << scan.diagnostic().message;
    std::vector<std::pair<size_t, Verdict>> got;
    for (const auto& f : scan.features()) got.push_back({f.index, f.kind});
    const std::vector<std::pair<size_t, Verdict>> want = {
        {1, Verdict::Invalid},   {3, Verdict::Invalid},   {4, Verdict::Invalid},
        {5, Verdict::Malformed}, {9, Verdict::Malformed}, {0, Verdict::Ok},
        {2, Verdict::Ok},        {7, Verdict::Ok},        {8, Verdict::Ok}};
    EXPECT_EQ(got, want);
    EXPECT_EQ(scan.total(), want.size());
    EXPECT_EQ(scan.progress(), want.size());
    ASSERT_FALSE(scan.features().empty());
    EXPECT_EQ(scan.features()[0].name, "bow-tie");
    EXPECT_NE(scan.features()[0].reason.find("ring 0"), std::string::npos)
        << scan.features()[0].reason;
    EXPECT_EQ(scan.features().back().id, "triangle");
    EXPECT_EQ(scan.features().back().vertices, 3u);

    FeatureScan single;  // not a collection: nothing to list
    single.start(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    single.wait();
    EXPECT_TRUE(single.features().empty());
}

#ifdef FLOOD_GDAL

// The viewer opens a GIS dataset like a polygon file (core/io/gdal/): a GeoPackage made here
// with ogr2ogr from a GeoJSON square with a hole.
TEST(ViewerGdal, OpensAGeoPackage) {
    std::filesystem::path d = scratch("viewer-gdal");
    std::ofstream(d / "square.geojson")
        << R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"name": "sq"},
             "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,10],[0,10],[0,0]],
                                                           [[3,3],[3,7],[7,7],[7,3],[3,3]]]}}]})";
    RunResult made = runShell("ogr2ogr -f GPKG " + (d / "square.gpkg").string() + " " +
                              (d / "square.geojson").string() + " 2>&1");
    ASSERT_EQ(made.code, 0) << made.out;
    Model m;
    m.open((d / "square.gpkg").string());
    EXPECT_EQ(m.exitCode(), 0) << m.verdict();
    EXPECT_EQ(m.polygon().vertices.size(), 8u);
    EXPECT_EQ(m.polygon().rings.size(), 2u);
    EXPECT_FALSE(m.failed()) << m.verdict();
    std::filesystem::remove_all(d);
}

#endif

// Opening the gallery file opens the gallery (issue 27 §4): its first polygon, its folder's
// list for the Open panel, and a count the UI shows the panel on; a gallery.json that lists
// nothing is read as a polygon file and fails as one.
TEST(ViewerGallery, OpeningTheGalleryFileOpensItsFirstPolygon) {
    const std::string dir = flood::testing::sourcePath("polygons");
    const std::vector<GalleryEntry> gallery = readGallery(dir);
    ASSERT_FALSE(gallery.empty());
    Model m;
    m.open(dir + "/gallery.json");
    EXPECT_TRUE(m.openDiagnostic().ok()) << m.openDiagnostic().message;
    EXPECT_EQ(m.path(), gallery.front().file);
    EXPECT_GT(m.steps(), 0u);
    EXPECT_EQ(m.galleryOpens(), 1u);
    EXPECT_EQ(m.galleryDir(), dir);

    const auto empty = flood::testing::scratch("empty-gallery");
    std::ofstream((empty / "gallery.json").string()) << "[]";
    Model none;
    none.open((empty / "gallery.json").string());
    EXPECT_EQ(none.openDiagnostic().status, Status::Malformed);
    EXPECT_EQ(none.galleryOpens(), 0u);
}

#endif
