#include "flood/teach/narrate.h"

#include "flood/machine/flood.h"
#include "flood/teach/transcript.h"

namespace flood {
namespace {

const char* sideName(Side s) { return s == Side::Left ? "Left" : "Right"; }
const char* fingerName(Side s) { return s == Side::Left ? "NextLeft" : "NextRight"; }
const char* fingerBefore(Side s) {
    return s == Side::Left ? "NextLeft before" : "NextRight before";
}
const char* bankName(Side s) { return s == Side::Left ? "left" : "right"; }
Side other(Side s) { return s == Side::Left ? Side::Right : Side::Left; }
Index finger(const Fingers& f, Side s) { return s == Side::Left ? f.nextLeft : f.nextRight; }
Index end(const Fingers& f, Side s) { return s == Side::Left ? f.left : f.right; }

// Writes what a sentence names: each vertex and triangle range goes into the text and into
// the Narration's data by the same call, so the two cannot disagree.
class Namer {
public:
    Namer(const Polygon& polygon, Narration& out) : polygon_(polygon), out_(out) {}

    // "vertex 7", or "vertex 7 of hole 1" when it lies on a hole; recorded with its role.
    std::string operator()(Index v, const char* role) {
        if (v == kNone) return "no vertex";
        out_.vertices.push_back({v, role});
        std::string s = "vertex " + std::to_string(v);
        if (v < polygon_.vertices.size()) {
            Index r = polygon_.ringOf(v);
            for (const Part& p : polygon_.parts)
                if (r > p.firstRing && r < p.firstRing + p.ringCount)
                    s += " of hole " + std::to_string(r - p.firstRing);
        }
        return s;
    }

    // ", cutting triangles 8-12" / ", cutting triangle 8" / `none`.
    std::string cutting(const Event& e, const char* none, const char* what = "") {
        if (e.triangleCount == 0) return none;
        out_.firstTriangle = e.firstTriangle, out_.triangleCount = e.triangleCount;
        std::string n = e.triangleCount == 1 ? ", cutting triangle " : ", cutting triangles ";
        return n + triangleRange(e.firstTriangle, e.triangleCount) + what;
    }

