#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sbsim::traffic {

/// Which per-vehicle values a VehicleSnapshot holds. Reading a value costs a libsumo lookup per
/// vehicle and step, so the snapshot reads only the union of what its readers declared (the
/// stories' conditions, the services): a run without either reads nothing per vehicle.
class SnapshotColumns {
public:
    enum Column : std::uint32_t {
        Position = 1u << 0,
        Speed = 1u << 1,
        Angle = 1u << 2,
        Acceleration = 1u << 3,  ///< derived from the speed change, so it reads Speed too
        Lane = 1u << 4,          ///< lane and road
        // Read once, when the vehicle departs (max speed again after a command changed it).
        Size = 1u << 5,  ///< length and width
        Type = 1u << 6,
        MaxSpeed = 1u << 7,
    };

    constexpr SnapshotColumns() = default;
    constexpr SnapshotColumns(Column c) : bits_(c) {}  // NOLINT: a column is a set of one
    constexpr SnapshotColumns(std::initializer_list<Column> columns) {
        for (const Column c : columns) bits_ |= c;
    }
    static constexpr SnapshotColumns none() { return {}; }
    static constexpr SnapshotColumns all() { return SnapshotColumns(kAllBits); }

    constexpr bool contains(SnapshotColumns other) const { return (bits_ & other.bits_) == other.bits_; }
    constexpr bool empty() const { return bits_ == 0; }
    constexpr SnapshotColumns operator|(SnapshotColumns other) const { return SnapshotColumns(bits_ | other.bits_); }
    constexpr SnapshotColumns& operator|=(SnapshotColumns other) { return *this = *this | other; }
    constexpr bool operator==(const SnapshotColumns&) const = default;
    /// The columns read per step (the others are read at departure).
    constexpr SnapshotColumns perStep() const { return SnapshotColumns(bits_ & kPerStepBits); }

    /// The columns' names ("position", "max_speed"), in declaration order.
    std::vector<std::string_view> names() const {
        std::vector<std::string_view> out;
        for (std::uint32_t k = 0; k < 8; ++k) {
            if ((bits_ & (1u << k)) != 0) out.emplace_back(kNames[k]);
        }
        return out;
    }
    /// "position|speed" ("none" for none); for messages and tests.
    std::string str() const {
        std::string out;
        for (const std::string_view name : names()) {
            if (!out.empty()) out += '|';
            out += name;
        }
        return out.empty() ? "none" : out;
    }
    /// The column called `name` as str() writes it ("lane", "max_speed"), if there is one.
    static std::optional<SnapshotColumns> named(std::string_view name) {
        for (std::uint32_t k = 0; k < 8; ++k) {
            if (name == kNames[k]) return SnapshotColumns(1u << k);
        }
        return std::nullopt;
    }

private:
    static constexpr const char* kNames[] = {"position", "speed", "angle", "acceleration",
                                             "lane",     "size",  "type",  "max_speed"};
    static constexpr std::uint32_t kAllBits = (1u << 8) - 1;
    static constexpr std::uint32_t kPerStepBits = (1u << 5) - 1;
    constexpr explicit SnapshotColumns(std::uint32_t bits) : bits_(bits) {}
    std::uint32_t bits_ = 0;
};

}  // namespace sbsim::traffic
