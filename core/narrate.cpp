#include "narrate.h"

#include <algorithm>
#include <sstream>

#include "flood.h"
#include "io_util.h"  // formatDouble: shortest round-trip
#include "transcript.h"

namespace flood {
namespace {

// "vertex 7", or "vertex 7 of hole 1" when it lies on a hole.
std::string vertex(const Polygon& polygon, Index v) {
    if (v == kNone) return "no vertex";
    std::string s = "vertex " + std::to_string(v);
    if (v < polygon.vertices.size()) {
        Index r = polygon.ringOf(v);
        for (const Part& p : polygon.parts)
            if (r > p.firstRing && r < p.firstRing + p.ringCount)
                s += " of hole " + std::to_string(r - p.firstRing);
    }
    return s;
}

const char* sideName(Side s) { return s == Side::Left ? "Left" : "Right"; }
const char* fingerName(Side s) { return s == Side::Left ? "NextLeft" : "NextRight"; }
const char* bankName(Side s) { return s == Side::Left ? "left" : "right"; }
Side other(Side s) { return s == Side::Left ? Side::Right : Side::Left; }
Index finger(const Fingers& f, Side s) { return s == Side::Left ? f.nextLeft : f.nextRight; }
Index end(const Fingers& f, Side s) { return s == Side::Left ? f.left : f.right; }

// ", cutting triangles 8-12" / ", cutting triangle 8" / `none`.
std::string cutting(const Event& e, const char* none, const char* what = "") {
    if (e.triangleCount == 0) return none;
    std::string n = e.triangleCount == 1 ? ", cutting triangle " : ", cutting triangles ";
    return n + triangleRange(e.firstTriangle, e.triangleCount) + what;
}

// Where the water goes after a Fill or a Spill: the gorge resumed or started.
std::string nextGorge(const Polygon& polygon, const Event& e) {
    if (e.gorgePopped != kNone)
        return "the pending gorge waiting at " + vertex(polygon, e.after.left) +
               " is taken from the to-do list";
    if (e.bottom != kNone)
        return "the water starts again at bottom " + vertex(polygon, e.bottom) +
               ", which it has not reached yet";
    return "nothing is left to flood: the part is done";
}

std::string raise(const Polygon& polygon, const Event& e) {
    Side s = e.side;
    std::string why = std::string(fingerName(s)) + " (" + vertex(polygon, finger(e.before, s)) +
                      ") is lower than " + fingerName(other(s)) + " (" +
                      vertex(polygon, finger(e.before, other(s))) + ")";
    if (e.didTest(Test::SagInside) && !e.testResult(Test::SagInside))
        why += std::string(" and no sag lies between the water and ") + fingerName(s);
    return why + ": the water rises on the " + bankName(s) + " bank to " +
           vertex(polygon, end(e.after, s)) + cutting(e, ", cutting no triangle yet") + ".";
}

std::string bridge(const Polygon& polygon, const Event& e) {
    std::string why;
    if (e.testResult(Test::SameNext))
        why = "NextLeft and NextRight meet at " + vertex(polygon, e.before.nextLeft) +
              ", but sag " + vertex(polygon, e.sag) + " still hangs in the gorge below them";
    else
        why = "Sag " + vertex(polygon, e.sag) + " hangs in the gorge above the water and below " +
              fingerName(e.side) + " (" + vertex(polygon, finger(e.before, e.side)) + ")";
    if (e.gorgePushed == kNone)  // a Steiner point bounds nothing: nothing to split
        return why + ": it is a single point; a bridge joins it to the water at " +
               vertex(polygon, e.bridgeTo) + " and the chain runs on through it" +
               cutting(e, "", " (the wedge the point sees)") + ".";
    return why + ": a bridge joins it to the water at " + vertex(polygon, e.bridgeTo) +
           " and splits the gorge; the left half floods on, the right half waits on the to-do "
           "list" +
           cutting(e, "", " (the wedge the sag sees)") + ".";
}

std::string spill(const Polygon& polygon, const Event& e) {
    Side s = e.side;
    std::string why = std::string(sideName(s)) + " (" + vertex(polygon, e.top) +
                      ") is a top with no jump pointer and " + fingerName(s) +
                      " lies below it: the water spills over; the gorge is held there (jump "
                      "pointer to " +
                      vertex(polygon, e.jumpTarget) + ") and the water runs down the far side";
    if (e.gorgePopped != kNone && !e.didTest(Test::WalkLanded))
        return why + " into the pending gorge waiting at " +
               vertex(polygon, end(e.after, Side::Left)) + ", which floods on from there.";
    if (e.testResult(Test::WalkLanded))
        return why + " to bottom " + vertex(polygon, e.bottom) + ", where a new gorge starts.";
    return why + ", but cannot tell where it lands, so " + nextGorge(polygon, e) + ".";
}

std::string jump(const Polygon& polygon, const Event& e) {
    Side s = e.side;
    return std::string(sideName(s)) + " (" + vertex(polygon, e.top) +
           ") is a top whose jump pointer is set: the water has come round from the far side, "
           "so the chain jumps to the other bank at " +
           vertex(polygon, e.jumpTarget) + " and the two gorges become one.";
}

std::string fill(const Polygon& polygon, const Event& e) {
    // "meet at vertex 7", as a Bridge says it: "the same vertex (vertex 7)" read aloud
    // repeats the word.
    std::string s = "NextLeft and NextRight meet at " + vertex(polygon, e.before.nextLeft);
    if (e.didTest(Test::SagInside)) s += " and no sag hangs below it";
    return s + ": the gorge is filled to its ceiling by a fan from it" + cutting(e, "") + "; " +
           nextGorge(polygon, e) + ".";
}

std::string forbidden(const Polygon& polygon, const Event& e) {
    std::string at = vertex(polygon, e.culprit), what;
    switch (e.reason) {
        case Forbidden::StartNotBottom:
            what = "The lowest vertex of the outer loop (" + at +
                   "), where Left and Right start, is not a convex bottom";
            break;
        case Forbidden::CeilingAsEnd:
            what = std::string(sideName(e.side)) + " (" + at +
                   ") is the highest point of its bank but convex: a ceiling, not a top";
            break;
        case Forbidden::JumpWrongSide:
            what = std::string(sideName(e.side)) + " (" + at +
                   ") is a top with a jump pointer, but its held gorge waits on the bank the "
                   "water came from";
            break;
        case Forbidden::SpillNoBottom:
            what = "The water spills over the top " + at + " but finds no gorge to flood";
            break;
        case Forbidden::NotFinite:
            what =
                "A coordinate of " + at + " is not a finite number, so no height can be compared";
            break;
        case Forbidden::ShortLoop:
            what = "A ring with fewer than three vertices bounds no area and cannot be flooded";
            break;
        case Forbidden::BadTriangle:
            what = "The triangle at " + at + " and " + vertex(polygon, e.culprit2) +
                   " would be inverted or flat";
            break;
        case Forbidden::FillOpen:
            what = "The fingers meet at " + at + " but the gorge does not close";
            break;
        case Forbidden::LeftBehind:
            what = "Nothing is left to flood, yet the water never reached " + at;
            break;
        case Forbidden::NoProgress: what = "The machine ran out of steps"; break;
        default: what = "The machine stopped"; break;
    }
    return what + ": forbidden (" + forbiddenName(e.reason) + "), " + forbiddenText(e.reason) + ".";
}

}  // namespace

std::string narrate(const Polygon& polygon, const Event& e) {
    switch (e.action) {
        case Action::Start: {
            std::string s = "The water starts at bottom " + vertex(polygon, e.bottom) +
                            ", the lowest vertex of the outer loop";
            if (polygon.parts.size() > 1) s += " of part " + std::to_string(e.part);
            return s + ": Left and Right are both this vertex.";
        }
        case Action::Raise: return raise(polygon, e);
        case Action::Bridge: return bridge(polygon, e);
        case Action::Spill: return spill(polygon, e);
        case Action::Jump: return jump(polygon, e);
        case Action::Fill: return fill(polygon, e);
        case Action::Forbidden: return forbidden(polygon, e);
        case Action::Count: break;
    }
    return "?";
}

// Declared in flood.h (the public API): a forbidden state's diagnostic, in words and as data.
Culprits forbiddenCulprits(const Polygon& polygon, const Event& e) {
    Culprits c;
    const Fingers& f = e.before;
    for (Index v : {e.culprit, e.culprit2, f.left, f.right, f.nextLeft, f.nextRight})
        if (v < polygon.vertices.size() &&
            std::find(c.vertices.begin(), c.vertices.end(), v) == c.vertices.end()) {
            c.vertices.push_back(v);
            Index r = polygon.ringOf(v);
            if (std::find(c.rings.begin(), c.rings.end(), r) == c.rings.end()) c.rings.push_back(r);
        }
    return c;
}

std::string describeForbidden(const Polygon& polygon, const Event& e) {
    std::ostringstream os;
    auto vertex = [&](const char* label, Index v) {
        if (v == kNone || v >= polygon.vertices.size()) return;
        Index r = polygon.ringOf(v);
        Point p = polygon.vertices[v];
        // Coordinates as the shortest text that reads back the same (-127.71, not
        // -127.70999999999999), as every message and file writes them.
        os << "; " << label << " = vertex " << v << " (ring " << r << " vertex "
           << v - polygon.rings[r].first << ", " << io_detail::formatDouble(p.x) << ", "
           << io_detail::formatDouble(p.y) << ")";
    };
    os << "forbidden transition " << forbiddenName(e.reason) << " at step " << e.step + 1;
    vertex("at", e.culprit);
    vertex("and", e.culprit2);
    vertex("Left", e.after.left);
    vertex("Right", e.after.right);
    os << ": " << forbiddenText(e.reason);
    return os.str();
}

}  // namespace flood
