#pragma once
// Runs library code that may abort on hostile input in a child process. Debian's GDCM keeps its
// assertions (a malformed file can end the program in assert()), so the DICOM reader parses
// and decodes in a forked child that writes its results into memory shared with the caller:
// whatever the child does, the caller gets an answer and goes on.

#include <cstddef>
#include <functional>
#include <span>
#include <string>

namespace volsg {

/// What an isolated call left: ok when the child returned true and exited normally; else
/// `message` is the child's own message (set through the second argument of `work`) or says
/// how it ended (the signal that stopped it).
struct IsolatedOutcome {
    bool ok = false;
    std::string message;
};

/// Forks; the child runs work(shared, message) on `sharedBytes` zeroed bytes that the caller
/// reads after the child exits (through `shared`), with default signal handlers, and leaves
/// with _exit (no atexit handlers, no leak check of a process image it shares). Throws Error
/// when the memory cannot be mapped or the process cannot be forked.
IsolatedOutcome runIsolated(std::size_t sharedBytes,
                            const std::function<bool(std::span<std::byte>, std::string&)>& work,
                            const std::function<void(std::span<const std::byte>)>& read);

} // namespace volsg