    bool holes() const { return polygon_.parts.size() > 1; }

private:
    const Polygon& polygon_;
    Narration& out_;
};

// Where the water goes after a Fill or a Spill: the gorge resumed or started.
std::string nextGorge(Namer& name, const Event& e) {
    if (e.gorgePopped != kNone)
        return "the pending gorge waiting at " + name(e.after.left, "gorge resumed") +
               " is taken from the to-do list";
    if (e.bottom != kNone)
        return "the water starts again at bottom " + name(e.bottom, "bottom") +
               ", which it has not reached yet";
    return "nothing is left to flood: the part is done";
}

std::string raise(Namer& name, const Event& e) {
    // Named one by one: the operands of + are evaluated in no set order.
    Side s = e.side;
    const std::string lower = name(finger(e.before, s), fingerBefore(s));
    const std::string higher = name(finger(e.before, other(s)), fingerBefore(other(s)));
    std::string why = std::string(fingerName(s)) + " (" + lower + ") is lower than " +
                      fingerName(other(s)) + " (" + higher + ")";
    if (e.didTest(Test::SagInside) && !e.testResult(Test::SagInside))
        why += std::string(" and no sag lies between the water and ") + fingerName(s);
    const std::string to = name(end(e.after, s), sideName(s));
    return why + ": the water rises on the " + bankName(s) + " bank to " + to +
           name.cutting(e, ", cutting no triangle yet") + ".";
}

std::string bridge(Namer& name, const Event& e) {
    std::string why;
    if (e.testResult(Test::SameNext)) {
        const std::string meet = name(e.before.nextLeft, "NextLeft = NextRight before");
        why = "NextLeft and NextRight meet at " + meet + ", but sag " + name(e.sag, "sag") +
              " still hangs in the gorge below them";
    } else {
        const std::string sag = name(e.sag, "sag");
        why = "Sag " + sag + " hangs in the gorge above the water and below " + fingerName(e.side) +
              " (" + name(finger(e.before, e.side), fingerBefore(e.side)) + ")";
    }
    const std::string to = name(e.bridgeTo, "bridge end");
    if (e.gorgePushed == kNone)  // a Steiner point bounds nothing: nothing to split
        return why + ": it is a single point; a bridge joins it to the water at " + to +
               " and the chain runs on through it" +
               name.cutting(e, "", " (the wedge the point sees)") + ".";
    return why + ": a bridge joins it to the water at " + to +
           " and splits the gorge; the left half floods on, the right half waits on the to-do "
           "list" +
           name.cutting(e, "", " (the wedge the sag sees)") + ".";
}

std::string spill(Namer& name, const Event& e) {
    Side s = e.side;
    const std::string top = name(e.top, "top");
    std::string why = std::string(sideName(s)) + " (" + top +
                      ") is a top with no jump pointer and " + fingerName(s) +
                      " lies below it: the water spills over; the gorge is held there (jump "
                      "pointer to " +
                      name(e.jumpTarget, "jump pointer") + ") and the water runs down the far side";
    if (e.gorgePopped != kNone && !e.didTest(Test::WalkLanded))
        return why + " into the pending gorge waiting at " +
               name(end(e.after, Side::Left), "gorge resumed") + ", which floods on from there.";
    if (e.testResult(Test::WalkLanded))
        return why + " to bottom " + name(e.bottom, "bottom") + ", where a new gorge starts.";
    return why + ", but cannot tell where it lands, so " + nextGorge(name, e) + ".";
}

std::string jump(Namer& name, const Event& e) {
    const std::string top = name(e.top, "top");
    return std::string(sideName(e.side)) + " (" + top +
           ") is a top whose jump pointer is set: the water has come round from the far side, "
           "so the chain jumps to the other bank at " +
           name(e.jumpTarget, "jump pointer") + " and the two gorges become one.";
}

std::string fill(Namer& name, const Event& e) {
    // "meet at vertex 7", as a Bridge says it: "the same vertex (vertex 7)" read aloud
    // repeats the word.
    std::string s =
        "NextLeft and NextRight meet at " + name(e.before.nextLeft, "NextLeft = NextRight before");
    if (e.didTest(Test::SagInside)) s += " and no sag hangs below it";
    return s + ": the gorge is filled to its ceiling by a fan from it" + name.cutting(e, "") +
           "; " + nextGorge(name, e) + ".";
}

std::string forbidden(Namer& name, const Event& e) {
    std::string what;
    auto at = [&] { return name(e.culprit, "culprit"); };
    switch (e.reason) {
        case Forbidden::StartNotBottom:
            what = "The lowest vertex of the outer loop (" + at() +
                   "), where Left and Right start, is not a convex bottom";
            break;
        case Forbidden::CeilingAsEnd:
            what = std::string(sideName(e.side)) + " (" + at() +
                   ") is the highest point of its bank but convex: a ceiling, not a top";
            break;
        case Forbidden::JumpWrongSide:
            what = std::string(sideName(e.side)) + " (" + at() +
                   ") is a top with a jump pointer, but its held gorge waits on the bank the "
                   "water came from";
            break;
        case Forbidden::SpillNoBottom:
            what = "The water spills over the top " + at() + " but finds no gorge to flood";
            break;
        case Forbidden::NotFinite:
            what = "A coordinate of " + at() +
                   " is not a finite number, so no height can be "
                   "compared";
            break;
        case Forbidden::ShortLoop:
            what = "A ring with fewer than three vertices bounds no area and cannot be flooded";
            break;
        case Forbidden::BadTriangle: {
            std::string first = at();  // named in the order the sentence says them
            what = "The triangle at " + first + " and " + name(e.culprit2, "culprit") +
                   " would be inverted or flat";
            break;
        }
        case Forbidden::FillOpen:
            what = "The fingers meet at " + at() + " but the gorge does not close";
            break;
        case Forbidden::LeftBehind:
            what = "Nothing is left to flood, yet the water never reached " + at();
            break;
        case Forbidden::NoProgress: what = "The machine ran out of steps"; break;
        default: what = "The machine stopped"; break;
    }
    return what + ": forbidden (" + forbiddenName(e.reason) + "), " + forbiddenText(e.reason) + ".";
}

std::string sentence(Namer& name, const Event& e) {
    switch (e.action) {
        case Action::Start: {
            std::string s = "The water starts at bottom " + name(e.bottom, "bottom") +
                            ", the lowest vertex of the outer loop";
            if (name.holes()) s += " of part " + std::to_string(e.part);
            return s + ": Left and Right are both this vertex.";
        }
        case Action::Raise: return raise(name, e);
        case Action::Bridge: return bridge(name, e);
        case Action::Spill: return spill(name, e);
        case Action::Jump: return jump(name, e);
        case Action::Fill: return fill(name, e);
        case Action::Forbidden: return forbidden(name, e);
        case Action::Count: break;
    }
    return "?";
}

}  // namespace

Narration narration(const Polygon& polygon, const Event& e) {
    Narration n;
    Namer name(polygon, n);
    n.text = sentence(name, e);
    return n;
}

std::string narrate(const Polygon& polygon, const Event& e) { return narration(polygon, e).text; }

}  // namespace flood
