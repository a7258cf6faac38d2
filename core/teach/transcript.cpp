#include "flood/teach/transcript.h"

namespace flood {

std::string triangleRange(uint32_t first, uint32_t count) {
    if (count == 0) return "";
    if (count == 1) return std::to_string(first);
    return std::to_string(first) + "-" + std::to_string(first + count - 1);
}

std::vector<TranscriptItem> transcriptItems(const std::vector<Event>& events) {
    std::vector<TranscriptItem> items;
    // Counted first: at 10^6 events, growing the list moved every item's strings a dozen times.
    size_t count = 0;
    for (size_t i = 0; i < events.size(); ++i)
        count +=
            events[i].action != Action::Start &&
            !(events[i].action == Action::Raise && i > 0 && events[i - 1].action == Action::Raise);
    items.reserve(count);
    for (uint32_t i = 0; i < events.size();) {
        const Event& e = events[i];
        if (e.action == Action::Start) {
            ++i;
            continue;
        }
        // Triangles are cut in order, so a run of raises cut one contiguous range.
        uint32_t last = i, count = e.triangleCount;
        if (e.action == Action::Raise)
            while (last + 1 < events.size() && events[last + 1].action == Action::Raise)
                count += events[++last].triangleCount;
        TranscriptItem item;
        item.firstEvent = i;
        item.lastEvent = last;
        item.text = actionName(e.action);
        std::string range = triangleRange(e.firstTriangle, count);
        if (!range.empty()) item.text += " " + range;
        item.endsGroup =
            e.action == Action::Spill || e.action == Action::Jump || e.action == Action::Fill;
        if (!items.empty()) items.back().separator = items.back().endsGroup ? "; " : ", ";
        items.push_back(std::move(item));
        i = last + 1;
    }
    return items;
}

std::string transcript(const std::vector<TranscriptItem>& items) {
    std::string out;
    for (const TranscriptItem& item : items) out += item.text + item.separator;
    return out;
}

std::string transcript(const std::vector<Event>& events) {
    return transcript(transcriptItems(events));
}

}  // namespace flood
