// What went wrong, and the process exit code that says so (docs/ERRORS.md lists them).
#pragma once
#include <string>

namespace flood {

enum class Status : int {
    Ok = 0,
    Usage = 2,        // bad command line
    Malformed = 3,    // unreadable file, syntax error, wrong structure
    Invalid = 4,      // the polygon breaks a validity rule (self-intersection, hole outside, ...)
    Forbidden = 5,    // the flood machine hit a forbidden state or transition (§6)
    Internal = 6,     // a bug: the exact checker rejected our own output, or an exception
    VerifyFailed = 7, // `flood verify`: the result failed a verification
    WriteFailed = 8   // an output (file or stdout) could not be written; nothing half-written kept
};

const char* statusName(Status s);

struct Diagnostic {
    Status status = Status::Ok;
    std::string message;  // one line: "FILE: ring R vertex V (x, y): what is wrong"
    bool ok() const { return status == Status::Ok; }
};

}  // namespace flood
