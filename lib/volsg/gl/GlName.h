#pragma once
// Owns one GL object name and deletes it when it goes away: the common core of the RAII
// wrappers (Buffer, Texture, ...), which then get correct move semantics for free.

#include <utility>

#include <glad/gl.h>

namespace volsg {

/// A move-only GL object name with the function that deletes it. Name 0 is "none": default
/// constructed wrappers make no GL call, so they can sit in containers and caches.
class GlName {
public:
    using Deleter = void (*)(GLuint);

    GlName() noexcept = default;
    GlName(GLuint name, Deleter deleter) noexcept : name_(name), deleter_(deleter) {}
    GlName(const GlName&) = delete;
    GlName& operator=(const GlName&) = delete;
    GlName(GlName&& o) noexcept
        : name_(std::exchange(o.name_, 0u)), deleter_(std::exchange(o.deleter_, nullptr)) {}
    GlName& operator=(GlName&& o) noexcept {
        if (this != &o) {
            reset();
            name_ = std::exchange(o.name_, 0u);
            deleter_ = std::exchange(o.deleter_, nullptr);
        }
        return *this;
    }
    ~GlName() { reset(); }

    GLuint get() const noexcept { return name_; }
    explicit operator bool() const noexcept { return name_ != 0; }

    /// Deletes the object now (the context it belongs to must be current).
    void reset() noexcept {
        if (name_ != 0 && deleter_) deleter_(name_);
        name_ = 0;
        deleter_ = nullptr;
    }

private:
    GLuint name_ = 0;
    Deleter deleter_ = nullptr;
};

} // namespace volsg
