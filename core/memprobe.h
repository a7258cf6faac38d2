// TEMPORARY (not to be committed): resident size probes.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <cstring>
namespace flood {
inline void memProbe(const char* what) {
    static const bool on = std::getenv("FLOOD_MEMPROBE") != nullptr;
    if (!on) return;
    FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return;
    char line[256];
    long rss = 0, hwm = 0;
    while (std::fgets(line, sizeof line, f)) {
        if (!std::strncmp(line, "VmRSS:", 6)) rss = std::atol(line + 6);
        if (!std::strncmp(line, "VmHWM:", 6)) hwm = std::atol(line + 6);
    }
    std::fclose(f);
    std::fprintf(stderr, "probe %-28s rss %8ld hwm %8ld\n", what, rss, hwm);
}
}  // namespace flood
