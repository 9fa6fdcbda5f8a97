#include <gtest/gtest.h>

#include <Eigen/Core>
#include <memory>

#include "sbsim/traffic/SharedColumn.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::traffic {
namespace {

using Column = SharedColumn<Eigen::VectorXd>;

TEST(SharedColumn, IsWrittenInPlaceWhileNobodyHoldsIt) {
    Column c;
    Eigen::VectorXd* first = c.writable(false);
    first->setConstant(4, 1.0);
    EXPECT_EQ(c.writable(false), first);
    EXPECT_EQ(c.shared().get(), first);  // a reader sees the column's own storage
}

TEST(SharedColumn, AHeldArrayKeepsItsValuesAndTwoArraysAlternate) {
    Column c;
    c.writable(false)->setConstant(3, 1.0);
    auto held = c.shared();  // as a Python view holds a step's array
    const Eigen::VectorXd* a = held.get();
    Eigen::VectorXd* b = c.writable(false);
    ASSERT_NE(b, a);
    b->setConstant(3, 2.0);
    EXPECT_EQ(*held, Eigen::VectorXd::Constant(3, 1.0));  // the reader's step is untouched
    EXPECT_EQ((*c)[0], 2.0);
    // The reader lets go of a and holds b: the next refill goes back to a (no allocation).
    held = c.shared();
    EXPECT_EQ(c.writable(false), a);
    EXPECT_EQ(*held, Eigen::VectorXd::Constant(3, 2.0));
}

TEST(SharedColumn, ArraysStillHeldAreLeftToTheirReaders) {
    Column c;
    c.writable(false)->setConstant(2, 1.0);
    const auto first = c.shared();
    c.writable(false)->setConstant(2, 2.0);
    const auto second = c.shared();
    Eigen::VectorXd* third = c.writable(true);  // both held: a fresh one, starting from the current values
    EXPECT_NE(third, first.get());
    EXPECT_NE(third, second.get());
    EXPECT_EQ(*third, Eigen::VectorXd::Constant(2, 2.0));
    third->setConstant(2, 3.0);
    EXPECT_EQ(*first, Eigen::VectorXd::Constant(2, 1.0));
    EXPECT_EQ(*second, Eigen::VectorXd::Constant(2, 2.0));
}

TEST(SharedColumn, ACopyOwnsItsArrays) {
    Column c;
    c.writable(false)->setConstant(2, 1.0);
    Column copy = c;
    copy.writable(false)->setConstant(2, 5.0);
    EXPECT_EQ(*c, Eigen::VectorXd::Constant(2, 1.0));
    EXPECT_NE(copy.shared().get(), c.shared().get());
}

TEST(SharedColumn, ASnapshotRefilledWhileAViewHoldsItsSpeedsKeepsTheView) {
    VehicleSnapshot s;
    VehicleSnapshot::Vehicle car;
    car.id = "a";
    car.speed = 3;
    s.assign({car}, kernel::SimTime::fromSeconds(1));
    const auto view = s.sharedSpeeds();
    EXPECT_EQ(view->data(), s.speeds().data());
    car.speed = 4;
    s.assign({car}, kernel::SimTime::fromSeconds(2));
    EXPECT_EQ((*view)[0], 3.0);
    EXPECT_EQ(s.speeds()[0], 4.0);
    EXPECT_NE(view->data(), s.speeds().data());
}

}  // namespace
}  // namespace sbsim::traffic
