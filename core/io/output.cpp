// Atomic output files and the checked standard output (output.h). POSIX calls throughout:
// each failure keeps its errno, so the message gives the system's reason.
#include "flood/io/output.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <mutex>
#include <streambuf>
#include <vector>

namespace flood {
namespace {

// A stream buffer over a file descriptor that remembers the errno of the first failed write;
// after it, every write fails at once.
class FdBuf : public std::streambuf {
public:
    explicit FdBuf(int fd) : fd_(fd), buf_(1 << 16) {
        setp(buf_.data(), buf_.data() + buf_.size());
    }
    int error() const { return error_; }
    void fail(int error) {
        if (!error_) error_ = error;
    }
    bool drain() {
        const char* p = pbase();
        while (!error_ && p < pptr()) {
            ssize_t k = ::write(fd_, p, size_t(pptr() - p));
            if (k < 0 && errno == EINTR) continue;
            if (k < 0) fail(errno);
            else p += k;
        }
        setp(buf_.data(), buf_.data() + buf_.size());
        return !error_;
    }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    int sync() override { return drain() ? 0 : -1; }

public:
    bool reported = false;  // the failure was already printed (by Output::commit)

private:
    int fd_;
    int error_ = 0;
    std::vector<char> buf_;
};

// Everything the program prints on stdout goes through std::cout into this buffer (see
// takeOverStdout), so a lost write keeps its reason.
// Never destroyed: std::cout is flushed after static destructors run.
FdBuf& stdoutBuf() {
    static FdBuf* buf = new FdBuf(STDOUT_FILENO);
    return *buf;
}

bool statOf(const std::string& path, int stdFd, struct stat& st) {
    return path == "-" ? ::fstat(stdFd, &st) == 0 : ::stat(path.c_str(), &st) == 0;
}

// --- Temporaries removed on a signal ---------------------------------------------------------
// Fixed slots, so the handler reads nothing but static memory: a slot is claimed (Claimed),
// its name copied, then published (File or Folder); the handler skips every other state.
enum SlotState : int { Free, Claimed, File, Folder };
struct Slot {
    std::atomic<int> state{Free};
    pid_t pid = 0;  // the process that made the temporary
    char path[PATH_MAX];
};
constexpr int kSlots = 32;
Slot slots[kSlots];
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kSignalCount = int(sizeof kSignals / sizeof kSignals[0]);
struct sigaction previous[kSignalCount];

// Whether the handler of each signal is running: a chain that leads back to it (two copies of
// this code, the program's and a module's, each installed over the other) ends there.
volatile sig_atomic_t running[kSignalCount];

void removeTemporaries(int sig, siginfo_t* info, void* context) {
    const int saved = errno;
    const pid_t self = ::getpid();
    for (int state : {int(File), int(Folder)})
        for (Slot& s : slots)
            if (s.state.load() == state && s.pid == self) {
                if (state == File) ::unlink(s.path);
                else ::rmdir(s.path);
            }
    int k = 0;
    while (k < kSignalCount && kSignals[k] != sig) ++k;
    if (k < kSignalCount) {
        const bool again = running[k];
        running[k] = 1;
        const struct sigaction& p = previous[k];
        const bool info3 = p.sa_flags & SA_SIGINFO;
        if (!again && info3 && p.sa_sigaction) {
            p.sa_sigaction(sig, info, context);
        } else if (!again && !info3 && p.sa_handler != SIG_DFL && p.sa_handler != SIG_IGN) {
            p.sa_handler(sig);
        } else if (again || (!info3 && p.sa_handler == SIG_DFL)) {
            // As if we had never been here: the default action, once this handler returns.
            struct sigaction dfl = {};
            dfl.sa_handler = SIG_DFL;
            ::sigemptyset(&dfl.sa_mask);
            ::sigaction(sig, &dfl, nullptr);
            ::raise(sig);
        }
        running[k] = 0;
    }
    errno = saved;
}

// Puts our handler in front of each signal's current one (unless ignored, or ours already):
// at every new temporary, so a handler installed since is kept too, called after ours.
void installHandlers() {
    static std::mutex m;
    std::lock_guard<std::mutex> lock(m);
    for (int k = 0; k < kSignalCount; ++k) {
        struct sigaction current;
        if (::sigaction(kSignals[k], nullptr, &current) != 0) continue;
        const bool info3 = current.sa_flags & SA_SIGINFO;
        if (info3 && current.sa_sigaction == removeTemporaries) continue;
        if (!info3 && current.sa_handler == SIG_IGN) continue;  // ignored (nohup): stays so
        previous[k] = current;
        struct sigaction ours = {};
        ours.sa_sigaction = removeTemporaries;
        ours.sa_flags = SA_SIGINFO | SA_RESTART;
        ::sigemptyset(&ours.sa_mask);
        ::sigaction(kSignals[k], &ours, nullptr);
    }
}

// The signals above blocked in this thread while it lives: a temporary made and recorded
// under it is never seen by the handler half-made (the signal waits until both are done).
class SignalsBlocked {
public:
    SignalsBlocked() {
        sigset_t set;
        ::sigemptyset(&set);
        for (int s : kSignals) ::sigaddset(&set, s);
        ::pthread_sigmask(SIG_BLOCK, &set, &old_);
    }
    ~SignalsBlocked() { ::pthread_sigmask(SIG_SETMASK, &old_, nullptr); }

private:
    sigset_t old_;
};

}  // namespace

int RemovedOnSignal::makeFile(std::string& pattern) {
    SignalsBlocked blocked;
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    int fd = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd < 0) return -1;
    pattern = name.data();
    add(pattern);
    return fd;
}

