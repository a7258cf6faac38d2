// What went wrong, and the process exit code that says so (docs/ERRORS.md lists them).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace flood {

enum class Status : int {
    Ok = 0,
    Usage = 2,         // bad command line
    Malformed = 3,     // unreadable file, syntax error, wrong structure
    Invalid = 4,       // the polygon breaks a validity rule (self-intersection, hole outside, ...)
    Forbidden = 5,     // the flood machine hit a forbidden state or transition (§6)
    Internal = 6,      // a bug: the exact checker rejected our own output, or an exception
    VerifyFailed = 7,  // `flood verify`: the result failed a verification
    WriteFailed = 8    // an output (file or stdout) could not be written; nothing half-written kept
};

const char* statusName(Status s);

// What a diagnostic blames, as data, so tools (the viewer's error view) never parse the
// message. Indices are global vertex indices of the polygon; an edge is named by its first
// vertex (the edge runs to the next vertex of its ring).
struct Culprits {
    std::vector<uint32_t> vertices;
    std::vector<uint32_t> rings;
    std::vector<uint32_t> edges;
    std::vector<uint32_t> triangles;  // indices into the triangle list (checker rejections)
    // Where the trouble is, when it is a point the diagnostic knows exactly (a shared vertex,
    // a vertex on an edge). Two crossing edges have no exact double point: their `edges`
    // are given and a display point is computed from them.
    bool hasPoint = false;
    double x = 0, y = 0;
    bool empty() const {
        return vertices.empty() && rings.empty() && edges.empty() && triangles.empty() && !hasPoint;
    }
};

struct Diagnostic {
    Status status = Status::Ok;
    std::string message;  // one line: "FILE: ring R vertex V (x, y): what is wrong"
    Culprits culprits;
    Diagnostic() = default;
    // Not an aggregate, so the many {status, message} diagnostics need no culprits spelled out.
    Diagnostic(Status s, std::string m, Culprits c = {})
        : status(s), message(std::move(m)), culprits(std::move(c)) {}
    // Out of line (status.cpp): clang 14 left the implicit destructor undefined in the machine's
    // templated code (core/machine/flood.cpp) of the fuzz build, so one definition is given here.
    ~Diagnostic();
    Diagnostic(const Diagnostic&) = default;
    Diagnostic(Diagnostic&&) = default;
    Diagnostic& operator=(const Diagnostic&) = default;
    Diagnostic& operator=(Diagnostic&&) = default;
    bool ok() const { return status == Status::Ok; }
};

}  // namespace flood
