// Where the viewer finds polygons: the samples folder, the default polygon, the teaching
// gallery's list.
#pragma once
#include <string>
#include <vector>

namespace flood::view {

// Where to look for polygons: $FLOOD_POLYGONS_DIR; else the installed share/flood/polygons
// beside the executable; else the source tree's polygons/ (a build); else the configured
// install prefix's.
std::string polygonsDir();
// polygons/FLOOD_VIEWER_DEFAULT_POLYGON (CMake cache, default paper-figure-7.json) if it
// exists, else the first polygon file, else "". FLOOD_POLYGONS_DIR overrides the directory.
std::string defaultPolygonPath();
// The teaching gallery, dir/gallery.json: a list of {"file", "title", "description"} in
// teaching order, files relative to dir. Missing or malformed: empty (the Open panel then
// lists the files only).
struct GalleryEntry {
    std::string file, title, description;  // file: full path
};
std::vector<GalleryEntry> readGallery(const std::string& dir);

}  // namespace flood::view
