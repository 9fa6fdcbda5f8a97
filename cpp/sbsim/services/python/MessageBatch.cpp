#include "sbsim/services/python/MessageBatch.h"

#include <algorithm>
#include <limits>

namespace sbsim::services::python {

namespace {
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

template <typename T>
const T* sparse(const std::vector<std::pair<std::uint32_t, T>>& items, std::uint32_t i) {
    const auto it =
        std::lower_bound(items.begin(), items.end(), i, [](const auto& e, std::uint32_t k) { return e.first < k; });
    return it != items.end() && it->first == i ? &it->second : nullptr;
}
}  // namespace

void MessageBatch::clear() {
    refs_.clear();
    chunks_.clear();
    lastChunk_ = nullptr;
    made_ = 0;
}

const std::vector<double>& MessageBatch::column(Column which) const {
    const auto k = static_cast<std::size_t>(which);
    std::vector<double>& out = columns_[k];
    if ((made_ & (1U << k)) != 0) return out;
    made_ |= 1U << k;
    const std::size_t n = refs_.size();
    out.resize(which == Column::CamPosition ? 2 * n : n);
    for (std::size_t i = 0; i < n; ++i) {
        const MessageStore::Row& r = row(i);
        switch (which) {
            case Column::ReceivedAt:
                out[i] = r.receivedAt;
                break;
            case Column::SentAt:
                out[i] = r.sentAt;
                break;
            case Column::Size:
                out[i] = r.size;
                break;
            case Column::CamPosition:
                out[2 * i] = r.cam ? r.camValues[0] : kNone;
                out[2 * i + 1] = r.cam ? r.camValues[1] : kNone;
                break;
            case Column::CamSpeed:
                out[i] = r.cam ? r.camValues[2] : kNone;
                break;
            case Column::CamHeading:
                out[i] = r.cam ? r.camValues[3] : kNone;
                break;
            case Column::kCount:
                break;
        }
    }
    return out;
}

ReceivedMessage MessageBatch::at(std::size_t i) const {
    const MessageStore::Chunk& from = chunk(i);
    const std::uint32_t k = rowIndex(i);
    const MessageStore::Row& r = from.rows[k];
    ReceivedMessage out;
    out.receivedAt = kernel::SimTime::fromSeconds(r.receivedAt);
    out.type = store_->typeNames()[r.type];
    out.sender = from.senders[k];
    out.sentAt = kernel::SimTime::fromSeconds(r.sentAt);
    out.sequence = r.sequence;
    out.size = r.size;
    out.frameBytes = r.frameBytes;
    const pybind11::object* payload = sparse(from.payloads, k);
    out.payload = payload != nullptr ? *payload : pybind11::none();
    if (const auto* denm = sparse(from.denms, k)) out.denm = *denm;
    if (r.cam) {
        const double* v = r.camValues;
        facilities::CamContent& cam = out.cam.emplace();
        cam.station = from.senders[k];  // a CAM is its originator's, sent single-hop
        cam.stationType = static_cast<facilities::StationType>(r.stationType);
        cam.position = {v[0], v[1]};
        cam.speed = v[2];
        cam.heading = v[3];
        cam.acceleration = v[4];
        cam.length = v[5];
        cam.width = v[6];
        cam.yawRate = v[7];
        cam.generationTime = kernel::SimTime::fromSeconds(v[8]);
    }
    return out;
}

std::vector<std::string> MessageBatch::senders() const {
    std::vector<std::string> out;
    out.reserve(refs_.size());
    for (std::size_t i = 0; i < refs_.size(); ++i) out.push_back(chunk(i).senders[rowIndex(i)]);
    return out;
}

std::vector<std::string> MessageBatch::types() const {
    std::vector<std::string> out;
    out.reserve(refs_.size());
    for (std::size_t i = 0; i < refs_.size(); ++i) out.push_back(store_->typeNames()[row(i).type]);
    return out;
}

}  // namespace sbsim::services::python