bool RemovedOnSignal::makeFolder(std::string& pattern) {
    SignalsBlocked blocked;
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (!::mkdtemp(name.data())) return false;
    pattern = name.data();
    add(pattern, true);
    return true;
}

void RemovedOnSignal::add(const std::string& path, bool folder) {
    if (count_ == int(sizeof slots_ / sizeof slots_[0]) || path.size() >= PATH_MAX) return;
    installHandlers();
    for (int k = 0; k < kSlots; ++k) {
        int expected = Free;
        if (!slots[k].state.compare_exchange_strong(expected, Claimed)) continue;
        std::memcpy(slots[k].path, path.c_str(), path.size() + 1);
        slots[k].pid = ::getpid();
        slots[k].state.store(folder ? Folder : File);
        slots_[count_++] = k;
        return;
    }
}

RemovedOnSignal& RemovedOnSignal::operator=(RemovedOnSignal&& other) noexcept {
    forget();
    std::copy(other.slots_, other.slots_ + other.count_, slots_);
    count_ = other.count_;
    other.count_ = 0;
    return *this;
}

void RemovedOnSignal::forget() {
    for (int i = 0; i < count_; ++i) slots[slots_[i]].state.store(Free);
    count_ = 0;
}

const char* OutputTarget::kind() const {
    if (!exists) return "a missing file";
    switch (st.st_mode & S_IFMT) {
        case S_IFREG: return "a regular file";
        case S_IFDIR: return "a directory";
        case S_IFCHR: return "a character device";
        case S_IFBLK: return "a block device";
        case S_IFIFO: return "a FIFO";
        case S_IFSOCK: return "a socket";
    }
    return "not a regular file";
}

