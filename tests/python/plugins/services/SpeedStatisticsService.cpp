// Records its vehicle's speed at every trigger (a time series) and, at the end, how many triggers
// it saw and its highest speed (scalars): what test_statistics.py checks the outputs against.
#include <sbsim/services/Service.h>
#include <sbsim/services/ServiceRegistry.h>

#include <algorithm>

namespace statistics_test {

class SpeedStatisticsService : public sbsim::services::Service {
public:
    void trigger() override {
        const auto self = selfIndex();
        if (!self) return;
        const double speed = snapshot().speeds()[*self];
        emit("speed", speed);
        top_ = std::max(top_, speed);
        ++triggers_;
    }
    void finish() override {
        recordScalar("triggers", static_cast<double>(triggers_));
        recordScalar("top_speed", top_);
    }

private:
    int triggers_ = 0;
    double top_ = 0;
};

SBSIM_REGISTER_SERVICE(SpeedStatisticsService);

}  // namespace statistics_test
