#pragma once
// Intrusively reference-counted base and its smart pointer.

#include <atomic>
#include <cstddef>
#include <utility>

namespace volsg {

/// Base of everything shared by reference: nodes, cached GL resources, volume data.
class Object {
public:
    Object() = default;
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;

    void ref() const noexcept { refCount_.fetch_add(1, std::memory_order_relaxed); }
    void unref() const noexcept {
        if (refCount_.fetch_sub(1, std::memory_order_acq_rel) == 1) delete this;
    }
    int refCount() const noexcept { return refCount_.load(std::memory_order_relaxed); }

protected:
    virtual ~Object() = default;

private:
    mutable std::atomic<int> refCount_{0};
};

/// Intrusive pointer: holding one keeps the object alive.
template <class T> class ref_ptr {
public:
    ref_ptr() noexcept = default;
    ref_ptr(std::nullptr_t) noexcept {}
    ref_ptr(T* p) noexcept : p_(p) {
        if (p_) p_->ref();
    }
    ref_ptr(const ref_ptr& o) noexcept : ref_ptr(o.p_) {}
    ref_ptr(ref_ptr&& o) noexcept : p_(std::exchange(o.p_, nullptr)) {}
    template <class U> ref_ptr(const ref_ptr<U>& o) noexcept : ref_ptr(o.get()) {}
    ~ref_ptr() {
        if (p_) p_->unref();
    }
    ref_ptr& operator=(ref_ptr o) noexcept {
        std::swap(p_, o.p_);
        return *this;
    }

    T* get() const noexcept { return p_; }
    T* operator->() const noexcept { return p_; }
    T& operator*() const noexcept { return *p_; }
    explicit operator bool() const noexcept { return p_ != nullptr; }
    bool operator==(const ref_ptr& o) const noexcept { return p_ == o.p_; }
    bool operator==(const T* o) const noexcept { return p_ == o; }

    /// Typed downcast; null when the object is not a U.
    template <class U> ref_ptr<U> cast() const noexcept { return ref_ptr<U>(dynamic_cast<U*>(p_)); }

private:
    T* p_ = nullptr;
};

} // namespace volsg
