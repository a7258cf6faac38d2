// Atomic output files and the checked standard output (output.h). POSIX calls throughout:
// each failure keeps its errno, so the message gives the system's reason.
#include "io/output.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
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

}  // namespace

struct Output::Impl {
    Impl(std::string path, std::string temp, int fd, int error)
        : path(std::move(path)), temp(std::move(temp)), fd(fd), buf(fd) {
        if (error) buf.fail(error);
    }
    std::string path, temp;  // temp is empty when writing in place
    int fd;                  // -1 for stdout: std::cout is written
    FdBuf buf;
    std::ostream out{&buf};
    bool done = false;

    std::string label() const {
        return path == "-" ? "cannot write standard output" : path + ": cannot write";
    }
};

Output::Output(std::string path) {
    int fd = -1, error = 0;
    std::string temp;
    struct stat st;
    if (path == "-") {
        // std::cout is the stream (stream()); fd stays -1.
    } else if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        if (S_ISDIR(st.st_mode)) error = EISDIR;
        else if ((fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC)) < 0) error = errno;
    } else {
        // A hidden name beside the output: ".NAME.XXXXXX" in the same directory.
        size_t slash = path.rfind('/');
        std::string pattern = slash == std::string::npos ? "." + path + ".XXXXXX"
                                                         : path.substr(0, slash + 1) + "." +
                                                               path.substr(slash + 1) + ".XXXXXX";
        std::vector<char> name(pattern.begin(), pattern.end());
        name.push_back('\0');
        fd = ::mkstemp(name.data());
        if (fd < 0) {
            error = errno;
        } else {
            temp = name.data();
            // mkstemp creates mode 0600; give the permissions a new file would get.
            mode_t mask = ::umask(0);
            ::umask(mask);
            if (::fchmod(fd, 0666 & ~mask) != 0) error = errno;
        }
    }
    impl_ = std::make_unique<Impl>(std::move(path), std::move(temp), fd, error);
}

Output::~Output() {
    Impl& o = *impl_;
    if (o.done) return;
    if (o.fd >= 0) ::close(o.fd);
    if (!o.temp.empty()) ::unlink(o.temp.c_str());
}

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
    if (!o.buf.error() && !o.temp.empty() && ::rename(o.temp.c_str(), o.path.c_str()) != 0)
        o.buf.fail(errno);
    if (!o.buf.error()) return Status::Ok;
    if (!o.temp.empty()) ::unlink(o.temp.c_str());
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
