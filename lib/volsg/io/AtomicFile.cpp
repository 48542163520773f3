#include <volsg/core/Error.h>
#include <volsg/io/AtomicFile.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace volsg {

namespace {

std::string errnoText() {
    return std::strerror(errno);
}

/// The file a save really replaces: the target of a symbolic link, else `path` itself.
std::string replacedPath(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(path, ec)) return path;
    const std::filesystem::path target = std::filesystem::read_symlink(path, ec);
    if (ec) return path;
    if (target.is_absolute()) return target.string();
    return (std::filesystem::path(path).parent_path() / target).string();
}

/// Removes the temporary file on every exit but a successful rename.
class TemporaryFile {
public:
    explicit TemporaryFile(const std::string& finalPath) {
        static std::atomic<unsigned> serial{0};
        path_ = finalPath + ".tmp." + std::to_string(::getpid()) + "." +
                std::to_string(serial.fetch_add(1));
        fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    }
    ~TemporaryFile() {
        if (fd_ >= 0) ::close(fd_);
        if (!renamed_) ::unlink(path_.c_str());
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    bool isOpen() const { return fd_ >= 0; }
    int fd() const { return fd_; }
    const std::string& path() const { return path_; }
    bool close() {
        const int fd = fd_;
        fd_ = -1;
        return ::close(fd) == 0;
    }
    void markRenamed() { renamed_ = true; }

private:
    std::string path_;
    int fd_ = -1;
    bool renamed_ = false;
};

} // namespace

void writeFileAtomically(const std::string& path, std::string_view bytes) {
    if (path.empty()) throw Error("cannot save: no file name given");
    const std::string target = replacedPath(path);
    struct stat old {};
    const bool hadFile = ::stat(target.c_str(), &old) == 0;
    if (hadFile && S_ISDIR(old.st_mode)) throw Error("cannot save: this is a folder", path);

    TemporaryFile temporary(target);
    if (!temporary.isOpen())
        throw Error("cannot save: cannot create a temporary file in its folder (" + errnoText() +
                        ")",
                    path);
    // A SIGXFSZ-free process gets EFBIG here; a full disk gives ENOSPC: both end the save.
    std::size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(temporary.fd(), bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0)
            throw Error("cannot save: write error after " + std::to_string(written) + " of " +
                            std::to_string(bytes.size()) + " bytes (" + errnoText() +
                            "); the previous file is unchanged",
                        path);
        written += std::size_t(n);
    }
    if (hadFile) ::fchmod(temporary.fd(), old.st_mode & 07777);
    if (::fsync(temporary.fd()) != 0 || !temporary.close())
        throw Error("cannot save: error flushing to the disk (" + errnoText() +
                        "); the previous file is unchanged",
                    path);
    if (::rename(temporary.path().c_str(), target.c_str()) != 0)
        throw Error("cannot save: cannot replace the file (" + errnoText() +
                        "); the previous file is unchanged",
                    path);
    temporary.markRenamed();
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    std::ostringstream content;
    write(content); // throws before any file is touched
    writeFileAtomically(path, std::move(content).str());
}

} // namespace volsg
