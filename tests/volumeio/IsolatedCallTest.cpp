// runIsolated (lib/volsg/volumeio/IsolatedCall.h): what a child writes reaches the caller, and a
// child that aborts, crashes or throws leaves the caller running with a message.
#include <doctest/doctest.h>

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include <volsg/volumeio/IsolatedCall.h>

using namespace volsg;

TEST_CASE("a child's shared bytes and its message reach the caller") {
    std::string seen;
    const IsolatedOutcome ok = runIsolated(
        6,
        [](std::span<std::byte> shared, std::string&) {
            std::memcpy(shared.data(), "volsg", 6);
            return true;
        },
        [&](std::span<const std::byte> shared) {
            seen = reinterpret_cast<const char*>(shared.data());
        });
    CHECK(ok.ok);
    CHECK(seen == "volsg");

    bool read = false;
    const IsolatedOutcome refused = runIsolated(
        1,
        [](std::span<std::byte>, std::string& message) {
            message = "slice-004.dcm: pixel data holds 2 bytes, expected 8";
            return false;
        },
        [&](std::span<const std::byte>) { read = true; });
    CHECK_FALSE(refused.ok);
    CHECK_FALSE(read);
    CHECK(refused.message == "slice-004.dcm: pixel data holds 2 bytes, expected 8");
}

TEST_CASE("a child that aborts or throws leaves the caller running") {
    const auto noRead = [](std::span<const std::byte>) {};
    const IsolatedOutcome aborted = runIsolated(
        1, [](std::span<std::byte>, std::string&) -> bool { std::abort(); }, noRead);
    CHECK_FALSE(aborted.ok);
    CHECK(aborted.message.rfind("stopped by signal 6", 0) == 0);

    const IsolatedOutcome threw = runIsolated(
        1, [](std::span<std::byte>, std::string&) -> bool { throw std::runtime_error("bad"); },
        noRead);
    CHECK_FALSE(threw.ok);
    CHECK(threw.message == "bad");
}
