#include "ChildProcess.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <volsg/core/Error.h>

#include "ModelReport.h"

namespace volsg::coincompare {

namespace {

/// Most a child may write; more is dropped (a row is a few hundred bytes).
constexpr std::size_t maxOutput = 1 << 20;

void writeAll(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += std::size_t(n);
    }
}

/// Reads what is there now; false at end of file.
bool readAvailable(RunningChild& child) {
    char buffer[8192];
    while (true) {
        const ssize_t n = ::read(child.fd, buffer, sizeof buffer);
        if (n > 0) {
            if (child.output.size() < maxOutput)
                child.output.append(buffer,
                                    std::min(std::size_t(n), maxOutput - child.output.size()));
            continue;
        }
        if (n == 0) return false;
        if (errno == EINTR) continue;
        return errno == EAGAIN || errno == EWOULDBLOCK; // nothing more for now
    }
}

std::string signalName(int sig) {
    switch (sig) {
    case SIGSEGV:
        return "SIGSEGV";
    case SIGABRT:
        return "SIGABRT";
    case SIGBUS:
        return "SIGBUS";
    case SIGFPE:
        return "SIGFPE";
    case SIGILL:
        return "SIGILL";
    case SIGKILL:
        return "SIGKILL";
    case SIGTERM:
        return "SIGTERM";
    default:
        return "signal " + std::to_string(sig);
    }
}

int millisecondsLeft(const RunningChild& child) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        child.deadline - std::chrono::steady_clock::now());
    return int(std::max<long long>(0, left.count()));
}

} // namespace

RunningChild startChild(const std::function<std::string()>& work, double timeoutSeconds) {
    int fds[2];
    if (::pipe(fds) != 0) throw volsg::Error(std::string("pipe: ") + std::strerror(errno));
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw volsg::Error(std::string("fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        ::close(fds[0]);
        // A crash is the child's end, reported by its status: no handler of the parent's (a
        // test framework's, say) may turn it into something else.
        for (const int sig : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL, SIGTERM, SIGINT, SIGPIPE})
            std::signal(sig, SIG_DFL);
        int status = 0;
        std::string out;
        try {
            out = work();
        } catch (const std::exception& e) {
            out = oneLine(e.what());
            status = 3;
        } catch (...) {
            out = "unknown exception";
            status = 3;
        }
        writeAll(fds[1], out);
        ::close(fds[1]);
        std::fflush(stdout);
        std::fflush(stderr);
        ::_exit(status);
    }
    ::close(fds[1]);
    ::fcntl(fds[0], F_SETFL, ::fcntl(fds[0], F_GETFL) | O_NONBLOCK);
    ::fcntl(fds[0], F_SETFD, FD_CLOEXEC);
    RunningChild child;
    child.pid = pid;
    child.fd = fds[0];
    child.timeoutSeconds = timeoutSeconds;
    child.deadline = std::chrono::steady_clock::now() +
                     std::chrono::milliseconds((long long)(timeoutSeconds * 1000.0));
    return child;
}

void pollChildren(const std::vector<RunningChild*>& children, int waitMilliseconds) {
    std::vector<pollfd> fds;
    std::vector<RunningChild*> open;
    for (RunningChild* c : children) {
        if (c->eof || c->fd < 0) continue;
        fds.push_back({c->fd, POLLIN, 0});
        open.push_back(c);
        waitMilliseconds = std::min(waitMilliseconds, millisecondsLeft(*c));
    }
    if (fds.empty()) return;
    const int n = ::poll(fds.data(), fds.size(), std::max(0, waitMilliseconds));
    if (n <= 0) return;
    for (std::size_t i = 0; i < fds.size(); ++i)
        if (fds[i].revents & (POLLIN | POLLHUP | POLLERR))
            if (!readAvailable(*open[i])) open[i]->eof = true;
}

bool childDone(const RunningChild& child) {
    return child.eof || std::chrono::steady_clock::now() >= child.deadline;
}

ChildResult finishChild(RunningChild& child) {
    while (!childDone(child))
        pollChildren({&child}, 1000);
    ChildResult result;
    bool killed = false;
    if (!child.eof) {
        ::kill(child.pid, SIGKILL);
        killed = true;
    }
    int status = 0;
    while (::waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!killed) readAvailable(child); // anything written just before the end
    ::close(child.fd);
    child.fd = -1;
    result.output = child.output;
    char text[64];
    if (killed) {
        std::snprintf(text, sizeof text, "timed out after %g s", child.timeoutSeconds);
        result.problem = text;
    } else if (WIFSIGNALED(status)) {
        result.problem = "crashed (" + signalName(WTERMSIG(status)) + ")";
    } else if (WIFEXITED(status) && WEXITSTATUS(status) == 3) {
        result.problem = oneLine(child.output.empty() ? "exception" : child.output);
    } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
        result.problem = "exited with status " + std::to_string(WEXITSTATUS(status));
    } else {
        result.ok = true;
    }
    return result;
}

ChildResult runInChild(const std::function<std::string()>& work, double timeoutSeconds) {
    RunningChild child = startChild(work, timeoutSeconds);
    return finishChild(child);
}

} // namespace volsg::coincompare
