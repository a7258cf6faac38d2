// Traces written and read back, in both forms (JSON Lines and binary), hold the same events, compared field by field by Event's
// operator== (generated from FLOOD_EVENT_FIELDS); the logs round-tripped give every field a
// value besides its initial one, so no field's comparison goes untried.
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "flood/log/trace_io.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

TEST(TraceRoundTrip, EveryEventFieldComesBackAndIsExercised) {
    std::vector<Trace> traces;
    for (const std::string& f : filesIn(sourcePath("polygons"), ".json"))
        traces.push_back(record(readOrFail(f)));
    // Forbidden runs carry a reason and culprits (record() floods without validating).
    for (const std::string& f : filesIn(sourcePath("polygons/invalid"), ".json"))
        if (f.find("forbidden-") != std::string::npos) traces.push_back(record(readOrFail(f)));
    for (const std::string& family : familyNames())
        traces.push_back(record(generate(family, 1, 60)));

    std::map<std::string, size_t> changed;  // field -> events where it is not its initial value
    const Event initial{};
    for (bool binary : {false, true})
        for (const Trace& t : traces) {
            Trace back = writtenAndRead(t, binary);
            ASSERT_EQ(back.events.size(), t.events.size());
            for (size_t i = 0; i < t.events.size(); ++i) {
                const Event& e = t.events[i];
                ASSERT_TRUE(back.events[i] == e) << "event " << i << " changed on the way";
#define FLOOD_X(kind, type, name, init) changed[#name] += !(e.name == initial.name);
                FLOOD_EVENT_FIELDS(FLOOD_X)
#undef FLOOD_X
            }
        }
#define FLOOD_X(kind, type, name, init) \
    EXPECT_GT(changed[#name], 0u) << #name " keeps its initial value in every trace tried";
    FLOOD_EVENT_FIELDS(FLOOD_X)
#undef FLOOD_X
}
