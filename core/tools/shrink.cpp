// The shrinker (see shrink.h): failure classification in a forked child, then greedy
// reduction of parts, holes, vertices and coordinate precision.
#include "flood/tools/shrink.h"

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "flood/check/checker.h"
#include "flood/check/touches.h"
#include "flood/check/verify.h"
#include "flood/io/io.h"

namespace flood {

const char* failureKindName(Failure::Kind k) {
    switch (k) {
        case Failure::Kind::None: return "none";
        case Failure::Kind::Forbidden: return "forbidden transition";
        case Failure::Kind::CheckerRejects: return "exact checker rejects the triangulation";
        case Failure::Kind::Crash: return "crash";
        case Failure::Kind::Hang: return "hang";
        case Failure::Kind::Slips: return "invalid, yet the unvalidated verification passes it";
    }
    return "?";
}

namespace {

// [SECTION] classification ----------------------------------------------------------------

// Slipping mode: the candidate is invalid and verify() on the unvalidated path passes it.
Failure classifySlip(const Polygon& polygon, const ShrinkOptions& o) {
    Polygon p = polygon;
    Failure f;
    Diagnostic d = validate(p, "candidate");
    if (d.ok()) return f;
    p.splits.clear();
    findTouches(p);
    if (!verify(p, o.flood).ok()) return f;
    f.kind = Failure::Kind::Slips;
    f.message = d.message;
    return f;
}

Failure classifyHere(const Polygon& polygon, const ShrinkOptions& o) {
    if (o.slipping) return classifySlip(polygon, o);
    FloodResult r = triangulate(polygon, nullptr, o.flood);
    Failure f;
    if (!r.diagnostic.ok()) {
        f.kind = Failure::Kind::Forbidden;
        f.reason = r.failure.reason;
        f.message = r.diagnostic.message;
        return f;
    }
    if (o.corrupt) o.corrupt(r.triangles);
    CheckResult c = checkTriangulation(polygon, r.triangles);
    if (!c.ok) {
        f.kind = Failure::Kind::CheckerRejects;
        f.message = c.reason;
    }
    return f;
}

// Child exit codes: 0 ok, 100 + reason forbidden, 120 checker rejects, 121 slips. Anything else,
// including a sanitizer's exit code 1 and a signal, is a crash; SIGALRM is a hang.
constexpr int kForbiddenBase = 100, kCheckerCode = 120, kSlipsCode = 121;

Failure classifyInChild(const Polygon& polygon, const ShrinkOptions& o) {
    pid_t pid = fork();
    if (pid < 0) return classifyHere(polygon, o);  // no fork available: run in process
    if (pid == 0) {
        alarm(o.timeoutSeconds);
        Failure f = classifyHere(polygon, o);
        int code = f.kind == Failure::Kind::Forbidden        ? kForbiddenBase + int(f.reason)
                   : f.kind == Failure::Kind::CheckerRejects ? kCheckerCode
                   : f.kind == Failure::Kind::Slips          ? kSlipsCode
                                                             : 0;
        _exit(code);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) return {Failure::Kind::Crash, Forbidden::None, "waitpid failed"};
    }
    Failure f;
    if (WIFSIGNALED(status)) {
        int sig = WTERMSIG(status);
        f.kind = sig == SIGALRM ? Failure::Kind::Hang : Failure::Kind::Crash;
        f.message = sig == SIGALRM
                        ? "no result within " + std::to_string(o.timeoutSeconds) + " s"
                        : "killed by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
        return f;
    }
    int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (code == 0) return f;
    if (code == kCheckerCode) {
        f.kind = Failure::Kind::CheckerRejects;
    } else if (code == kSlipsCode) {
        f.kind = Failure::Kind::Slips;
    } else if (code > kForbiddenBase && code < kForbiddenBase + int(Forbidden::Count)) {
        f.kind = Failure::Kind::Forbidden;
        f.reason = Forbidden(code - kForbiddenBase);
    } else {
        f.kind = Failure::Kind::Crash;
        f.message = "exited with code " + std::to_string(code);
        return f;
    }
    // The child only reports the class; recompute the message in-process only when safe,
    // i.e. for classes that are not crashes (the run finished normally there).
    f.message = classifyHere(polygon, o).message;
    return f;
}

// [SECTION] the polygon as editable rings -------------------------------------------------

// A vertex and its index in the input, so the repro can say which input vertices remain.
struct Vertex {
    Point p;
    Index origin = kNone;
    bool operator==(const Vertex& o) const { return p == o.p && origin == o.origin; }
    bool operator!=(const Vertex& o) const { return !(*this == o); }
};
using Rings = std::vector<std::vector<Vertex>>;
using Parts = std::vector<Rings>;

Parts toParts(const Polygon& p) {
    Parts parts;
    for (const Part& part : p.parts) {
        Rings rings;
        for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
            const Ring& ring = p.rings[r];
            auto& out = rings.emplace_back();
            for (Index v = ring.first; v < ring.first + ring.count; ++v)
                out.push_back({p.vertices[v], v});
        }
        parts.push_back(std::move(rings));
    }
    return parts;
}

