#include <volsg/volumeio/IsolatedCall.h>

#include <algorithm>
#include <csignal>
#include <cstring>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <volsg/core/Error.h>

namespace volsg {

namespace {

/// The child's message goes in the first bytes of the mapping, after its length.
constexpr std::size_t kMessageBytes = 1024;

struct Mapping {
    void* address = MAP_FAILED;
    std::size_t size = 0;
    ~Mapping() {
        if (address != MAP_FAILED) munmap(address, size);
    }
};

} // namespace

IsolatedOutcome runIsolated(std::size_t sharedBytes,
                            const std::function<bool(std::span<std::byte>, std::string&)>& work,
                            const std::function<void(std::span<const std::byte>)>& read) {
    Mapping map;
    map.size = kMessageBytes + std::max<std::size_t>(sharedBytes, 1);
    map.address =
        mmap(nullptr, map.size, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (map.address == MAP_FAILED)
        throw Error("cannot map " + std::to_string(map.size) + " bytes for the DICOM reader");
    auto* bytes = static_cast<std::byte*>(map.address);
    const std::span<std::byte> shared(bytes + kMessageBytes, sharedBytes);

    const pid_t child = fork();
    if (child < 0)
        throw Error(std::string("cannot fork the DICOM reader: ") + std::strerror(errno));
    if (child == 0) {
        // Default handlers: a fuzzer's or sanitizer's handler would report the child's abort
        // as the caller's crash.
        for (int s : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL})
            std::signal(s, SIG_DFL);
        // A library's assertion text is not the user's message: the caller reports the outcome.
        if (const int null = open("/dev/null", O_WRONLY); null >= 0) dup2(null, STDERR_FILENO);
        std::string message;
        bool ok = false;
        try {
            ok = work(shared, message);
        } catch (const std::exception& e) {
            message = e.what();
        } catch (...) {
            message = "an unknown exception";
        }
        const std::size_t n = std::min(message.size(), kMessageBytes - sizeof(std::size_t));
        std::memcpy(bytes, &n, sizeof n);
        std::memcpy(bytes + sizeof n, message.data(), n);
        _exit(ok ? 0 : 1);
    }

    int status = 0;
    while (waitpid(child, &status, 0) < 0)
        if (errno != EINTR)
            throw Error(std::string("cannot wait for the DICOM reader: ") + std::strerror(errno));
    IsolatedOutcome out;
    if (WIFSIGNALED(status)) {
        out.message = "stopped by signal " + std::to_string(WTERMSIG(status)) + " (" +
                      strsignal(WTERMSIG(status)) + ")";
        return out;
    }
    std::size_t n = 0;
    std::memcpy(&n, bytes, sizeof n);
    out.message.assign(reinterpret_cast<const char*>(bytes) + sizeof n,
                       std::min(n, kMessageBytes - sizeof n));
    out.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (out.ok) read(shared);
    return out;
}

} // namespace volsg
