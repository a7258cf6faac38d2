// Names of the exit statuses (docs/ERRORS.md).
#include "flood/geometry/status.h"

namespace flood {

const char* statusName(Status s) {
    switch (s) {
        case Status::Ok: return "ok";
        case Status::Usage: return "usage";
        case Status::Malformed: return "malformed";
        case Status::Invalid: return "invalid";
        case Status::Forbidden: return "forbidden";
        case Status::Internal: return "internal";
        case Status::VerifyFailed: return "verify-failed";
        case Status::WriteFailed: return "write-failed";
    }
    return "unknown";
}

Diagnostic::~Diagnostic() = default;

}  // namespace flood
