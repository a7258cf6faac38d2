// flood: the command-line program (docs/CLI.md); the commands themselves are cli::run().
#include "flood/io/output.h"
#include "run.h"

int main(int argc, char** argv) { return flood::finishStdout(flood::cli::run(argc, argv)); }
