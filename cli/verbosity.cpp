// -q and -v (verbosity.h).
#include "verbosity.h"

#include <cstdio>
#include <iostream>

namespace flood::cli {

Verbosity verbosity = Verbosity::Normal;

namespace {
// A stream without a buffer: writes to it set badbit and go nowhere.
std::ostream& sink() {
    thread_local std::ostream none(nullptr);
    none.clear();
    return none;
}
}  // namespace

std::ostream& warning() {
    if (verbosity == Verbosity::Quiet) return sink();
    return std::cerr << "warning: ";
}

std::ostream& note() { return verbosity == Verbosity::Quiet ? sink() : std::cerr; }

std::ostream& detail() { return verbosity == Verbosity::Verbose ? std::cerr : sink(); }

std::string timeText(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f s", seconds);
    return text;
}

double Stopwatch::lap() {
    auto now = std::chrono::steady_clock::now();
    double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
}

}  // namespace flood::cli
