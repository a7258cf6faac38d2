// The C++ half of the Python module `flood` (python/flood/__init__.py is the other half): turns
// Python inputs into core Polygons while holding the GIL, then runs the core without it.
// Inputs arrive already normalised by __init__.py: a str (WKT or GeoJSON text, read by the
// core's own readers) or a list of parts, each a list of (n, 2) float64 arrays, outer ring
// first. Failures come back as (status code, message) pairs; __init__.py turns them into
// Diagnostic objects and exceptions.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <memory>
#include <thread>
#include <type_traits>

#include "cli/run.h"  // the flood command, for python -m flood
#include "flood/check/checker.h"
#include "flood/check/diagnostic_where.h"
#include "flood/check/verdict.h"
#include "flood/io/io.h"
#include "flood/io/output.h"
#include "flood/log/replay.h"
#include "flood/machine/flood.h"
#include "flood/tools/generate.h"

namespace py = pybind11;
using namespace flood;

namespace flood::io_detail {
// Defined in core/io/io_read.cpp: the readers' ring cleaning (repeated consecutive points dropped
// with a warning, a closing point dropped), so an array reads exactly as the same file would.
void addCleanRing(ReadResult& rr, const std::string& name, const std::vector<Point>& raw,
                  bool outer);
}  // namespace flood::io_detail

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Why `a` is no ring, or "": a ring is n rows of x, y and optionally z and m (dropped), so an
// (n, 2), (n, 3) or (n, 4) array. A shape with fewer rows than columns, 2 to 4 of them, is
// what a transposed ring [xs, ys, zs] looks like: refused too (a (3, 4) array would otherwise
// be three points), except one point (a hole of one point, z given).
std::string badRingShape(const Array& a) {
    const char* expected =
        "a ring is an (n, 2), (n, 3) or (n, 4) array: one row per point, x, y[, z[, m]]";
    if (!a) return expected;
    std::string shape = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k)
        shape += (k ? ", " : "") + std::to_string(a.shape(k));
    shape += a.ndim() == 1 ? ",)" : ")";
    if (a.ndim() != 2) return std::string(expected) + "; got an array of shape " + shape;
    const py::ssize_t rows = a.shape(0), columns = a.shape(1);
    if (rows >= 2 && rows <= 4 && columns > rows)
        return std::string(expected) + "; got shape " + shape + ", " + std::to_string(rows) +
               " rows of " + std::to_string(columns) +
               ": transposed? [xs, ys] or [xs, ys, zs] must be passed as its transpose (a.T)";
    if (columns < 2 || columns > 4) return std::string(expected) + "; got shape " + shape;
    return "";
}

// A str's UTF-8 bytes in `text`, or "" and a Malformed diagnostic when it has a lone surrogate
// (UTF-8 cannot hold one; the command line's JSON reader refuses "\ud800" as malformed too).
// Needs the GIL.
Diagnostic utf8Of(py::handle str, const std::string& name, std::string& text) {
    Py_ssize_t size = 0;
    if (const char* utf8 = PyUnicode_AsUTF8AndSize(str.ptr(), &size)) {
        text.assign(utf8, size_t(size));
        return {};
    }
    PyErr_Clear();
    Py_ssize_t at = 0;
    const Py_ssize_t length = PyUnicode_GET_LENGTH(str.ptr());
    Py_UCS4 c = 0;
    while (at < length && ((c = PyUnicode_READ_CHAR(str.ptr(), at)) < 0xD800 || c > 0xDFFF)) ++at;
    char code[16];
    std::snprintf(code, sizeof code, "U+%04X", unsigned(c));
    return {Status::Malformed, name + ": the text holds a lone surrogate " + code +
                                   " at character " + std::to_string(at) +
                                   ": it is not Unicode, and UTF-8 cannot encode it"};
}

