// The paper's transcript of a run (Fig. 7): "Raise 0-7, Spill; Raise 8-12, Jump; ...".
#pragma once
#include <string>
#include <vector>

#include "flood/machine/events.h"

namespace flood {

// One item of the transcript and the events it covers. Consecutive raises are one item
// "Raise first-last" (their triangles); any other action is an item of its own, showing the
// range of the triangles it cut. A Spill, Jump or Fill ends a group: the paper writes "; "
// after it and ", " after any other item. Start events are not part of the paper's
// vocabulary and belong to no item.
struct TranscriptItem {
    uint32_t firstEvent = 0, lastEvent = 0;  // inclusive indices into the event log
    std::string text;                        // "Raise 8-12", "Bridge", "Fill 13"
    bool endsGroup = false;                  // a Spill, Jump or Fill
    std::string separator;  // what follows it: "; " ends a group, ", " does not, "" (the last)
};

std::vector<TranscriptItem> transcriptItems(const std::vector<Event>& events);

// The items joined, each followed by its separator.
std::string transcript(const std::vector<TranscriptItem>& items);
std::string transcript(const std::vector<Event>& events);

// The triangle range of an item: "8-12", "8" or "" when it cut none.
std::string triangleRange(uint32_t first, uint32_t count);

}  // namespace flood
