// JSON Lines traces (see trace_io.h). nlohmann::json (Debian nlohmann-json3-dev, header-only)
// reads and writes each line; a bracket scan bounds nesting before parsing.
#include "flood/log/trace_io.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>

#include "flood/io/io.h"
#include "io/io_util.h"

namespace flood {
namespace {

using nlohmann::json;

const char* kTestNames[] = {
#define FLOOD_X(name, text) #name,
    FLOOD_TESTS(FLOOD_X)
#undef FLOOD_X
};

json indexJson(uint32_t i) { return i == kNone ? json(nullptr) : json(i); }

// JSON has no NaN or infinity (nlohmann would write null, which no reader takes back): an
// unvalidated run may hold them, so they are written as the strings "NaN", "Infinity",
// "-Infinity" and read back as the same values.
json coordinateJson(double v) {
    if (std::isnan(v)) return "NaN";
    if (std::isinf(v)) return v > 0 ? "Infinity" : "-Infinity";
    return v;
}

bool readCoordinate(const json& j, double& v) {
    if (j.is_number()) {
        v = j.get<double>();
        return true;
    }
    if (!j.is_string()) return false;
    const std::string& s = j.get_ref<const std::string&>();
    if (s == "NaN") v = std::numeric_limits<double>::quiet_NaN();
    else if (s == "Infinity") v = std::numeric_limits<double>::infinity();
    else if (s == "-Infinity") v = -std::numeric_limits<double>::infinity();
    else return false;
    return true;
}

json fingersJson(const Fingers& f) {
    return {{"left", indexJson(f.left)},
            {"right", indexJson(f.right)},
            {"nextLeft", indexJson(f.nextLeft)},
            {"nextRight", indexJson(f.nextRight)}};
}

json testsJson(uint8_t bits) {
    json a = json::array();
    for (int t = 0; t < int(Test::Count); ++t)
        if (bits >> t & 1) a.push_back(kTestNames[t]);
    return a;
}

// How each kind of event field (FLOOD_EVENT_FIELDS) is written.
json writeActionName(Action a) { return actionName(a); }
json writeSideName(Side s) { return s == Side::Left ? "Left" : "Right"; }
json writeTestNames(uint8_t bits) { return testsJson(bits); }
json writeReasonName(Forbidden f) { return forbiddenName(f); }
json writeNumber(uint32_t v) { return v; }
json writeFingerVertices(const Fingers& f) { return fingersJson(f); }
json writeVertex(Index v) { return indexJson(v); }
json writeGorgeId(uint32_t g) { return indexJson(g); }

const Event kInitial{};  // every field at its initial value

// The fields the event's action uses (usesField()), less those at their initial value: the
// reader restores them. The action is always written.
json eventJson(const Event& e) {
    json o = json::object();
#define FLOOD_X(kind, type, name, initial)                                \
    if (Field::name == Field::action ||                                   \
        (usesField(e.action, Field::name) && !(e.name == kInitial.name))) \
        o[#name] = write##kind(e.name);
    FLOOD_EVENT_FIELDS(FLOOD_X)
#undef FLOOD_X
    return o;
}

struct Bad {
    std::string message;
};

const json& field(const json& o, const char* key) {
    if (!o.is_object() || !o.contains(key)) throw Bad{std::string("missing field \"") + key + "\""};
    return o[key];
}

uint32_t number(const json& o, const char* key) {
    const json& v = field(o, key);
    if (!v.is_number_unsigned() || v.get<uint64_t>() > 0xffffffffull)
        throw Bad{std::string("field \"") + key + "\" is not an unsigned 32-bit integer"};
    return v.get<uint32_t>();
}

// A vertex index (or null for none), checked against the vertex count.
Index vertex(const json& o, const char* key, size_t n) {
    const json& v = field(o, key);
    if (v.is_null()) return kNone;
    uint32_t i = number(o, key);
    if (i >= n)
        throw Bad{std::string("field \"") + key + "\" = " + std::to_string(i) +
                  " is not a vertex index (there are " + std::to_string(n) + ")"};
    return i;
}

uint32_t idOrNone(const json& o, const char* key) {
    return field(o, key).is_null() ? kNone : number(o, key);
}

Fingers fingers(const json& o, const char* key, size_t n) {
    const json& f = field(o, key);
    return {vertex(f, "left", n), vertex(f, "right", n), vertex(f, "nextLeft", n),
            vertex(f, "nextRight", n)};
}

uint8_t tests(const json& o, const char* key) {
    const json& a = field(o, key);
    if (!a.is_array()) throw Bad{std::string("field \"") + key + "\" is not a list of test names"};
    uint8_t bits = 0;
    for (const json& t : a) {
        int found = -1;
        for (int i = 0; i < int(Test::Count); ++i)
            if (t.is_string() && t.get<std::string>() == kTestNames[i]) found = i;
        if (found < 0)
            throw Bad{"unknown test " + io_detail::echo(t.dump()) + " in \"" + key + "\""};
        bits |= uint8_t(1u << found);
    }
    return bits;
}

template <typename Enum, typename NameFn>
Enum byName(const json& o, const char* key, int count, NameFn name) {
    const json& v = field(o, key);
    if (v.is_string())
        for (int i = 0; i < count; ++i)
            if (v.get<std::string>() == name(Enum(i))) return Enum(i);
    throw Bad{std::string("field \"") + key + "\" has unknown value " + io_detail::echo(v.dump())};
}

// How each kind of event field is read back (n: the vertex count, to check indices against).
Action readActionName(const json& o, const char* key, size_t) {
    return byName<Action>(o, key, int(Action::Count), actionName);
}
Side readSideName(const json& o, const char* key, size_t) {
    return byName<Side>(o, key, 2, [](Side s) { return s == Side::Left ? "Left" : "Right"; });
}
uint8_t readTestNames(const json& o, const char* key, size_t) { return tests(o, key); }
Forbidden readReasonName(const json& o, const char* key, size_t) {
    return byName<Forbidden>(o, key, int(Forbidden::Count), forbiddenName);
}
uint32_t readNumber(const json& o, const char* key, size_t) { return number(o, key); }
Fingers readFingerVertices(const json& o, const char* key, size_t n) { return fingers(o, key, n); }
Index readVertex(const json& o, const char* key, size_t n) { return vertex(o, key, n); }
uint32_t readGorgeId(const json& o, const char* key, size_t) { return idOrNone(o, key); }

// A field left out keeps its initial value (version 1 wrote them all); only the action is
// required. A subject field the action does not use is skipped: it shares storage with the
// action's own (version 1 wrote them all, null).
Event parseEvent(const json& o, size_t n) {
    Event e;
    e.action = readActionName(o, "action", n);
#define FLOOD_X(kind, type, name, initial)                                                     \
    if (Field::name != Field::action && usesField(e.action, Field::name) && o.contains(#name)) \
        e.name = read##kind(o, #name, n);
    FLOOD_EVENT_FIELDS(FLOOD_X)
#undef FLOOD_X
    return e;
}

void parseHeader(const json& h, Polygon& p) {
    const json& format = field(h, "format");
    if (!format.is_string() || format.get<std::string>() != "flood-trace")
        throw Bad{"not a flood trace (\"format\" is not \"flood-trace\")"};
    uint32_t version = number(h, "version");
    if (version < 1 || int(version) > kTraceFormatVersion)
        throw Bad{"trace format version " + std::to_string(version) +
                  ", this build reads versions 1 to " + std::to_string(kTraceFormatVersion)};
    const json& vs = field(h, "vertices");
    if (!vs.is_array()) throw Bad{"\"vertices\" is not an array"};
    for (size_t i = 0; i < vs.size(); ++i) {
        const json& v = vs[i];
        Point q;
        if (!v.is_array() || v.size() != 2 || !readCoordinate(v[0], q.x) ||
            !readCoordinate(v[1], q.y))
            throw Bad{"vertex " + std::to_string(i) + " is not a pair of numbers"};
        p.vertices.push_back(q);
    }
    auto pairs = [&](const char* key) {
        const json& a = field(h, key);
        if (!a.is_array()) throw Bad{std::string("\"") + key + "\" is not an array"};
        std::vector<std::pair<uint32_t, uint32_t>> out;
        for (const json& x : a) {
            if (!x.is_array() || x.size() != 2 || !x[0].is_number_unsigned() ||
                !x[1].is_number_unsigned() || x[0].get<uint64_t>() > 0xffffffffull ||
                x[1].get<uint64_t>() > 0xffffffffull)
                throw Bad{std::string("\"") + key + "\" entries must be [first, count] pairs"};
            out.emplace_back(x[0].get<uint32_t>(), x[1].get<uint32_t>());
        }
        return out;
    };
    uint64_t next = 0;
    for (auto [first, count] : pairs("rings")) {
        if (first != next) throw Bad{"rings do not cover the vertices in order"};
        p.rings.push_back({first, count});
        next += count;
    }
    if (next != p.vertices.size()) throw Bad{"rings do not cover all vertices"};
    next = 0;
    for (auto [first, count] : pairs("parts")) {
        if (first != next || count == 0) throw Bad{"parts do not cover the rings in order"};
        p.parts.push_back({first, count});
        next += count;
    }
    if (next != p.rings.size()) throw Bad{"parts do not cover all rings"};
    // T-junctions (optional: only written when there are any).
    if (h.contains("splits"))
        for (auto [edge, vertex] : pairs("splits")) {
            if (edge >= p.vertices.size() || vertex >= p.vertices.size())
                throw Bad{"\"splits\" names a vertex beyond the vertex list"};
            p.splits.push_back({edge, vertex});
        }
}

// The direction the water rose along (optional: written only when it is not +y).
void parseUpField(const json& h, Up& up) {
    if (!h.contains("up")) return;
    const json& u = h["up"];
    Up d;
    if (!u.is_array() || u.size() != 2 || !u[0].is_number() || !u[1].is_number() ||
        !(d = Up{u[0].get<double>(), u[1].get<double>()}).valid())
        throw Bad{"\"up\" is not a direction [x, y] (nonzero, finite)"};
    up = d;
}

}  // namespace

void writeTrace(std::ostream& out, const Trace& trace) {
    const Polygon& p = trace.polygon;
    json vertices = json::array(), rings = json::array(), parts = json::array();
    for (const Point& v : p.vertices)
        vertices.push_back({coordinateJson(v.x), coordinateJson(v.y)});
    for (const Ring& r : p.rings) rings.push_back({r.first, r.count});
    for (const Part& q : p.parts) parts.push_back({q.firstRing, q.ringCount});
    json header = {{"format", "flood-trace"},
                   {"version", kTraceFormatVersion},
                   {"vertices", vertices},
                   {"rings", rings},
                   {"parts", parts}};
    if (trace.up != Up::PlusY) header["up"] = {trace.up.x, trace.up.y};
    if (!p.splits.empty()) {
        json splits = json::array();
        for (const EdgeSplit& sp : p.splits) splits.push_back({sp.edge, sp.vertex});
        header["splits"] = splits;
    }
    out << header.dump() << "\n";
    for (const Event& e : trace.events) out << eventJson(e).dump() << "\n";
    json tris = json::array();
    for (const Triangle& t : trace.triangles) tris.push_back({t[0], t[1], t[2]});
    json last = {{"triangles", tris},
                 {"status", statusName(trace.diagnostic.status)},
                 {"message", trace.diagnostic.message}};
    out << last.dump() << "\n";
}

Diagnostic parseTrace(std::string_view text, const std::string& name, Trace& trace) {
    if (isBinaryTrace(text)) return parseBinaryTrace(text, name, trace);
    trace = Trace{};
    size_t lineNo = 0, pos = 0;
    bool sawHeader = false, sawEnd = false;
    try {
        while (pos < text.size()) {
            size_t eol = text.find('\n', pos);
            if (eol == std::string_view::npos) eol = text.size();
            std::string_view line = text.substr(pos, eol - pos);
            pos = eol + 1;
            ++lineNo;
            if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
            if (sawEnd) throw Bad{"text after the final triangles line"};
            if (io_detail::tooDeep(line) != std::string_view::npos)
                throw Bad{"JSON nested too deeply"};
            json o;
            try {
                o = json::parse(line.begin(), line.end());
            } catch (const json::parse_error& e) {
                throw Bad{std::string("JSON syntax error at column ") + std::to_string(e.byte) +
                          ": " + io_detail::jsonReason(e.what())};
            }
            if (size_t at = io_detail::firstUnderflow(line); at != std::string_view::npos)
                throw Bad{"column " + std::to_string(at + 1) + ": " +
                          io_detail::underflowReason(io_detail::literalAt(line, at))};
            if (!o.is_object()) throw Bad{"a line must be one JSON object"};
            if (!sawHeader) {
                parseHeader(o, trace.polygon);
                parseUpField(o, trace.up);
                sawHeader = true;
            } else if (o.contains("triangles")) {
                const json& ts = o["triangles"];
                if (!ts.is_array()) throw Bad{"\"triangles\" is not an array"};
                size_t n = trace.polygon.vertices.size();
                for (const json& t : ts) {
                    if (!t.is_array() || t.size() != 3) throw Bad{"a triangle is not [a, b, c]"};
                    Triangle tri;
                    for (int k = 0; k < 3; ++k) {
                        if (!t[k].is_number_unsigned() || t[k].get<uint64_t>() >= n)
                            throw Bad{"triangle " + io_detail::echo(t.dump()) +
                                      " has a bad vertex index"};
                        tri[k] = t[k].get<Index>();
                    }
                    trace.triangles.push_back(tri);
                }
                const json& st = field(o, "status");
                bool known = false;
                for (int s : {0, 2, 3, 4, 5, 6, 7})
                    if (st.is_string() && st.get<std::string>() == statusName(Status(s))) {
                        trace.diagnostic.status = Status(s);
                        known = true;
                    }
                if (!known) throw Bad{"unknown status " + io_detail::echo(st.dump())};
                const json& msg = field(o, "message");
                if (!msg.is_string()) throw Bad{"\"message\" is not a string"};
                trace.diagnostic.message = msg.get<std::string>();
                sawEnd = true;
            } else {
                Event e = parseEvent(o, trace.polygon.vertices.size());
                if (e.step != trace.events.size())
                    throw Bad{"event step " + std::to_string(e.step) + ", expected " +
                              std::to_string(trace.events.size())};
                // Before the replay, the invariant checker or the viewer index anything with it.
                if (const char* problem =
                        eventProblem(e, trace.polygon.vertices.size(), trace.polygon.parts.size()))
                    throw Bad{"event " + std::to_string(e.step) + " (" + actionName(e.action) +
                              "): " + problem};
                trace.events.push_back(e);
            }
        }
        if (!sawHeader) throw Bad{"empty trace, no header line"};
        if (!sawEnd) throw Bad{"truncated trace: no final triangles line"};
        for (const Event& e : trace.events)
            if (uint64_t(e.firstTriangle) + e.triangleCount > trace.triangles.size()) {
                lineNo = 0;
                throw Bad{"event " + std::to_string(e.step) +
                          " refers to triangles beyond the final list"};
            }
        trace.events.shrink_to_fit();  // the log is most of a trace's memory: no slack kept
    } catch (const Bad& b) {
        trace = Trace{};
        return {Status::Malformed,
                name + (lineNo ? ":" + std::to_string(lineNo) : std::string()) + ": " + b.message};
    } catch (const json::exception& e) {
        trace = Trace{};
        return {Status::Malformed,
                name + ":" + std::to_string(lineNo) + ": " + io_detail::echo(e.what())};
    }
    return {};
}

Diagnostic readTraceFile(const std::string& path, Trace& trace) {
    trace = Trace{};
    std::string text;
    const std::string name = path == "-" ? "<stdin>" : path;
    Diagnostic d =
        readInputFile(path, text, kDefaultMaxInputBytes, "a flood trace", kBinaryTraceMagic);
    if (!d.ok()) return d;
    return parseTrace(text, name, trace);
}

}  // namespace flood
