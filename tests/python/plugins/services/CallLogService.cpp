// Logs every call the middleware makes as a time series of the statistics: initialize (1), trigger (2),
// signal (3), indicate (4: the message's sequence number as value is in the "indicate" series),
// on_cam (5), on_denm (6), finish (7). test_python_services.py runs a Python service logging the
// same calls and compares the two sequences.
#include <sbsim/facilities/Cam.h>
#include <sbsim/facilities/Denm.h>
#include <sbsim/facilities/ItsMessageHandler.h>
#include <sbsim/services/Service.h>
#include <sbsim/services/ServiceRegistry.h>

namespace test_services {

class CallLogService : public sbsim::services::Service, public sbsim::facilities::ItsMessageHandler {
public:
    void initialize() override { emit("call", 1); }
    void trigger() override { emit("call", 2); }
    void receiveSignal(const sbsim::traffic::StoryboardSignal&) override { emit("call", 3); }
    void indicate(const sbsim::radio::V2xMessage& message) override {
        emit("call", 4);
        emit("indicate", static_cast<double>(message.sequence()));
    }
    void indicateCam(const sbsim::facilities::Cam&) override { emit("call", 5); }
    void indicateDenm(const sbsim::facilities::Denm&) override { emit("call", 6); }
    void finish() override { emit("call", 7); }
};

SBSIM_REGISTER_SERVICE(CallLogService);

}  // namespace test_services
