// The `flood` command as a function: what cli/flood.cpp's main() runs, and what the Python
// module runs for `python -m flood` and its `flood` console script, so both doors are one
// command. It takes over std::cout (flood/io/output.h); the caller ends with finishStdout().
#pragma once

namespace flood::cli {

// Parses argv (argv[0] names the program in usage messages) and runs the command; returns the
// exit code of docs/ERRORS.md.
int run(int argc, char** argv);

}  // namespace flood::cli
