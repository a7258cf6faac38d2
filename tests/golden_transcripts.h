// Golden transcripts, written once for every test that checks them: each small polygon in
// polygons/ shows one situation of the paper (numbers included: the polygons are small).
#pragma once
#include <map>
#include <string>

namespace flood::testing {

inline const std::map<std::string, std::string> kGoldenTranscripts = {
    {"monotone.json", "Raise 0-2, Fill 3"},
    {"two-gorges.json", "Raise 0, Spill; Raise 1, Jump; Raise 2, Fill 3-4"},
    {"sag.json", "Raise, Bridge 0, Raise 1, Fill 2; Raise 3, Fill 4"},
    {"pending-bottoms.json",
     "Raise, Bridge 0, Bridge 1, Raise 2, Fill 3; Bridge 4, Raise 5, Fill 6; Raise 7, Fill 8; "
     "Raise 9, Fill 10"},
    {"hole.json", "Raise, Bridge 0, Raise 1, Spill; Raise 2-3, Jump; Raise 4-5, Fill 6-7"},
    {"touching-hole.json",
     "Raise, Bridge 0, Fill 1; Raise 2, Spill; Raise, Jump; Raise 3, Fill 4-5"},
    {"horizontal.json",
     "Raise 0, Spill; Raise 1, Jump; Raise 2-5, Bridge 6, Raise 7, Fill 8; Fill 9"},
    {"collinear.json", "Raise 0-4, Bridge 5, Raise 6, Fill 7; Raise 8-10, Fill 11"},
    {"overhang.json", "Raise 0-1, Spill; Raise, Bridge 2, Fill 3; Raise, Jump; Raise 4, Fill 5-7"},
    // Steiner points: each bridge is an antenna into the gorge; nothing waits on the to-do list.
    {"steiner.json", "Raise, Bridge 0, Raise 1, Bridge 2-3, Raise 4, Fill 5-6"},
    // T-junctions flood like shared vertices: the holes touching the outer ring inside an edge
    // become part of its loop.
    {"t-junction.json",
     "Raise, Bridge 0, Raise 1, Spill; Raise 2, Jump; Bridge 3-5, Bridge 6-7, Bridge 8, Raise 9, "
     "Spill; Raise, Jump; Raise 10-12, Fill 13-14; Fill 15"},
};

}  // namespace flood::testing
