// Threads lent to the core's reading (flood/io/io.h, TaskRunner): the core starts none itself.
#pragma once
#include "flood/io/io.h"

namespace flood::cli {

// Runs the tasks on `threads` threads, this one and threads - 1 started for the call, each
// taking the next task left; the first exception a task throws is thrown again once all have
// stopped. One thread: no runner (the reader's serial path).
TaskRunner threadRunner(unsigned threads);

// The cores this process may run on (taskset, cgroups' cpusets), at least 1: the default of
// every -j. std::thread::hardware_concurrency() counts the machine's.
unsigned availableCores();

}  // namespace flood::cli