Polygon toPolygon(const Parts& parts, std::vector<Index>* origin = nullptr) {
    Polygon p;
    std::vector<Point> pts;
    for (const Rings& rings : parts)
        for (size_t r = 0; r < rings.size(); ++r) {
            pts.clear();
            for (const Vertex& v : rings[r]) {
                pts.push_back(v.p);
                if (origin) origin->push_back(v.origin);
            }
            p.addRing(pts, r == 0);
        }
    return p;
}

// Rounds x to `bits` significant bits (bits >= 1), exactly representable.
double roundBits(double x, int bits) {
    if (!std::isfinite(x) || x == 0) return x;
    int e;
    std::frexp(x, &e);
    return std::ldexp(std::nearbyint(std::ldexp(x, bits - e)), e - bits);
}

// [SECTION] the repro as the user reads it back --------------------------------------------

// What `flood triangulate` does between reading and flooding: validate (which records the
// T-junctions), or with --no-validate search for them alone. The slipping mode prepares its
// own (classifySlip). False, with the reason, when validation refuses the polygon.
bool prepareAsRead(Polygon& p, const ShrinkOptions& o, bool validated, std::string& why) {
    if (o.slipping) return true;
    if (validated) {
        Diagnostic d = validate(p, "repro");
        why = d.message;
        return d.ok();
    }
    p.splits.clear();
    findTouches(p);
    return true;
}

class Shrinker {
public:
    Shrinker(const Polygon& input, const ShrinkOptions& o) : o_(o) {
        Polygon checked = input;  // validate() records the T-junctions the flood needs
        result_.inputValid = validate(checked, "shrink").ok();
        if (!result_.inputValid) checked.splits = input.splits;
        result_.failure = test(checked);
        result_.polygon = checked;
        best_ = toParts(input);
        for (Index v = 0; v < input.vertices.size(); ++v) result_.origin.push_back(v);
    }

    ShrinkResult run() {
        if (result_.failure.kind == Failure::Kind::None) return result_;
        bool progress = true;
        while (progress && result_.tries < o_.maxTries && !result_.cancelled) {
            progress = false;
            progress |= removeRings();
            progress |= removeVertices();
            progress |= reducePrecision();
        }
        result_.origin.clear();
        result_.polygon = toPolygon(best_, &result_.origin);
        // The final word: the repro's own bytes, read back, fail the same way. accept() has
        // seen that of every candidate it kept; only the input itself is left to read back.
        result_.reproduces =
            keptCandidate_ || classifyText(geoJsonGeometry(result_.polygon), o_, result_.inputValid)
                                  .sameClass(result_.failure);
        return result_;
    }

private:
    Failure test(const Polygon& p) {
        ++result_.tries;
        return o_.fork ? classifyInChild(p, o_) : classifyHere(p, o_);
    }

    size_t bestVertices() const {
        size_t n = 0;
        for (const Rings& rings : best_)
            for (const auto& ring : rings) n += ring.size();
        return n;
    }

    // Keeps `candidate` if, written and read back, it fails the same way (and stays valid when
    // the input was).
    bool accept(const Parts& candidate) {
        if (stopped()) return false;
        if (o_.onTry && !o_.onTry(result_.tries, bestVertices())) {
            result_.cancelled = true;
            return false;
        }
        Polygon p = toPolygon(candidate);
        if (p.rings.empty()) return false;
        ReadResult back = parsePolygon(geoJsonGeometry(p), "candidate");
        if (!back.diagnostic.ok() || !sameGeometry(back.polygon, p)) return false;
        std::string why;
        if (!prepareAsRead(back.polygon, o_, result_.inputValid, why)) return false;
        Failure f = test(back.polygon);
        if (!f.sameClass(result_.failure)) return false;
        best_ = candidate;
        result_.failure = f;
        keptCandidate_ = true;
        return true;
    }

    // Out of tries or cancelled: the loops below stop copying candidates at once.
    bool stopped() const { return result_.cancelled || result_.tries >= o_.maxTries; }

    bool removeRings() {
        bool any = false;
        // Whole parts, last first, while more than one remains.
        for (size_t i = best_.size(); i-- > 0 && best_.size() > 1;) {
            Parts c = best_;
            c.erase(c.begin() + long(i));
            any |= accept(c);
        }
        // Holes; then an outer ring, its first hole becoming the outer ring.
        for (size_t pi = best_.size(); pi-- > 0;) {
            for (size_t r = best_[pi].size(); r-- > 0;) {
                if (pi >= best_.size() || r >= best_[pi].size() || best_[pi].size() < 2) continue;
                Parts c = best_;
                c[pi].erase(c[pi].begin() + long(r));
                any |= accept(c);
            }
        }
        return any;
    }

