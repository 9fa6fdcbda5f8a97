#pragma once

#include <memory>

namespace sbsim::traffic {

/// One array of a VehicleSnapshot, held by shared_ptr so that a reader outside C++ (a Python
/// service's numpy view) can point at the snapshot's own storage instead of copying it, and keep
/// it alive. The snapshot's writer asks writable() before each refill: while nobody else holds the
/// current array it is written in place (no allocation); when a reader still holds it, the reader
/// keeps that step's values and the writer switches to a spare array (double-buffering: the spare
/// is the one released a step earlier, so a reader that holds only the latest step's array costs
/// no allocation either), or to a fresh one when the spare is held as well.
template <typename T>
class SharedColumn {
public:
    SharedColumn() : current_(std::make_shared<T>()) {}
    // A copied snapshot owns its arrays: it never writes into another's.
    SharedColumn(const SharedColumn& other) : current_(std::make_shared<T>(*other.current_)) {}
    SharedColumn& operator=(const SharedColumn& other) {
        if (this != &other) *writable(false) = *other.current_;
        return *this;
    }
    // A moved-from column reads as empty and is writable again.
    SharedColumn(SharedColumn&&) noexcept = default;
    SharedColumn& operator=(SharedColumn&&) noexcept = default;
    ~SharedColumn() = default;

    const T& operator*() const { return current_ ? *current_ : empty(); }
    const T* operator->() const { return &**this; }
    /// The current array, for a reader that keeps it (its values stay those of this step).
    std::shared_ptr<const T> shared() const {
        return current_ ? std::shared_ptr<const T>(current_) : std::make_shared<const T>();
    }

    /// The array to write now. `keepValues`: a switched-to array starts with the current values
    /// (for a writer that does not rewrite every element); otherwise its values are unspecified.
    T* writable(bool keepValues) {
        if (!current_) current_ = std::make_shared<T>();
        if (current_.use_count() == 1) return current_.get();
        if (!spare_ || spare_.use_count() > 1) spare_ = std::make_shared<T>();
        if (keepValues) *spare_ = *current_;
        current_.swap(spare_);
        return current_.get();
    }

private:
    static const T& empty() {
        static const T none;
        return none;
    }

    std::shared_ptr<T> current_;
    std::shared_ptr<T> spare_;  // the array before current_; reused once its readers let go
};

}  // namespace sbsim::traffic
