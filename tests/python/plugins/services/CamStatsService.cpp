// Reads every CAM its vehicle receives (after the LDM took it in): how many, how many from a standing
// sender (below 1 m/s), and the sum of their speeds, recorded as scalars at the end. The C++ side of
// bench/python_services.py's comparison with the same service written in Python.
#include <sbsim/facilities/Cam.h>
#include <sbsim/facilities/ItsMessageHandler.h>
#include <sbsim/services/Service.h>
#include <sbsim/services/ServiceRegistry.h>

namespace test_services {

class CamStatsService : public sbsim::services::Service, public sbsim::facilities::ItsMessageHandler {
public:
    void indicateCam(const sbsim::facilities::Cam& cam) override {
        const double speed = cam.content().speed;
        ++cams_;
        if (speed < 1.0) ++slow_;
        speedSum_ += speed;
    }
    void finish() override {
        recordScalar("cams", static_cast<double>(cams_));
        recordScalar("slow", static_cast<double>(slow_));
        recordScalar("speed_sum", speedSum_);
    }

private:
    long cams_ = 0;
    long slow_ = 0;
    double speedSum_ = 0;
};

SBSIM_REGISTER_SERVICE(CamStatsService);

}  // namespace test_services
