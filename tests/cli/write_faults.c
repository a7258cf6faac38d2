/* Write faults for the tests (tests/cli/write_faults_test.cpp), in the spirit of SQLite's fault
 * injection: an LD_PRELOAD library that lets a process write FLOOD_FAULT_BYTES bytes to regular
 * files and then fails the way a full disk does. Only writes to regular files count and fail
 * (stderr and pipes pass), through every door the writers use: write, pwrite, pwrite64 (Flood's
 * own output, SQLite under GeoPackage) and fwrite, fputs, fputc (GDAL's files, FlatGeobuf).
 *
 *   FLOOD_FAULT_BYTES=N   the budget; unset: nothing fails, the bytes are only counted
 *   FLOOD_FAULT=enospc    (default) the write that crosses N writes up to N and returns that
 *                         short count; every later one fails with ENOSPC. Streams as stdio
 *                         does: a buffer's worth (4096 bytes) past N is taken and lost without
 *                         an error, then fwrite fails; a stream that lost data fails its
 *                         fflush and fclose, the only sign of a loss in its last buffer
 *   FLOOD_FAULT=short     past N, each write(2)/pwrite(2) writes half of what it is given (at
 *                         least a byte) and says so, without an error: a writer must loop
 *   FLOOD_FAULT_REPORT=F  at exit, the bytes written to regular files are appended to F
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static int configured, limited, shortMode;
static unsigned long long budget, written;
static FILE* failed[64];           /* streams that lost data: their fflush and fclose fail */
static unsigned long long dropped; /* stream bytes taken as if buffered, never written */
#define BUFFERED 4096ull
static int failedCount;

#define REAL(name) ((__typeof__(&name))dlsym(RTLD_NEXT, #name))

static void report(void) {
    const char* to = getenv("FLOOD_FAULT_REPORT");
    if (!to) return;
    FILE* (*open)(const char*, const char*) = REAL(fopen);
    FILE* f = open(to, "a");
    if (!f) return;
    char line[32];
    int n = snprintf(line, sizeof line, "%llu\n", written);
    REAL(fwrite)(line, 1, (size_t)n, f);
    REAL(fclose)(f);
}

__attribute__((constructor)) static void configure(void) {
    if (configured) return;
    configured = 1;
    const char* n = getenv("FLOOD_FAULT_BYTES");
    const char* mode = getenv("FLOOD_FAULT");
    limited = n && *n;
    budget = limited ? strtoull(n, NULL, 10) : 0;
    shortMode = mode && strcmp(mode, "short") == 0;
    atexit(report);
}

static int regular(int fd) {
    struct stat st;
    return fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
}

/* How many of `n` bytes to a regular file may be written now; -1: none, errno is ENOSPC. */
static long long allowed(size_t n) {
    pthread_mutex_lock(&lock);
    long long k = (long long)n;
    if (limited && written + n > budget) {
        if (shortMode)
            k = written >= budget ? (n > 1 ? (long long)n / 2 : (long long)n)
                                  : (long long)(budget - written);
        else k = written >= budget ? -1 : (long long)(budget - written);
    }
    pthread_mutex_unlock(&lock);
    if (k < 0) errno = ENOSPC;
    return k;
}

static void count(long long k) {
    if (k <= 0) return;
    pthread_mutex_lock(&lock);
    written += (unsigned long long)k;
    pthread_mutex_unlock(&lock);
}

static void markFailed(FILE* f) {
    pthread_mutex_lock(&lock);
    if (failedCount < (int)(sizeof failed / sizeof failed[0])) failed[failedCount++] = f;
    pthread_mutex_unlock(&lock);
}

/* Whether `f` lost data; `forget`: it is being closed. */
static int lostData(FILE* f, int forget) {
    int found = 0;
    pthread_mutex_lock(&lock);
    for (int i = 0; i < failedCount; ++i)
        if (failed[i] == f) {
            found = 1;
            if (forget) failed[i] = failed[--failedCount];
            break;
        }
    pthread_mutex_unlock(&lock);
    return found;
}

/* The three doors to a file descriptor differ only in the offset they take. */
enum Door { WRITE, PWRITE, PWRITE64 };

static ssize_t realWrite(enum Door door, int fd, const void* buf, size_t n, off64_t at) {
    switch (door) {
        case WRITE: return REAL(write)(fd, buf, n);
        case PWRITE: return REAL(pwrite)(fd, buf, n, (off_t)at);
        default: return REAL(pwrite64)(fd, buf, n, at);
    }
}

static ssize_t faultyWrite(enum Door door, int fd, const void* buf, size_t n, off64_t at) {
    if (!regular(fd)) return realWrite(door, fd, buf, n, at);
    long long k = allowed(n);
    if (k < 0) return -1;
    ssize_t r = realWrite(door, fd, buf, (size_t)k, at);
    count(r);
    return r;
}

ssize_t write(int fd, const void* buf, size_t n) { return faultyWrite(WRITE, fd, buf, n, 0); }

ssize_t pwrite(int fd, const void* buf, size_t n, off_t at) {
    return faultyWrite(PWRITE, fd, buf, n, at);
}

ssize_t pwrite64(int fd, const void* buf, size_t n, off64_t at) {
    return faultyWrite(PWRITE64, fd, buf, n, at);
}

/* Streams: a short count is an error (C11 7.21.8.2), so `short` mode leaves them alone. */
static int streamFaults(FILE* f) {
    pthread_mutex_lock(&lock);
    int on = limited && !shortMode;
    pthread_mutex_unlock(&lock);
    return on && regular(fileno(f));
}

size_t fwrite(const void* buf, size_t size, size_t items, FILE* f) {
    if (!streamFaults(f) || size == 0) {
        size_t r = REAL(fwrite)(buf, size, items, f);
        if (regular(fileno(f))) count((long long)(r * size));
        return r;
    }
    const size_t n = size * items;
    long long k = allowed(n);
    size_t w = k > 0 ? REAL(fwrite)(buf, 1, (size_t)k, f) : 0;
    count((long long)w);
    if (w == n) return items;
    /* The rest is lost; up to a buffer's worth of it is taken as stdio would take it. */
    markFailed(f);
    pthread_mutex_lock(&lock);
    size_t taken = n - w < BUFFERED - dropped ? n - w : (size_t)(BUFFERED - dropped);
    dropped += taken;
    pthread_mutex_unlock(&lock);
    if (w + taken < n) errno = ENOSPC;
    return (w + taken) / size;
}

int fputs(const char* s, FILE* f) {
    size_t n = strlen(s);
    return fwrite(s, 1, n, f) == n ? 1 : EOF;
}

int fputc(int c, FILE* f) {
    unsigned char b = (unsigned char)c;
    return fwrite(&b, 1, 1, f) == 1 ? c : EOF;
}

int fflush(FILE* f) {
    int r = REAL(fflush)(f);
    if (f && lostData(f, 0)) {
        errno = ENOSPC;
        return EOF;
    }
    return r;
}

int fclose(FILE* f) {
    const int lost = lostData(f, 1);
    int r = REAL(fclose)(f);
    if (lost) {
        errno = ENOSPC;
        return EOF;
    }
    return r;
}
