// Binary traces (see trace_io.h): the same Trace as the JSON Lines form, small and fast to
// read, for the traces of large faces (a 10^6-event JSON trace is ~400 bytes an event).
// Layout, integers as LEB128 varints ("v"), signed ones zigzagged ("z"), doubles as 8 raw
// little-endian bytes ("d"):
//   "FLOODTRB" · v version · d up.x · d up.y
//   v vertices · (d x · d y) each · v rings · v count each (firsts follow) · v parts ·
//   v ringCount each · v splits · (v edge · v vertex) each
//   v events · each event: v mask · z delta for each slot whose bit is set (below)
//   v triangles · each: 3 × z (corner − the previous triangle's same corner)
//   v status · v length · the message's bytes
// An event is 27 32-bit slots (its fields; the subject pair is stored once, as it is held).
// Each slot has a prediction from the previous event (the fingers stay where they were, the
// step counts on, the triangles follow the previous ones, the rest keep their initial
// values); the mask says which slots differ from it and each of those is written as the
// difference. A typical event is 10-20 bytes.
// Reading checks every count against the bytes left before allocating, every enum against
// its range, and then everything the JSON reader checks (eventProblem(), triangle indices).
#include <cstring>
#include <ostream>

#include "flood/log/trace_io.h"

namespace flood {
namespace {

constexpr size_t kMagicSize = 8;  // kBinaryTraceMagic without its terminating NUL
constexpr uint32_t kBinaryVersion = 1;

// The event's slots, the mask's bits in this order: the fields that change at most steps come
// first so that the mask is one or two bytes.
enum Slot : int {
    kAfterLeft,
    kAfterRight,
    kAfterNextLeft,
    kAfterNextRight,
    kWater,
    kTriangleCount,
    kAction,
    kTested,
    kPassed,
    kSide,
    kSagTests,
    kSubject,
    kSubject2,
    kChainIndex,
    kCutLeft,
    kCutRight,
    kGorgePushed,
    kGorgePopped,
    kBottom,
    kReason,
    kPart,
    kBeforeLeft,
    kBeforeRight,
    kBeforeNextLeft,
    kBeforeNextRight,
    kFirstTriangle,
    kStep,
    kSlots
};
// Every field of Event is a slot: a field added to FLOOD_EVENT_FIELDS must be added here.
static_assert(sizeof(Event) == 96, "Event changed: give its new field a slot (trace_bin.cpp)");

using Slots = uint32_t[kSlots];

void toSlots(const Event& e, Slots s) {
    s[kAfterLeft] = e.after.left, s[kAfterRight] = e.after.right;
    s[kAfterNextLeft] = e.after.nextLeft, s[kAfterNextRight] = e.after.nextRight;
    s[kWater] = e.water, s[kTriangleCount] = e.triangleCount, s[kAction] = uint32_t(e.action);
    s[kTested] = e.tested, s[kPassed] = e.passed, s[kSide] = uint32_t(e.side);
    s[kSagTests] = e.sagTests, s[kSubject] = e.sag, s[kSubject2] = e.bridgeTo;
    s[kChainIndex] = e.chainIndex, s[kCutLeft] = e.cutLeft, s[kCutRight] = e.cutRight;
    s[kGorgePushed] = e.gorgePushed, s[kGorgePopped] = e.gorgePopped, s[kBottom] = e.bottom;
    s[kReason] = uint32_t(e.reason), s[kPart] = e.part;
    s[kBeforeLeft] = e.before.left, s[kBeforeRight] = e.before.right;
    s[kBeforeNextLeft] = e.before.nextLeft, s[kBeforeNextRight] = e.before.nextRight;
    s[kFirstTriangle] = e.firstTriangle, s[kStep] = e.step;
}

// The slots' ranges are checked by the caller (enums) and by eventProblem() (vertices).
void fromSlots(const Slots s, Event& e) {
    e.after = {s[kAfterLeft], s[kAfterRight], s[kAfterNextLeft], s[kAfterNextRight]};
    e.water = s[kWater], e.triangleCount = s[kTriangleCount], e.action = Action(s[kAction]);
    e.tested = uint8_t(s[kTested]), e.passed = uint8_t(s[kPassed]), e.side = Side(s[kSide]);
    e.sagTests = s[kSagTests], e.sag = s[kSubject], e.bridgeTo = s[kSubject2];
    e.chainIndex = s[kChainIndex], e.cutLeft = s[kCutLeft], e.cutRight = s[kCutRight];
    e.gorgePushed = s[kGorgePushed], e.gorgePopped = s[kGorgePopped], e.bottom = s[kBottom];
    e.reason = Forbidden(s[kReason]), e.part = s[kPart];
    e.before = {s[kBeforeLeft], s[kBeforeRight], s[kBeforeNextLeft], s[kBeforeNextRight]};
    e.firstTriangle = s[kFirstTriangle], e.step = s[kStep];
}

// What slot k is expected to hold, from the previous event's slots and this event's slots
// before k (the subject's second vertex is expected at its first).
uint32_t predict(int k, const Slots prev, const Slots cur) {
    switch (k) {
        case kSagTests:
        case kChainIndex:
        case kCutLeft:
        case kCutRight: return 0;
        case kSubject: return cur[kAfterLeft];
        case kSubject2: return cur[kSubject];
        case kGorgePushed:
        case kGorgePopped:
        case kBottom: return kNone;
        case kReason: return uint32_t(Forbidden::None);
        case kBeforeLeft:
        case kBeforeRight:
        case kBeforeNextLeft:
        case kBeforeNextRight: return prev[k - kBeforeLeft + kAfterLeft];
        case kFirstTriangle: return prev[kFirstTriangle] + prev[kTriangleCount];
        case kStep: return prev[kStep] + 1;
        default: return prev[k];
    }
}

// The slots of the "event before the first": where the predictions start.
void firstPrediction(Slots s) {
    Event none;
    toSlots(none, s);
    s[kStep] = uint32_t(-1);  // the first event is step 0
}

// --- writing ------------------------------------------------------------------------------

void putVarint(std::string& out, uint64_t v) {
    while (v >= 0x80) out.push_back(char(uint8_t(v) | 0x80)), v >>= 7;
    out.push_back(char(v));
}
void putZigzag(std::string& out, int64_t v) {
    putVarint(out, (uint64_t(v) << 1) ^ (v < 0 ? ~uint64_t(0) : 0));  // zigzag: -1 -> 1, 1 -> 2
}
void putDouble(std::string& out, double d) {
    uint64_t bits;
    std::memcpy(&bits, &d, 8);
    for (int i = 0; i < 8; ++i) out.push_back(char(uint8_t(bits >> (8 * i))));
}
// A 32-bit slot's difference from its prediction, modulo 2^32, as the shortest signed value.
int64_t slotDelta(uint32_t value, uint32_t predicted) { return int32_t(value - predicted); }

// --- reading ------------------------------------------------------------------------------

struct Bad {
    std::string message;
};

struct Reader {
    std::string_view in;
    size_t at = 0;

