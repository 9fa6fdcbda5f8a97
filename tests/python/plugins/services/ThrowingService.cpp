// Throws from its trigger once its vehicle has run `after` seconds (a parameter): the run must end
// with exit code 2 naming the service, the vehicle and the time.
#include <sbsim/services/Service.h>
#include <sbsim/services/ServiceRegistry.h>

#include <stdexcept>

namespace test_services {

class ThrowingService : public sbsim::services::Service {
public:
    void initialize() override { at_ = simTime().seconds() + numberParameter("after", 5.0); }
    void trigger() override {
        if (simTime().seconds() >= at_) throw std::runtime_error("the service's own bug");
    }

private:
    double at_ = 0;
};

SBSIM_REGISTER_SERVICE(ThrowingService);

}  // namespace test_services
