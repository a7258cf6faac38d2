#include "flood/teach/quiz.h"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "flood/teach/decision_tree.h"
#include "flood/teach/narrate.h"

namespace flood {

QuizActions QuizActions::all() {
    QuizActions q;
    for (Action a : kQuizChoices) q.set(a, true);
    return q;
}

void QuizActions::set(Action a, bool on) {
    const uint8_t bit = uint8_t(1u << int(a));
    bits = on ? uint8_t(bits | bit) : uint8_t(bits & ~bit);
}

namespace {
std::string lower(std::string s) {
    for (char& ch : s) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return s;
}
}  // namespace

bool parseQuizActions(const std::string& text, QuizActions& out, std::string& error) {
    QuizActions q;
    std::stringstream in(text);
    for (std::string word; std::getline(in, word, ',');) {
        word.erase(0, word.find_first_not_of(" \t"));
        word.erase(word.find_last_not_of(" \t") + 1);
        if (lower(word) == "all") {
            q = QuizActions::all();
            continue;
        }
        bool found = false;
        for (Action a : kQuizChoices)
            if (lower(word) == lower(actionName(a))) q.set(a, found = true);
        if (!found) {
            error = "'" + word +
                    "' is not an action to ask about (raise, bridge, spill, jump, fill or all)";
            return false;
        }
    }
    if (q.empty()) {
        error = "no action to ask about (raise, bridge, spill, jump, fill or all)";
        return false;
    }
    out = q;
    return true;
}

std::string quizActionsText(QuizActions asked) {
    std::string s;
    for (Action a : kQuizChoices)
        if (asked.has(a)) s += (s.empty() ? "" : ", ") + lower(actionName(a));
    return s;
}

Action quizChoiceOfKey(char key) {
    if (key >= '1' && key <= '5') return kQuizChoices[size_t(key - '1')];
    for (Action a : kQuizChoices)
        if (std::tolower(static_cast<unsigned char>(key)) == lower(actionName(a))[0]) return a;
    return Action::Count;
}

std::vector<uint32_t> quizQuestions(const std::vector<Event>& events, QuizActions asked) {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < events.size(); ++i)
        if (events[i].action != Action::Start && events[i].action != Action::Forbidden &&
            asked.has(events[i].action))
            out.push_back(i);
    return out;
}

std::string quizPrompt(const Polygon& polygon, const std::vector<Event>& events, uint32_t i,
                       const std::vector<VertexClass>& classes) {
    const Event& e = events[i];
    auto vertex = [&](Index v) {
        std::string s = "vertex " + std::to_string(v);
        if (v < classes.size()) s += std::string(" (") + vertexClassName(classes[v]) + ")";
        return s;
    };
    const Fingers& f = e.before;
    std::ostringstream os;
    os << "Before step " << i + 1 << ": ";
    if (f.nextLeft != kNone && f.nextLeft == f.nextRight)
        os << "NextLeft and NextRight are the same vertex, " << vertex(f.nextLeft);
    else os << "NextLeft is " << vertex(f.nextLeft) << ", NextRight " << vertex(f.nextRight);
    os << "; Left is " << vertex(f.left) << ", Right " << vertex(f.right) << ".";
    // Which finger is lower is geometry the student reads off the picture; in words, say it.
    if (e.didTest(Test::LeftLower))
        os << (e.testResult(Test::LeftLower) ? " NextLeft is lower than NextRight."
                                             : " NextRight is lower than NextLeft.");
    // What the steps before left behind in this part: the water, held tops, unbridged sags.
    std::vector<std::pair<Index, Index>> held;  // top, the bank its jump pointer leads to
    std::vector<Index> bridged;
    Index water = kNone;
    for (uint32_t j = 0; j < i; ++j) {
        const Event& b = events[j];
        if (b.part != e.part) continue;
        water = b.water;
        if (b.action == Action::Spill) held.emplace_back(b.top, b.jumpTarget);
        if (b.action == Action::Jump)
            held.erase(std::remove_if(held.begin(), held.end(),
                                      [&](const auto& h) { return h.first == b.top; }),
                       held.end());
        if (b.action == Action::Bridge) bridged.push_back(b.sag);
    }
    if (water != kNone) os << " The water is at vertex " << water << ".";
    if (!held.empty()) {
        os << " Held at a top (a jump pointer set by a spill):";
        for (size_t h = 0; h < held.size(); ++h)
            os << (h ? "," : "") << " vertex " << held[h].first << " (to vertex " << held[h].second
               << ")";
        os << ".";
    }
    if (e.part < polygon.parts.size()) {
        const Part& p = polygon.parts[e.part];
        const Ring& last = polygon.rings[p.firstRing + p.ringCount - 1];
        std::vector<Index> sags;
        for (Index v = polygon.rings[p.firstRing].first; v < last.first + last.count; ++v)
            if (v < classes.size() && classes[v] == VertexClass::Sag &&
                std::find(bridged.begin(), bridged.end(), v) == bridged.end())
                sags.push_back(v);
        constexpr size_t kListed = 10;
        if (!sags.empty()) {
            os << " Sags not bridged yet:";
            for (size_t s = 0; s < std::min(sags.size(), kListed); ++s)
                os << (s ? ", " : " ") << sags[s];
            if (sags.size() > kListed) os << " and " << sags.size() - kListed << " more";
            os << ".";
        }
    }
    os << " Which action comes next: raise, bridge, spill, jump or fill?";
    return os.str();
}

