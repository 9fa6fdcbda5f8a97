// ServiceVehicle's position and driving distances on a real SUMO run (the generated grid): a
// service asks, every trigger, how far its vehicle drives to the end of its route's last edge and
// to that point in 2D; the distances shrink as it drives, match each other, and a spot off its
// route has none.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "SumoTestSupport.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/disc/DiscMedium.h"
#include "sbsim/services/Service.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::services {
namespace {

struct Sample {
    double t;
    std::optional<double> toEdge;
    std::optional<double> toPoint;
    std::optional<double> offRoute;
    traffic::Position position;
    Eigen::Vector2d snapshotPosition;
};
std::map<std::string, std::vector<Sample>>* samples = nullptr;

class DistanceProbe : public Service {
public:
    void trigger() override {
        if (!selfIndex()) return;
        const std::vector<std::string> route = vehicle().route();
        const std::string& last = route.back();
        Sample s{simTime().seconds(),  vehicle().drivingDistance(last, 5.0),
                 std::nullopt,         std::nullopt,
                 vehicle().position(), position()};
        // The 2D point: where the vehicle was at its first trigger (behind it from then on).
        if (!target_) target_ = s.snapshotPosition;
        s.toPoint = vehicle().drivingDistanceTo(target_->x(), target_->y());
        // An edge of the grid no route of this vehicle uses: its first edge, behind it once left.
        s.offRoute = vehicle().drivingDistance(route.front(), 0.0);
        (*samples)[vehicleId()].push_back(s);
    }

private:
    std::optional<Eigen::Vector2d> target_;
};
SBSIM_REGISTER_SERVICE(DistanceProbe);

TEST(DrivingDistance, ShrinksAlongTheRoute) {
    std::map<std::string, std::vector<Sample>> seen;
    samples = &seen;
    {
        traffic::VehicleRegistry registry;
        kernel::Simulation sim(1);
        traffic::SumoSettings settings = test::scenarioSettings();
        settings.end = test::sec(40);
        auto& sumo = sim.emplaceModule<traffic::SumoBridge>(settings);
        sumo.load();
        auto& manager = sim.emplaceModule<ServiceManager>(
            ServicesConfig::parse(R"(<services><service type="DistanceProbe"/></services>)", "test.xml"), test::sec(1),
            sumo.snapshot(), registry);
        auto& medium = sim.emplaceModule<radio::DiscMedium>(
            radio::DiscSettings{}, sumo.snapshot(), [&](const std::string& id) { return manager.middlewareOf(id); });
        manager.setMedium(medium);
        manager.attach(sumo);
        registry.attach(sumo);
        sumo.demandColumns(ServiceManager::columns());
        sim.run();
        sim.finish();
    }
    samples = nullptr;
    ASSERT_GT(seen.size(), 10u);
    std::size_t checked = 0;
    for (const auto& [id, list] : seen) {
        ASSERT_FALSE(list.empty());
        for (std::size_t i = 0; i < list.size(); ++i) {
            const Sample& s = list[i];
            // The live position is the snapshot's (read after the same step).
            EXPECT_NEAR(s.position.x, s.snapshotPosition.x(), 1e-6) << id;
            EXPECT_NEAR(s.position.y, s.snapshotPosition.y(), 1e-6) << id;
            ASSERT_TRUE(s.toEdge) << id << " at " << s.t;
            if (i > 0) {
                EXPECT_LE(*s.toEdge, *list[i - 1].toEdge + 1e-6) << id << " drives towards its destination";
                // Its first position lies behind it now.
                EXPECT_FALSE(s.toPoint && *s.toPoint > 1e-3) << id << " at " << s.t;
            }
            ++checked;
        }
        if (list.size() > 3) EXPECT_LT(*list.back().toEdge, *list.front().toEdge) << id;
        EXPECT_FALSE(list.back().offRoute && *list.back().offRoute > 0) << id << ": its first edge is behind it";
    }
    EXPECT_GT(checked, 100u);
}

}  // namespace
}  // namespace sbsim::services
