#include "transcript.h"

namespace flood {

std::string triangleRange(uint32_t first, uint32_t count) {
    if (count == 0) return "";
    if (count == 1) return std::to_string(first);
    return std::to_string(first) + "-" + std::to_string(first + count - 1);
}

std::string transcript(const std::vector<Event>& events) {
    std::string out, sep;
    auto item = [&](Action a, uint32_t first, uint32_t count) {
        out += sep;
        out += actionName(a);
        std::string range = triangleRange(first, count);
        if (!range.empty()) out += " " + range;
        bool endsGroup = a == Action::Spill || a == Action::Jump || a == Action::Fill;
        sep = endsGroup ? "; " : ", ";
    };
    for (size_t i = 0; i < events.size();) {
        const Event& e = events[i];
        if (e.action == Action::Start) {
            ++i;
            continue;
        }
        if (e.action != Action::Raise) {
            item(e.action, e.firstTriangle, e.triangleCount);
            ++i;
            continue;
        }
        uint32_t first = e.firstTriangle, count = 0;
        for (; i < events.size() && events[i].action == Action::Raise; ++i)
            count += events[i].triangleCount;
        item(Action::Raise, first, count);
    }
    return out;
}

}  // namespace flood