std::vector<QuizPredicate> decidingPredicates(const Event& e) {
    std::vector<QuizPredicate> out;
    const DecisionTree& t = decisionTree();
    for (const PathStep& s : decisionPath(e).steps) {
        const DecisionNode& n = t.nodes[size_t(s.node)];
        if (n.kind == DecisionNode::Kind::Test && s.ran) out.push_back({n.test, s.answer});
    }
    return out;
}

std::string quizAnswer(const Polygon& polygon, const Event& e) {
    std::string s = std::string(actionName(e.action)) + ". Decided by: ";
    const std::vector<QuizPredicate> tests = decidingPredicates(e);
    for (size_t k = 0; k < tests.size(); ++k)
        s += std::string(k ? "; " : "") + testText(tests[k].test) + "? " +
             (tests[k].answer ? "yes" : "no");
    return s + ". " + narrate(polygon, e);
}

std::string quizQuestionsText(const Polygon& polygon, const std::vector<Event>& events,
                              QuizActions asked, Up up) {
    const std::vector<VertexClass> classes = classifyVertices(polygon, up);
    const std::vector<uint32_t> questions = quizQuestions(events, asked);
    std::ostringstream os;
    os << "Predict the next action (" << quizActionsText(asked) << "): " << questions.size()
       << (questions.size() == 1 ? " question" : " questions") << "\n";
    for (size_t q = 0; q < questions.size(); ++q)
        os << q + 1 << ". " << quizPrompt(polygon, events, questions[q], classes) << "\n";
    return os.str();
}

std::string quizAnswersText(const Polygon& polygon, const std::vector<Event>& events,
                            QuizActions asked) {
    const std::vector<uint32_t> questions = quizQuestions(events, asked);
    std::ostringstream os;
    os << "Answers\n";
    for (size_t q = 0; q < questions.size(); ++q)
        os << q + 1 << ". step " << questions[q] + 1 << ": "
           << quizAnswer(polygon, events[questions[q]]) << "\n";
    return os.str();
}

QuizSession::QuizSession(const std::vector<Event>& events, QuizActions asked)
    : asked_(asked), questions_(quizQuestions(events, asked)) {
    for (uint32_t i : questions_) truth_.push_back(events[i].action);
    given_.assign(questions_.size(), Action::Count);
}

int QuizSession::questionOf(uint32_t i) const {
    auto it = std::lower_bound(questions_.begin(), questions_.end(), i);
    return it != questions_.end() && *it == i ? int(it - questions_.begin()) : -1;
}

bool QuizSession::answer(size_t q, Action choice) {
    if (q >= size() || answered(q) ||
        std::find(kQuizChoices.begin(), kQuizChoices.end(), choice) == kQuizChoices.end())
        return false;
    given_[q] = choice;
    return true;
}

size_t QuizSession::answeredCount() const {
    return size_t(
        std::count_if(given_.begin(), given_.end(), [](Action a) { return a != Action::Count; }));
}

size_t QuizSession::score() const {
    size_t n = 0;
    for (size_t q = 0; q < size(); ++q) n += correct(q);
    return n;
}

}  // namespace flood
