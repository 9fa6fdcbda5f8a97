#include "sbsim/radio/ReceptionInterest.h"

namespace sbsim::radio {

bool ReceptionInterest::assign(std::vector<std::uint64_t>& bits, Index station, bool value) {
    const std::size_t word = station / 64;
    if (bits.size() <= word) {
        if (!value) return false;
        bits.resize(word + 1, 0);
    }
    const std::uint64_t mask = std::uint64_t{1} << (station % 64);
    const bool was = (bits[word] & mask) != 0;
    bits[word] = value ? bits[word] | mask : bits[word] & ~mask;
    return was != value;
}

void ReceptionInterest::set(Index station, const std::optional<std::vector<std::string>>& types) {
    // What it took before is forgotten first: a station's services may change (another vehicle
    // with its name, a service hosted after the others).
    const bool wasRegistered = registered(station);
    const bool was = Takers::test(&restrictedBits_, station);
    if (was) {
        for (const std::string& type : typesOf_[station]) {
            Typed& t = typed_[type];
            if (assign(t.bits, station, false)) --t.count;
        }
        typesOf_[station].clear();
    }
    assign(registeredBits_, station, true);
    assign(restrictedBits_, station, types.has_value());
    restricted_ = restricted_ - (was ? 1 : 0) + (types ? 1 : 0);
    unrestricted_ = unrestricted_ - (wasRegistered && !was ? 1 : 0) + (types ? 0 : 1);
    if (!types) return;
    if (typesOf_.size() <= station) typesOf_.resize(station + 1);
    for (const std::string& type : *types) {
        Typed& t = typed_[type];
        if (assign(t.bits, station, true)) ++t.count;
        typesOf_[station].push_back(type);
    }
}

ReceptionInterest::Takers ReceptionInterest::takersOf(std::string_view type) const {
    Takers t;
    t.restricted_ = &restrictedBits_;
    const auto it = typed_.find(type);
    t.typed_ = it == typed_.end() ? nullptr : &it->second.bits;
    t.noRegisteredTaker_ = unrestricted_ == 0 && (it == typed_.end() || it->second.count == 0);
    return t;
}

}  // namespace sbsim::radio
