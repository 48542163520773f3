#pragma once
// Work in a forked child with a deadline: a crash, a hang or an exception in Coin or volsg
// becomes a one-line problem for that model instead of the end of the run. POSIX only.

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace volsg::coincompare {

/// What a child gave back.
struct ChildResult {
    bool ok = false;     ///< the work returned normally and the child exited with status 0
    std::string output;  ///< what the work returned (when ok), or wrote before it failed
    std::string problem; ///< when !ok: "timed out after 60 s", "crashed (SIGSEGV)", the
                         ///< exception's message, "exited with status 3" (one line)
};

/// A child started by startChild and not yet finished.
struct RunningChild {
    pid_t pid = -1;
    int fd = -1; ///< read end of the pipe the child writes its output to
    std::string output;
    bool eof = false; ///< the child closed the pipe (it has exited or is about to)
    std::chrono::steady_clock::time_point deadline;
    double timeoutSeconds = 0.0;
};

/// Forks; the child runs `work` and writes what it returns to a pipe, then leaves with _exit
/// (no atexit handlers or static destructors of Coin or volsg run in the child). An exception
/// from `work` is written instead and the child exits with status 3. Flushes stdout and stderr
/// before forking. Throws volsg::Error when fork or pipe fail.
RunningChild startChild(const std::function<std::string()>& work, double timeoutSeconds);

/// Reads what the children have written, waiting at most `waitMilliseconds` for any of them;
/// sets eof for the ones that closed their pipe. Children past their deadline are left for
/// finishChild to kill.
void pollChildren(const std::vector<RunningChild*>& children, int waitMilliseconds);

/// True when finishChild would not wait: the pipe is closed or the deadline has passed.
bool childDone(const RunningChild& child);

/// Waits for the pipe to close (or kills the child at its deadline with SIGKILL), reaps the
/// child and says how it ended.
ChildResult finishChild(RunningChild& child);

/// startChild and finishChild.
ChildResult runInChild(const std::function<std::string()>& work, double timeoutSeconds);

} // namespace volsg::coincompare