    bool removeVertices() {
        bool any = false;
        for (size_t pi = 0; pi < best_.size(); ++pi) {
            for (size_t r = 0; r < best_[pi].size(); ++r) {
                for (size_t chunk = std::max<size_t>(1, best_[pi][r].size() / 2);; chunk /= 2) {
                    // Remove each run of `chunk` vertices in turn, keeping at least 3.
                    for (size_t start = 0; start < best_[pi][r].size() && !stopped();) {
                        size_t n = best_[pi][r].size();
                        size_t end = std::min(n, start + chunk);
                        if (n - (end - start) < 3) break;
                        Parts c = best_;
                        auto& cr = c[pi][r];
                        cr.erase(cr.begin() + long(start), cr.begin() + long(end));
                        if (accept(c)) any = true;  // the same start now names the next run
                        else start += chunk;
                    }
                    if (chunk <= 1 || stopped()) break;
                }
            }
        }
        return any;
    }

    template <typename F>
    Parts mapped(F&& f) const {
        Parts c = best_;
        for (Rings& rings : c)
            for (auto& ring : rings)
                for (Vertex& v : ring) v.p = {f(v.p.x), f(v.p.y)};
        return c;
    }

    bool reducePrecision() {
        bool any = false;
        Parts ints = mapped([](double x) { return std::isfinite(x) ? std::nearbyint(x) : x; });
        if (ints != best_ && accept(ints)) any = true;
        // The fewest significant bits that keep the failure (binary search over 1..52 is not
        // monotone in general; scan upwards and stop at the first that works).
        for (int bits = 1; bits < 53; ++bits) {
            Parts c = mapped([bits](double x) { return roundBits(x, bits); });
            if (c == best_) break;  // already this coarse
            if (accept(c)) {
                any = true;
                break;
            }
        }
        // Vertex by vertex to integers (when the global rounding changed the failure).
        for (size_t pi = 0; pi < best_.size(); ++pi)
            for (size_t r = 0; r < best_[pi].size(); ++r)
                for (size_t v = 0; v < best_[pi][r].size() && !stopped(); ++v) {
                    Point q = best_[pi][r][v].p;
                    if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;
                    Point rq{std::nearbyint(q.x), std::nearbyint(q.y)};
                    if (rq == q) continue;
                    Parts c = best_;
                    c[pi][r][v].p = rq;
                    any |= accept(c);
                }
        return any;
    }

    ShrinkOptions o_;
    ShrinkResult result_;
    Parts best_;
    bool keptCandidate_ = false;  // best_ is a candidate accept() read back and kept
};

}  // namespace

Failure classify(const Polygon& polygon, const ShrinkOptions& options) {
    return options.fork ? classifyInChild(polygon, options) : classifyHere(polygon, options);
}

ShrinkResult shrink(const Polygon& polygon, const ShrinkOptions& options) {
    return Shrinker(polygon, options).run();
}

Failure classifyText(std::string_view text, const ShrinkOptions& options, bool validated) {
    Failure f;
    ReadResult r = parsePolygon(text, "repro");
    if (!r.diagnostic.ok()) {
        f.message = r.diagnostic.message;
        return f;
    }
    if (!prepareAsRead(r.polygon, options, validated, f.message)) return f;
    return classify(r.polygon, options);
}

std::string reproduceCommand(const ShrinkResult& result, const ReproSource& source) {
    const std::string up = source.up.empty() ? "" : " --up " + source.up;
    const std::string out =
        source.output.empty() || source.output == "-" ? "REPRO.json" : source.output;
    if (result.failure.kind == Failure::Kind::Slips)
        return "flood verify --no-validate" + up + " " + out;
    return std::string("flood triangulate") + (result.inputValid ? "" : " --no-validate") + up +
           " " + out;
}

std::string reproJson(const Polygon& input, const ShrinkResult& result, const ReproSource& source) {
    using json = nlohmann::ordered_json;
    const Polygon& p = result.polygon;
    json props = json::object();
    props["source"] = source.file;
    if (!source.feature.empty()) props["feature"] = source.feature;
    if (!source.up.empty()) props["up"] = source.up;
    std::string kind = failureKindName(result.failure.kind);
    props["failure"] = kind;
    if (result.failure.kind == Failure::Kind::Forbidden)
        props["reason"] = forbiddenName(result.failure.reason);
    props["message"] = result.failure.message;
    props["reproduce"] = reproduceCommand(result, source);
    // The input's vertex indices that remain, ring by ring, and where they were.
    json rings = json::array();
    double box[4] = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const Ring& ring : p.rings) {
        json ids = json::array();
        for (Index v = ring.first; v < ring.first + ring.count; ++v) {
            if (v >= result.origin.size() || result.origin[v] >= input.vertices.size()) continue;
            Index o = result.origin[v];
            ids.push_back(o);
            const Point q = input.vertices[o];
            box[0] = std::min(box[0], q.x), box[1] = std::min(box[1], q.y);
            box[2] = std::max(box[2], q.x), box[3] = std::max(box[3], q.y);
        }
        rings.push_back(std::move(ids));
    }
    props["source_vertices"] = std::move(rings);
    if (box[0] <= box[2]) props["source_bbox"] = {box[0], box[1], box[2], box[3]};
    std::string text = "{\"type\":\"Feature\",\"properties\":";
    text += props.dump(-1, ' ', false, json::error_handler_t::replace);
    text += ",\n\"geometry\":" + geoJsonGeometry(p) + "}\n";
    return text;
}

}  // namespace flood