OutputTarget outputTarget(const std::string& path) {
    OutputTarget t;
    t.file = path;
    // What the kernel finds at the end of the links first: a device, a FIFO or a directory is
    // named by `path` itself (written in place or refused), which also keeps /proc's links
    // (/dev/stdout -> /proc/self/fd/1 -> "pipe:[...]") working, whose text names no file.
    if (::stat(path.c_str(), &t.st) == 0 && !S_ISREG(t.st.st_mode)) {
        t.exists = true;
        return t;
    }
    for (int links = 0;; ++links) {
        if (::lstat(t.file.c_str(), &t.st) != 0) {
            if (errno != ENOENT) t.error = errno;
            t.st = {};
            return t;
        }
        if (!S_ISLNK(t.st.st_mode)) {
            t.exists = true;
            return t;
        }
        if (links == 40) {  // as the kernel's limit on links followed
            t.error = ELOOP;
            return t;
        }
        std::vector<char> buf(size_t(t.st.st_size > 0 ? t.st.st_size : PATH_MAX) + 1);
        ssize_t n = ::readlink(t.file.c_str(), buf.data(), buf.size());
        if (n < 0 || size_t(n) >= buf.size()) {
            t.error = n < 0 ? errno : ENAMETOOLONG;
            return t;
        }
        std::string to(buf.data(), size_t(n));
        size_t slash = t.file.rfind('/');
        if (to[0] != '/' && slash != std::string::npos) to = t.file.substr(0, slash + 1) + to;
        t.file = to;
    }
}

// rename() that fails on an existing name: false with errno set.
static bool renameNoReplace(const std::string& from, const std::string& to) {
#ifdef RENAME_NOREPLACE
    return ::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0;
#else  // Emscripten's libc has no renameat2: as on a file system without RENAME_NOREPLACE
    (void)from, (void)to;
    errno = ENOSYS;
    return false;
#endif
}

std::string temporaryPattern(const std::string& file) {
    size_t slash = file.rfind('/');
    return slash == std::string::npos
               ? "." + file + ".XXXXXX"
               : file.substr(0, slash + 1) + "." + file.substr(slash + 1) + ".XXXXXX";
}

int adoptPermissions(int fd, const std::string& path, const OutputTarget& target) {
    mode_t mode;
    if (target.regular()) {
        // The owner first: chown clears the set-user-ID and set-group-ID bits. Only root
        // (or the owner, for a group of theirs) may; otherwise the writer owns the new file.
        if (target.st.st_uid != ::geteuid() || target.st.st_gid != ::getegid()) {
            int r = fd >= 0 ? ::fchown(fd, target.st.st_uid, target.st.st_gid)
                            : ::chown(path.c_str(), target.st.st_uid, target.st.st_gid);
            if (r != 0 && fd >= 0) (void)::fchown(fd, uid_t(-1), target.st.st_gid);
        }
        mode = target.st.st_mode & 07777;
    } else {
        mode_t mask = ::umask(0);
        ::umask(mask);
#ifdef __EMSCRIPTEN__
        // Emscripten starts every program with umask 0777 (nobody there sets one): outputs
        // would be mode 000, unreadable by the page or, under Node, by the user. A shell's
        // usual mask instead.
        mask = 022;
#endif
        mode = 0666 & ~mask;
    }
    int r = fd >= 0 ? ::fchmod(fd, mode) : ::chmod(path.c_str(), mode);
    return r == 0 ? 0 : errno;
}

struct Output::Impl {
    Impl(std::string path, std::string file, std::string temp, int fd, int error)
        : path(std::move(path)), file(std::move(file)), temp(std::move(temp)), fd(fd), buf(fd) {
        if (error) buf.fail(error);
    }
    std::string path;  // as given (messages name it)
    std::string file;  // what is replaced: `path`, or the end of its symbolic links
    std::string temp;  // empty when writing in place
    int fd;            // -1 for stdout: std::cout is written
    FdBuf buf;
    std::ostream out{&buf};
    bool done = false;
    bool noReplace = false;
    RemovedOnSignal guard;

    std::string label() const {
        return path == "-" ? "cannot write standard output" : path + ": cannot write";
    }
};