// Reads one input (see the file comment). Needs the GIL.
ReadResult readInput(py::handle input, const std::string& name) {
    if (py::isinstance<py::str>(input)) {
        std::string text;
        ReadResult rr;
        rr.diagnostic = utf8Of(input, name, text);
        if (!rr.diagnostic.ok()) return rr;
        py::gil_scoped_release unlocked;
        return parsePolygon(text, name);
    }
    if (py::isinstance<py::bytes>(input)) {  // WKB (the Python side passes only WKB as bytes)
        std::string bytes = input.cast<std::string>();
        py::gil_scoped_release unlocked;
        return parseWkb(bytes, name);
    }
    ReadResult rr;
    size_t parts = 0;
    for (py::handle part : input) {
        // An empty part is no polygon, as the command line's reader says of [].
        if (py::len(part) == 0) {
            rr.diagnostic = {Status::Malformed, name + ": polygon " + std::to_string(parts) +
                                                    ": polygon has no rings"};
            return rr;
        }
        ++parts;
        bool outer = true;
        for (py::handle ring : part) {
            Array a = Array::ensure(ring);
            if (std::string why = badRingShape(a); !why.empty()) {
                rr.diagnostic = {
                    Status::Malformed,
                    name + ": ring " + std::to_string(rr.polygon.rings.size()) + ": " + why};
                return rr;
            }
            std::vector<Point> raw(size_t(a.shape(0)));
            auto v = a.unchecked<2>();
            for (size_t i = 0; i < raw.size(); ++i) raw[i] = {v(i, 0), v(i, 1)};
            io_detail::addCleanRing(rr, name, raw, outer);
            outer = false;
        }
    }
    if (rr.polygon.rings.empty())
        rr.diagnostic = {Status::Malformed, name + ": polygon has no rings"};
    return rr;
}

// The CLI's --up: an axis, an angle in degrees or "X,Y" (flood/geometry/up.h).
Up upOf(const std::string& up) {
    Up d;
    std::string why;
    if (!parseUp(up, d, why)) throw py::value_error("up: " + why);
    return d;
}

// The CLI's pipeline (cli/main.cpp): read, validate, flood, exact check of the result.
struct Outcome {
    Diagnostic diagnostic;
    std::vector<std::string> warnings;
    Polygon polygon;
    std::vector<Triangle> triangles;
    Where where;  // check() keeps where the diagnostic points, not the polygon
};

// The core's judge (flood/check/verdict.h): validation, flooding, the checker's verdict. No GIL
// needed.
void run(Outcome& o, bool validateFirst, const Options& options, const std::string& name) {
    if (!o.diagnostic.ok()) return;
    Judgement j = judge(o.polygon, name, {validateFirst, true, options});
    o.diagnostic = std::move(j.diagnostic);
    if (j.ok()) o.triangles = std::move(j.triangles);
}

Outcome prepare(py::handle input, const std::string& name) {
    ReadResult rr = readInput(input, name);
    Outcome o;
    o.diagnostic = rr.diagnostic;
    o.warnings = std::move(rr.warnings);
    if (rr.warningsOmitted)
        o.warnings.push_back(name + ": ... and " + std::to_string(rr.warningsOmitted) +
                             " more warnings like these");
    o.polygon = std::move(rr.polygon);
    return o;
}

py::array_t<double> verticesArray(const Polygon& p) {
    py::array_t<double> a({py::ssize_t(p.vertices.size()), py::ssize_t(2)});
    auto m = a.mutable_unchecked<2>();
    for (size_t i = 0; i < p.vertices.size(); ++i)
        m(i, 0) = p.vertices[i].x, m(i, 1) = p.vertices[i].y;
    return a;
}

py::array_t<int64_t> trianglesArray(const std::vector<Triangle>& t) {
    py::array_t<int64_t> a({py::ssize_t(t.size()), py::ssize_t(3)});
    auto m = a.mutable_unchecked<2>();
    for (size_t i = 0; i < t.size(); ++i)
        for (int k = 0; k < 3; ++k) m(i, k) = t[i][k];
    return a;
}

