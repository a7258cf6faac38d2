// Outputs that are written completely or not at all, and the standard output checked at exit
// (docs/ERRORS.md, exit 8 "write-failed").
#pragma once
#include <sys/stat.h>

#include <memory>
#include <ostream>
#include <string>

#include "flood/geometry/status.h"

namespace flood {

// Where a write to `path` lands: `path` itself or, when it is a symbolic link to a regular file
// (or to nothing), the file at the end of its links (a dangling link's target is created, as
// the shell's `>` does). Writers replace `file` and never the link: a temporary in the folder
// of `file`, renamed over it. A link to anything else (a device, a FIFO, /dev/stdout's) is
// `path` itself, with `st` what the kernel finds at its end.
struct OutputTarget {
    std::string file;     // the name to write
    int error = 0;        // ELOOP, or what lstat or readlink said (ENOENT is a new file)
    bool exists = false;  // `st` holds what `file` is
    struct stat st = {};
    bool regular() const { return exists && S_ISREG(st.st_mode); }
    bool directory() const { return exists && S_ISDIR(st.st_mode); }
    // "a character device", "a FIFO", ... for messages about a file that is not regular.
    const char* kind() const;
};
OutputTarget outputTarget(const std::string& path);

// The hidden temporary name beside `file`: "DIR/.NAME.XXXXXX" (for mkstemp, mkdtemp).
std::string temporaryPattern(const std::string& file);

// Gives a temporary (`fd`, or `path` when fd < 0) what the file it replaces has: its
// permissions (0600 stays 0600) and, where allowed, its owner and group; a new file gets
// 0666 less the umask. Returns 0 or the errno of a failed chmod.
int adoptPermissions(int fd, const std::string& path, const OutputTarget& target);

// Temporary files and folders that must not outlive the program: a SIGINT, SIGTERM or SIGHUP
// removes them (files first, then folders; async-signal-safe: unlink and rmdir of names kept
// in static buffers), then the signal is handled as before (the default: the program ends by
// it). The handler is put in front at each new temporary, for each signal not ignored; the
// program's own handler is called after ours. A forked child never removes its parent's
// temporaries.
class RemovedOnSignal {
public:
    RemovedOnSignal() = default;
    ~RemovedOnSignal() { forget(); }  // forgets the names (removes nothing)
    RemovedOnSignal(const RemovedOnSignal&) = delete;
    RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;
    RemovedOnSignal& operator=(RemovedOnSignal&& other) noexcept;  // takes over its names
    // mkstemp / mkdtemp of `pattern` ("...XXXXXX", replaced by the name made), recorded here
    // with the signals blocked, so no signal comes between the making and the recording.
    // -1 (false) with errno set when it could not be made.
    int makeFile(std::string& pattern);
    bool makeFolder(std::string& pattern);
    void add(const std::string& path, bool folder = false);  // a name to remove, made or not
    void forget();

private:
    int slots_[8] = {};
    int count_ = 0;
};

// One output of a command: `path`, or stdout for "-". A regular file (existing or new) is
// written to a temporary file beside it (same directory, so the rename cannot cross file
// systems) and renamed over `path` only once every write and the close succeeded: a full disk
// or a file-size limit leaves the old file as it was. The file replaced keeps its permissions;
// through a symbolic link its target is written, the link stays. A path that exists and is
// no regular file (/dev/null, a pipe, a terminal) is written in place: renaming over it would
// replace it. With IfExists::Fail an existing `path` (any kind, a link too) is never touched:
// commit() fails with EEXIST (error()), atomically, so a caller can try another name.
class Output {
public:
    enum class IfExists { Replace, Fail };
    explicit Output(std::string path, IfExists ifExists = IfExists::Replace);
    ~Output();  // removes the temporary file of an output that was not committed
    Output(const Output&) = delete;
    Output& operator=(const Output&) = delete;

    std::ostream& stream();
    // True when this output goes to a temporary file that commit() renames into place: what
    // is written may still be discarded unseen (by not committing), so it can be written
    // before it is known to be wanted. False for stdout and outputs written in place.
    bool discardable() const;
    // Whether Output(path) would be discardable, asked before opening it (a pipe is not
    // opened until it is wanted: opening blocks until a reader comes).
    static bool discardable(const std::string& path);
    // Flushes, closes and renames. On failure prints "error: PATH: cannot write: REASON"
    // (the system's reason), removes the temporary and returns WriteFailed. With `message`
    // the line goes there instead of stderr (the viewer shows it in its status line).
    Status commit(std::string* message = nullptr);
    // The errno of the failure, 0 when none yet: what the constructor met (EEXIST when
    // IfExists::Fail finds the name taken) is known at once, the rest once commit() failed.
    int error() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// True when both name the same existing file (device and inode: "a.json", "./a.json" and a
// symlink to it are one file); "-" is the file on stdin or stdout.
bool sameFile(const std::string& input, const std::string& output);

// Routes std::cout through a buffer that keeps the reason of a failed write; call first.
void takeOverStdout();

// Flushes std::cout and stdout; if anything written there was lost, prints "error: cannot
// write standard output: REASON" and returns `code`, or WriteFailed when `code` was 0.
int finishStdout(int code);

}  // namespace flood