    size_t left() const { return in.size() - at; }
    [[noreturn]] void truncated() const {
        throw Bad{"truncated at byte " + std::to_string(in.size())};
    }
    uint64_t varint(int maxBits = 64) {
        uint64_t v = 0;
        for (int shift = 0;; shift += 7) {
            if (at >= in.size()) truncated();
            uint8_t b = uint8_t(in[at++]);
            if (shift >= maxBits || (shift > 0 && shift + 7 > maxBits && (b >> (maxBits - shift))))
                throw Bad{"byte " + std::to_string(at - 1) + ": a number too large"};
            v |= uint64_t(b & 0x7f) << shift;
            if (!(b & 0x80)) return v;
        }
    }
    uint32_t u32() { return uint32_t(varint(32)); }
    int64_t zigzag32() {  // a slot's difference, an int32 zigzagged
        uint64_t z = varint(32);
        return int64_t(z >> 1) ^ -int64_t(z & 1);
    }
    double real() {
        if (left() < 8) truncated();
        uint64_t bits = 0;
        for (int i = 0; i < 8; ++i) bits |= uint64_t(uint8_t(in[at++])) << (8 * i);
        double d;
        std::memcpy(&d, &bits, 8);
        return d;
    }
    // A count of items each at least `minBytes` long: more than the bytes left is a lie that
    // would otherwise allocate gigabytes.
    size_t count(const char* what, size_t minBytes) {
        uint64_t c = varint();
        if (c > left() / minBytes)
            throw Bad{std::string("byte ") + std::to_string(at) + ": " + std::to_string(c) + " " +
                      what + " cannot fit in the " + std::to_string(left()) + " bytes left"};
        return size_t(c);
    }
};

void readPolygon(Reader& r, Polygon& p) {
    p.vertices.resize(r.count("vertices", 16));
    for (Point& q : p.vertices) q.x = r.real(), q.y = r.real();
    uint64_t next = 0;
    p.rings.resize(r.count("rings", 1));
    for (Ring& ring : p.rings) {
        ring = {Index(next), r.u32()};
        next += ring.count;
        if (next > p.vertices.size()) throw Bad{"rings hold more vertices than the list"};
    }
    if (next != p.vertices.size()) throw Bad{"rings do not cover all vertices"};
    next = 0;
    p.parts.resize(r.count("parts", 1));
    for (Part& part : p.parts) {
        part = {Index(next), r.u32()};
        next += part.ringCount;
        if (part.ringCount == 0 || next > p.rings.size())
            throw Bad{"parts do not cover the rings in order"};
    }
    if (next != p.rings.size()) throw Bad{"parts do not cover all rings"};
    p.splits.resize(r.count("splits", 2));
    for (EdgeSplit& s : p.splits) {
        s.edge = r.u32(), s.vertex = r.u32();
        if (s.edge >= p.vertices.size() || s.vertex >= p.vertices.size())
            throw Bad{"a split names a vertex beyond the vertex list"};
    }
}

Event readEvent(Reader& r, Slots prev, const Trace& t) {
    const size_t at = r.at;
    uint32_t mask = r.u32();
    if (mask >> kSlots) throw Bad{"byte " + std::to_string(at) + ": an unknown field"};
    Slots cur;
    for (int k = 0; k < kSlots; ++k) {
        cur[k] = predict(k, prev, cur);
        if (mask >> k & 1) cur[k] += uint32_t(r.zigzag32());
    }
    const std::string where =
        "event " + std::to_string(t.events.size()) + " (byte " + std::to_string(at) + "): ";
    if (cur[kAction] >= uint32_t(Action::Count) || cur[kSide] > 1 ||
        cur[kReason] >= uint32_t(Forbidden::Count) || cur[kTested] >> int(Test::Count) ||
        cur[kPassed] >> int(Test::Count))
        throw Bad{where + "a name out of range"};
    if (cur[kStep] != t.events.size())
        throw Bad{where + "step " + std::to_string(cur[kStep]) + ", expected " +
                  std::to_string(t.events.size())};
    Event e;
    fromSlots(cur, e);
    if (const char* problem = eventProblem(e, t.polygon.vertices.size(), t.polygon.parts.size()))
        throw Bad{where + actionName(e.action) + ": " + problem};
    std::memcpy(prev, cur, sizeof(Slots));
    return e;
}

}  // namespace

bool isBinaryTrace(std::string_view text) {
    return text.size() >= kMagicSize &&
           std::memcmp(text.data(), kBinaryTraceMagic, kMagicSize) == 0;
}

void writeBinaryTrace(std::ostream& out, const Trace& trace) {
    std::string b(kBinaryTraceMagic, kMagicSize);
    putVarint(b, kBinaryVersion);
    putDouble(b, trace.up.x), putDouble(b, trace.up.y);
    const Polygon& p = trace.polygon;
    putVarint(b, p.vertices.size());
    for (const Point& q : p.vertices) putDouble(b, q.x), putDouble(b, q.y);
    putVarint(b, p.rings.size());
    for (const Ring& r : p.rings) putVarint(b, r.count);
    putVarint(b, p.parts.size());
    for (const Part& q : p.parts) putVarint(b, q.ringCount);
    putVarint(b, p.splits.size());
    for (const EdgeSplit& s : p.splits) putVarint(b, s.edge), putVarint(b, s.vertex);
    putVarint(b, trace.events.size());
    Slots prev, cur;
    firstPrediction(prev);
    for (const Event& e : trace.events) {
        toSlots(e, cur);
        uint32_t mask = 0;
        for (int k = 0; k < kSlots; ++k)
            if (cur[k] != predict(k, prev, cur)) mask |= 1u << k;
        putVarint(b, mask);
        for (int k = 0; k < kSlots; ++k)
            if (mask >> k & 1) putZigzag(b, slotDelta(cur[k], predict(k, prev, cur)));
        std::memcpy(prev, cur, sizeof(Slots));
        if (b.size() >= (1 << 20)) out.write(b.data(), std::streamsize(b.size())), b.clear();
    }
    putVarint(b, trace.triangles.size());
    Triangle last = {0, 0, 0};
    for (const Triangle& t : trace.triangles) {
        for (int k = 0; k < 3; ++k) putZigzag(b, slotDelta(t[k], last[k]));
        last = t;
        if (b.size() >= (1 << 20)) out.write(b.data(), std::streamsize(b.size())), b.clear();
    }
    putVarint(b, uint32_t(trace.diagnostic.status));
    putVarint(b, trace.diagnostic.message.size());
    b += trace.diagnostic.message;
    out.write(b.data(), std::streamsize(b.size()));
}

Diagnostic parseBinaryTrace(std::string_view text, const std::string& name, Trace& trace) {
    trace = Trace{};
    Reader r{text, kMagicSize};
    try {
        if (!isBinaryTrace(text)) throw Bad{"not a binary flood trace (no FLOODTRB)"};
        uint64_t version = r.varint();
        if (version < 1 || version > kBinaryVersion)
            throw Bad{"binary trace version " + std::to_string(version) +
                      ", this build reads version 1 to " + std::to_string(kBinaryVersion)};
        Up up{r.real(), r.real()};
        if (!up.valid()) throw Bad{"the direction is not a finite nonzero [x, y]"};
        trace.up = up;
        readPolygon(r, trace.polygon);
        const size_t events = r.count("events", 1);
        trace.events.reserve(events);
        Slots prev;
        firstPrediction(prev);
        for (size_t i = 0; i < events; ++i) trace.events.push_back(readEvent(r, prev, trace));
        trace.triangles.resize(r.count("triangles", 3));
        const size_t n = trace.polygon.vertices.size();
        Triangle last = {0, 0, 0};
        for (Triangle& t : trace.triangles) {
            for (int k = 0; k < 3; ++k) {
                t[k] = last[k] + uint32_t(r.zigzag32());
                if (t[k] >= n) throw Bad{"a triangle has a bad vertex index"};
            }
            last = t;
        }
        uint64_t status = r.varint();
        bool known = false;
        for (int s : {0, 2, 3, 4, 5, 6, 7}) known |= status == uint64_t(s);
        if (!known) throw Bad{"unknown status " + std::to_string(status)};
        trace.diagnostic.status = Status(status);
        size_t length = r.count("message bytes", 1);
        trace.diagnostic.message.assign(text.substr(r.at, length));
        r.at += length;
        if (r.left()) throw Bad{"bytes after the end of the trace at byte " + std::to_string(r.at)};
        for (const Event& e : trace.events)
            if (uint64_t(e.firstTriangle) + e.triangleCount > trace.triangles.size())
                throw Bad{"event " + std::to_string(e.step) +
                          " refers to triangles beyond the final list"};
    } catch (const Bad& b) {
        trace = Trace{};
        return {Status::Malformed, name + ": " + b.message};
    }
    return {};
}

}  // namespace flood