// Ring lengths, so Python can tell which vertices belong to which ring.
std::vector<Index> ringCounts(const Polygon& p) {
    std::vector<Index> counts;
    for (const Ring& r : p.rings) counts.push_back(r.count);
    return counts;
}

py::object index(Index i) { return i == kNone ? py::object(py::none()) : py::object(py::int_(i)); }

// (status code, message, reason, ring, vertex): where it points read from its culprits
// (flood/check/diagnostic_where.h), None for "names none".
py::tuple diagnosticTuple(const Diagnostic& d, const Polygon& polygon, const std::string& name) {
    Where w = whereOf(polygon, d.culprits);
    return py::make_tuple(int(d.status), d.message, reasonOf(d.message, name, w), index(w.ring),
                          index(w.vertex));
}

// The numpy dtype of flood::Event: field names, types and offsets as flood/machine/events.h has
// them, so the log is copied into the array byte for byte.
py::dtype eventDtype() {
    py::dict fingers;
    fingers["names"] = py::make_tuple("left", "right", "nextLeft", "nextRight");
    fingers["formats"] = py::make_tuple("<u4", "<u4", "<u4", "<u4");
    fingers["offsets"] = py::make_tuple(offsetof(Fingers, left), offsetof(Fingers, right),
                                        offsetof(Fingers, nextLeft), offsetof(Fingers, nextRight));
    fingers["itemsize"] = sizeof(Fingers);
    py::object fingersType = py::dtype::from_args(fingers);
    py::list names, formats, offsets;
    auto field = [&](const char* n, py::object format, size_t offset) {
        names.append(n);
        formats.append(format);
        offsets.append(offset);
    };
    // Every field of FLOOD_EVENT_FIELDS, typed by its size: a one-byte enum or bit set, a
    // 32-bit number, index or id, or the four fingers.
    py::str u1("u1"), u4("<u4");
    auto format = [&](size_t size) -> py::object {
        return size == 1 ? py::object(u1) : size == 4 ? py::object(u4) : fingersType;
    };
#define FLOOD_X(kind, type, name, initial)                                                 \
    static_assert(sizeof(type) == 1 || sizeof(type) == 4 || std::is_same_v<type, Fingers>, \
                  "a new kind of event field needs its numpy type here");                  \
    field(#name, format(sizeof(type)), offsetof(Event, name));
    FLOOD_EVENT_FIELDS(FLOOD_X)
#undef FLOOD_X
    py::dict d;
    d["names"] = names;
    d["formats"] = formats;
    d["offsets"] = offsets;
    d["itemsize"] = sizeof(Event);
    return py::dtype::from_args(d);
}

static_assert(std::is_standard_layout_v<Event> && std::is_trivially_copyable_v<Event>,
              "events are copied into numpy byte for byte");

// A recorded run and its replay; the replay points into the trace, so both live here.
struct TraceHandle {
    Trace trace;
    std::unique_ptr<Replay> replay;
    std::vector<std::string> warnings;
    std::string name;  // the input's name, which its diagnostic's message starts with
};

}  // namespace

