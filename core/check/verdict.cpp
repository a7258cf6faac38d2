// The one judge (flood/check/verdict.h).
#include "flood/check/verdict.h"

#include <utility>

namespace flood {

namespace {
struct VerdictRow {
    const char* word;
    Status status;
    const char* meaning;
};
// The FLOOD_VERDICTS table, one row per Verdict.
const VerdictRow kVerdicts[] = {
#define FLOOD_X(name, word, status, meaning) {word, Status::status, meaning},
    FLOOD_VERDICTS(FLOOD_X)
#undef FLOOD_X
};
}  // namespace

const char* verdictName(Verdict v) { return kVerdicts[int(v)].word; }
Status verdictStatus(Verdict v) { return kVerdicts[int(v)].status; }
const char* verdictMeaning(Verdict v) { return kVerdicts[int(v)].meaning; }

Verdict verdictOfRead(const Diagnostic& read) {
    if (read.ok()) return Verdict::Ok;
    return read.status == Status::Internal ? Verdict::Internal : Verdict::Malformed;
}

Judgement judgeRun(const Polygon& polygon, const std::vector<Triangle>& triangles,
                   const Diagnostic& run, const std::string& name, bool exactCheck,
                   const std::function<TriangleCheck()>& triangleCheck) {
    Judgement j;
    if (!run.ok()) {  // the machine stopped, or failed itself (an exception while flooding)
        j.verdict = run.status == Status::Forbidden ? Verdict::Forbidden : Verdict::Internal;
        j.diagnostic = run;
        return j;
    }
    if (!exactCheck) return j;
    j.check = checkTriangulation(polygon, triangles, triangleCheck);
    if (!j.check.ok) {
        j.verdict = Verdict::Checker;
        j.diagnostic = {Status::Internal,
                        name + ": the exact checker rejects the triangulation: " + j.check.reason,
                        j.check.culprits};
    }
    return j;
}

Judgement judge(Polygon& polygon, const std::string& name, const JudgeOptions& options) {
    if (options.validate)
        if (Diagnostic d = validate(polygon, name); !d.ok()) {
            Judgement j;
            j.verdict = Verdict::Invalid;
            j.diagnostic = std::move(d);
            return j;
        }
    FloodResult r = triangulate(polygon, nullptr, options.flood);
    Judgement j = judgeRun(polygon, r.triangles, r.diagnostic, name, options.exactCheck);
    if (j.verdict == Verdict::Forbidden) j.failure = r.failure;
    j.triangles = std::move(r.triangles);
    return j;
}

Judgement judge(ReadResult& read, const std::string& name, const JudgeOptions& options) {
    if (Verdict v = verdictOfRead(read.diagnostic); v != Verdict::Ok) {
        Judgement j;
        j.verdict = v;
        j.diagnostic = read.diagnostic;
        return j;
    }
    return judge(read.polygon, name, options);
}

}  // namespace flood