Output::Output(std::string path, IfExists ifExists) {
    int fd = -1, error = 0;
    std::string temp, file = path;
    struct stat st;
    RemovedOnSignal guard;
    const bool noReplace = ifExists == IfExists::Fail;
    OutputTarget target;
    if (path == "-") {
        // std::cout is the stream (stream()); fd stays -1.
    } else if (noReplace && ::lstat(path.c_str(), &st) == 0) {
        error = EEXIST;  // a name taken by anything, a link too: not ours to write
    } else if (target = outputTarget(path); target.error) {
        error = target.error;
    } else if (target.exists && !target.regular()) {
        file = target.file;
        if (target.directory()) error = EISDIR;
        else if ((fd = ::open(target.file.c_str(), O_WRONLY | O_CLOEXEC)) < 0) error = errno;
    } else {
        // A hidden name beside the file replaced: ".NAME.XXXXXX" in the same directory.
        file = target.file;
        temp = temporaryPattern(file);
        fd = guard.makeFile(temp);
        if (fd < 0) {
            error = errno;
            temp.clear();
        } else {
            error = adoptPermissions(fd, temp, target);
        }
    }
    impl_ = std::make_unique<Impl>(std::move(path), std::move(file), std::move(temp), fd, error);
    impl_->noReplace = noReplace;
    impl_->guard = std::move(guard);
}

Output::~Output() {
    Impl& o = *impl_;
    if (o.done) return;
    if (o.fd >= 0) ::close(o.fd);
    if (!o.temp.empty()) ::unlink(o.temp.c_str());
}

int Output::error() const { return impl_->buf.error(); }

bool Output::discardable() const { return !impl_->temp.empty(); }

bool Output::discardable(const std::string& path) {
    struct stat st;
    return path != "-" && (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode));
}

std::ostream& Output::stream() { return impl_->path == "-" ? std::cout : impl_->out; }

Status Output::commit(std::string* message) {
    Impl& o = *impl_;
    o.done = true;
    if (o.path == "-") {
        std::cout.flush();
        if (!stdoutBuf().error()) return Status::Ok;
        o.buf.fail(stdoutBuf().error());
        stdoutBuf().reported = true;
    }
    o.out.flush();
    o.buf.drain();
    if (o.fd >= 0 && ::close(o.fd) != 0) o.buf.fail(errno);
    if (!o.buf.error() && !o.temp.empty() && !o.noReplace &&
        ::rename(o.temp.c_str(), o.file.c_str()) != 0)
        o.buf.fail(errno);
    if (!o.buf.error() && !o.temp.empty() && o.noReplace && !renameNoReplace(o.temp, o.file)) {
        // A file system without RENAME_NOREPLACE: a hard link fails on an existing name too.
        const bool unsupported = errno == EINVAL || errno == ENOSYS;
        if (!unsupported || ::link(o.temp.c_str(), o.file.c_str()) != 0) o.buf.fail(errno);
        else ::unlink(o.temp.c_str());
    }
    if (!o.buf.error()) {
        o.guard.forget();
        return Status::Ok;
    }
    if (!o.temp.empty()) ::unlink(o.temp.c_str());
    o.guard.forget();
    std::string line = "error: " + o.label() + ": " + std::strerror(o.buf.error());
    if (message) *message = line;
    else std::cerr << line << "\n";
    return Status::WriteFailed;
}

bool sameFile(const std::string& input, const std::string& output) {
    struct stat a, b;
    return statOf(input, STDIN_FILENO, a) && statOf(output, STDOUT_FILENO, b) &&
           S_ISREG(a.st_mode) && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

void takeOverStdout() { std::cout.rdbuf(&stdoutBuf()); }

int finishStdout(int code) {
    std::cout.flush();
    FdBuf& buf = stdoutBuf();
    errno = 0;
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) buf.fail(errno ? errno : EIO);
    if (!buf.error()) return code;
    if (!buf.reported)
        std::cerr << "error: cannot write standard output: " << std::strerror(buf.error()) << "\n";
    return code != 0 ? code : int(Status::WriteFailed);
}

}  // namespace flood
