#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace sbsim::kernel {

/// std::allocator whose value-initialisation is default-initialisation: a vector of trivial
/// values resized up is not zero-filled first. For columns written whole right after a resize
/// (the channel model's StepLinks and LinkBudget::classify's scratch), where a memset per sender
/// and step was ~1 % of the channel model's time on bench5k.
template <typename T>
class DefaultInitAllocator : public std::allocator<T> {
public:
    template <typename U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    DefaultInitAllocator() noexcept = default;
    template <typename U>
    DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}

    template <typename U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;  // default-, not value-initialised
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

}  // namespace sbsim::kernel
