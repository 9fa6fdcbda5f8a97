#include "sbsim/radio/ReceptionInterest.h"

namespace sbsim::radio {

void ReceptionInterest::assign(std::vector<std::uint64_t>& bits, Index station, bool value) {
    const std::size_t word = station / 64;
    if (bits.size() <= word) {
        if (!value) return;
        bits.resize(word + 1, 0);
    }
    const std::uint64_t mask = std::uint64_t{1} << (station % 64);
    bits[word] = value ? bits[word] | mask : bits[word] & ~mask;
}

void ReceptionInterest::set(Index station, const std::optional<std::vector<std::string>>& types) {
    // What it took before is forgotten first: a station's services may change (another vehicle
    // with its name, a service hosted after the others).
    const bool was = Takers::test(&restrictedBits_, station);
    if (was) {
        for (const std::string& type : typesOf_[station]) assign(typed_[type], station, false);
        typesOf_[station].clear();
    }
    assign(restrictedBits_, station, types.has_value());
    restricted_ = restricted_ - (was ? 1 : 0) + (types ? 1 : 0);
    if (!types) return;
    if (typesOf_.size() <= station) typesOf_.resize(station + 1);
    for (const std::string& type : *types) {
        assign(typed_[type], station, true);
        typesOf_[station].push_back(type);
    }
}

ReceptionInterest::Takers ReceptionInterest::takersOf(std::string_view type) const {
    Takers t;
    t.restricted_ = &restrictedBits_;
    const auto it = typed_.find(type);
    t.typed_ = it == typed_.end() ? nullptr : &it->second;
    return t;
}

}  // namespace sbsim::radio
