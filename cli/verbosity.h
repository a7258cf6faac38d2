// -q and -v, the same on every command of `flood`: what goes to stderr besides errors.
//   -q  errors only: no progress line, no warnings, notes or summaries on stderr.
//   -v  also detail: the time of each stage (read, validate, flood, check and write) and,
//       from `flood check`, a line per feature.
// stdout (the command's result) is the same at every level.
#pragma once
#include <chrono>
#include <iosfwd>
#include <string>

namespace flood::cli {

enum class Verbosity { Quiet, Normal, Verbose };
extern Verbosity verbosity;  // set by run() from -q/-v

// "warning: " on stderr, to be followed by the message and "\n"; a sink under -q.
std::ostream& warning();
// A note or summary on stderr (the stream itself, no prefix); a sink under -q.
std::ostream& note();
// -v's detail lines on stderr, "COMMAND: " in front; a sink unless -v.
std::ostream& detail();

// "0.012 s": a stage's time as -v prints it.
std::string timeText(double seconds);

// Seconds since the last lap (or since construction), for -v's stage timings.
class Stopwatch {
public:
    double lap();

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace flood::cli