PYBIND11_MODULE(_flood, m) {
    m.doc() = "Flood's core (C++): see the package flood for the documented API";
    m.attr("NONE") = kNone;
    {
        py::list actions, tests, reasons;
        for (int i = 0; i < int(Action::Count); ++i) actions.append(actionName(Action(i)));
        for (int i = 0; i < int(Test::Count); ++i) tests.append(testText(Test(i)));
        for (int i = 0; i < int(Forbidden::Count); ++i) reasons.append(forbiddenName(Forbidden(i)));
        m.attr("ACTIONS") = actions;
        m.attr("TESTS") = tests;
        m.attr("FORBIDDEN") = reasons;
        py::dict statuses;
        for (Status s :
             {Status::Ok, Status::Usage, Status::Malformed, Status::Invalid, Status::Forbidden,
              Status::Internal, Status::VerifyFailed, Status::WriteFailed})
            statuses[py::int_(int(s))] = statusName(s);
        m.attr("STATUS_NAMES") = statuses;
    }
    m.attr("EVENT_DTYPE") = eventDtype();

    // Which files of a folder are polygons (polygonFiles, flood/io/io.h): the tests' listing of
    // polygons/ (python/tests/conftest.py), the one the C++ tests and the viewer use.
    m.def("polygon_files", [](const std::string& dir) { return polygonFiles(dir); });

    m.def("validate", [](py::handle input, const std::string& name) {
        Outcome o = prepare(input, name);
        {
            py::gil_scoped_release unlocked;
            if (o.diagnostic.ok()) o.diagnostic = validate(o.polygon, name);
        }
        return py::make_tuple(diagnosticTuple(o.diagnostic, o.polygon, name), o.warnings);
    });

    m.def("triangulate",
          [](py::handle input, bool validateFirst, const std::string& up, const std::string& name) {
              Options options;
              options.up = upOf(up);
              Outcome o = prepare(input, name);
              {
                  py::gil_scoped_release unlocked;
                  run(o, validateFirst, options, name);
              }
              return py::make_tuple(diagnosticTuple(o.diagnostic, o.polygon, name), o.warnings,
                                    verticesArray(o.polygon), trianglesArray(o.triangles),
                                    ringCounts(o.polygon));
          });

    // Many features at once on `threads` C++ threads: arrays are read first (they need the
    // GIL), texts (WKT, GeoJSON) by the threads; then every feature is validated, flooded and
    // checked without the GIL. One (status, message, reason, ring, vertex, triangle count) per feature, in order.
    m.def("check", [](py::sequence inputs, bool validateFirst, const std::string& up,
                      unsigned threads, const std::vector<std::string>& names) {
        Options options;
        options.up = upOf(up);
        if (names.size() != inputs.size()) throw py::value_error("one name per feature");
        std::vector<Outcome> outcomes(inputs.size());
        std::vector<std::string> texts(inputs.size());
        // Texts and WKB are copied and read by the threads; arrays (and a text that is no
        // UTF-8) are read here.
        enum class Kind : uint8_t { Arrays, Text, Wkb };
        std::vector<Kind> kind(inputs.size(), Kind::Arrays);
        for (size_t i = 0; i < inputs.size(); ++i) {
            // Ctrl+C: Python's handler only sets a flag, acted on here (a KeyboardInterrupt).
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            py::handle input = inputs[i];
            if (py::isinstance<py::str>(input)) kind[i] = Kind::Text;
            else if (py::isinstance<py::bytes>(input)) kind[i] = Kind::Wkb;
            if (kind[i] == Kind::Wkb) texts[i] = input.cast<std::string>();
            else if (kind[i] == Kind::Arrays) outcomes[i] = prepare(input, names[i]);
            else if (Diagnostic d = utf8Of(input, names[i], texts[i]); !d.ok())
                outcomes[i].diagnostic = d, kind[i] = Kind::Arrays;  // read: a verdict already
        }
        bool interrupted = false;
        {
            py::gil_scoped_release unlocked;
            std::atomic<size_t> nextFeature{0};
            std::atomic<bool> stop{false};
            auto one = [&](size_t i) {
                Outcome& o = outcomes[i];
                if (kind[i] != Kind::Arrays) {
                    ReadResult rr = kind[i] == Kind::Text ? parsePolygon(texts[i], names[i])
                                                          : parseWkb(texts[i], names[i]);
                    o.diagnostic = rr.diagnostic;
                    o.polygon = std::move(rr.polygon);
                    std::string().swap(texts[i]);
                }
                run(o, validateFirst, options, names[i]);
                o.where = whereOf(o.polygon, o.diagnostic.culprits);
                o.polygon = {};  // the verdict is all that is kept
            };
            auto worker = [&] {
                for (size_t i; !stop.load(std::memory_order_relaxed) &&
                               (i = nextFeature++) < outcomes.size();)
                    one(i);
            };
            if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
            threads = unsigned(std::min<size_t>(threads, std::max<size_t>(1, outcomes.size())));
            std::vector<std::thread> pool;
            for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
            // This thread works too, and between its features looks for a signal (Ctrl+C) with
            // the GIL, at most every 20 ms: taking the GIL from a busy Python thread can wait
            // its switch interval (5 ms). A signal stops every worker after its feature.
            using Clock = std::chrono::steady_clock;
            Clock::time_point lastLook = Clock::now();
            for (size_t i;
                 !stop.load(std::memory_order_relaxed) && (i = nextFeature++) < outcomes.size();) {
                one(i);
                if (Clock::now() - lastLook < std::chrono::milliseconds(20)) continue;
                py::gil_scoped_acquire locked;
                if (PyErr_CheckSignals() != 0) interrupted = true, stop = true;
                lastLook = Clock::now();
            }
            for (std::thread& t : pool) t.join();
        }
        if (interrupted) throw py::error_already_set();  // the KeyboardInterrupt, still set
        py::list verdicts;
        for (const Outcome& o : outcomes)
            verdicts.append(
                py::make_tuple(int(o.diagnostic.status), o.diagnostic.message,
                               reasonOf(o.diagnostic.message, names[&o - outcomes.data()], o.where),
                               index(o.where.ring), index(o.where.vertex), o.triangles.size()));
        return verdicts;
    });

    m.def("generate", [](const std::string& family, size_t size, uint64_t seed) {
        auto families = familyNames();
        if (std::find(families.begin(), families.end(), family) == families.end())
            throw py::value_error("unknown family '" + family + "'");
        Polygon p;
        {
            py::gil_scoped_release unlocked;
            p = generate(family, seed, size);
        }
        py::list parts;
        for (const Part& part : p.parts) {
            py::list rings;
            for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
                const Ring& ring = p.rings[r];
                py::array_t<double> a({py::ssize_t(ring.count), py::ssize_t(2)});
                auto m = a.mutable_unchecked<2>();
                for (Index i = 0; i < ring.count; ++i)
                    m(i, 0) = p.vertices[ring.first + i].x, m(i, 1) = p.vertices[ring.first + i].y;
                rings.append(a);
            }
            parts.append(rings);
        }
        return parts;
    });
    m.def("families", &familyNames);
    // `python -m flood ARGS` and the `flood` console script: the command itself (cli/run.h),
    // not a re-implementation, so every option, message and exit code is the CLI's. It writes
    // to file descriptors 1 and 2 directly; the caller flushes Python's streams first.
    m.def("_cli", [](const std::vector<std::string>& args) {
        std::vector<std::string> copy = args;
        std::vector<char*> argv;
        for (std::string& a : copy) argv.push_back(a.data());
        argv.push_back(nullptr);
        py::gil_scoped_release unlocked;
        return flood::finishStdout(flood::cli::run(int(copy.size()), argv.data()));
    });
    m.def("wkb_like", [](const py::bytes& b) { return wkbLike(std::string_view(b)); });

    py::class_<Fingers>(m, "Fingers")
        .def_readonly("left", &Fingers::left)
        .def_readonly("right", &Fingers::right)
        .def_readonly("nextLeft", &Fingers::nextLeft)
        .def_readonly("nextRight", &Fingers::nextRight)
        .def("__repr__", [](const Fingers& f) {
            return "Fingers(left=" + std::to_string(f.left) + ", right=" + std::to_string(f.right) +
                   ", nextLeft=" + std::to_string(f.nextLeft) +
                   ", nextRight=" + std::to_string(f.nextRight) + ")";
        });

    py::class_<Gorge>(m, "Gorge")
        .def_readonly("id", &Gorge::id)
        .def_readonly("held", &Gorge::held)
        .def_readonly("top", &Gorge::top)
        .def_readonly("chain", &Gorge::chain);

    py::class_<ReplayState>(m, "ReplayState")
        .def_readonly("step", &ReplayState::step)
        .def_readonly("part", &ReplayState::part)
        .def_readonly("fingers", &ReplayState::fingers)
        .def_property_readonly("left", [](const ReplayState& s) { return s.fingers.left; })
        .def_property_readonly("right", [](const ReplayState& s) { return s.fingers.right; })
        .def_readonly("water", &ReplayState::water)
        .def_readonly("triangleCount", &ReplayState::triangleCount)
        .def_readonly("chain", &ReplayState::chain)
        .def_readonly("dormant", &ReplayState::dormant)
        .def_readonly("jumps", &ReplayState::jumps)
        .def_readonly("bridges", &ReplayState::bridges)
        .def_readonly("forbidden", &ReplayState::forbidden);

    // The replay of a trace (flood/log/replay.h); seek returns a copy of the state, so a state read
    // earlier does not change under the caller when the replay moves on.
    py::class_<TraceHandle, std::shared_ptr<TraceHandle>>(m, "Trace")
        .def_property_readonly(
            "events",
            [](const TraceHandle& t) {
                py::array a(eventDtype(),
                            std::vector<py::ssize_t>{py::ssize_t(t.trace.events.size())});
                if (!t.trace.events.empty())
                    std::memcpy(a.mutable_data(), t.trace.events.data(),
                                t.trace.events.size() * sizeof(Event));
                return a;
            })
        .def_property_readonly("vertices",
                               [](const TraceHandle& t) { return verticesArray(t.trace.polygon); })
        .def_property_readonly(
            "triangles", [](const TraceHandle& t) { return trianglesArray(t.trace.triangles); })
        .def_property_readonly("diagnostic",
                               [](const TraceHandle& t) {
                                   return diagnosticTuple(t.trace.diagnostic, t.trace.polygon,
                                                          t.name);
                               })
        .def_readonly("warnings", &TraceHandle::warnings)
        .def("__len__", [](const TraceHandle& t) { return t.trace.events.size(); })
        .def("seek", [](TraceHandle& t, uint32_t step) {
            if (step > t.replay->size())
                throw py::index_error("step " + std::to_string(step) + " is past the last event (" +
                                      std::to_string(t.replay->size()) + ")");
            return ReplayState(t.replay->seek(step));
        });

    // Records a run: read, validate (unless told not to), flood with a recorder. A forbidden
    // run is recorded too (it is what one wants to look at); malformed or invalid input is not.
    m.def("trace",
          [](py::handle input, bool validateFirst, const std::string& up,
             const std::string& name) -> py::object {
              Options options;
              options.up = upOf(up);
              Outcome o = prepare(input, name);
              auto t = std::make_shared<TraceHandle>();
              t->warnings = o.warnings;
              t->name = name;
              {
                  py::gil_scoped_release unlocked;
                  if (o.diagnostic.ok() && validateFirst) o.diagnostic = validate(o.polygon, name);
                  if (o.diagnostic.ok()) {
                      t->trace = record(o.polygon, options);
                      // A forbidden run keeps the machine's diagnostic; a checked one the judge's.
                      if (t->trace.diagnostic.ok())
                          t->trace.diagnostic = judgeRun(t->trace.polygon, t->trace.triangles,
                                                         t->trace.diagnostic, name)
                                                    .diagnostic;
                      t->replay = std::make_unique<Replay>(t->trace);
                  }
              }
              if (!o.diagnostic.ok()) return diagnosticTuple(o.diagnostic, o.polygon, name);
              return py::cast(t);
          });
}
