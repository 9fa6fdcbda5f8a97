#pragma once

#include <Eigen/Core>
#include <array>

namespace sbsim::storyboard::geometry {

/// The ground rectangle of a vehicle: length along its heading, width across it. Built from SUMO's
/// pose, whose position is the centre of the front bumper and whose angle is in degrees, 0 = north
/// (+y), clockwise.
class Footprint {
public:
    /// Gaps narrower than this (m) count as touching, so rounding cannot separate touching shapes.
    static constexpr double kTouchTolerance = 1e-9;

    Footprint(const Eigen::Vector2d& centre, const Eigen::Vector2d& unitHeading, double length, double width)
        : centre_(centre), heading_(unitHeading), halfLength_(0.5 * length), halfWidth_(0.5 * width) {}

    /// From SUMO's front bumper centre and angle (degrees).
    static Footprint fromSumo(const Eigen::Vector2d& frontBumper, double sumoAngleDeg, double length, double width);
    /// The unit heading of a SUMO angle, (sin a, cos a); exact at multiples of 90°.
    static Eigen::Vector2d headingOf(double sumoAngleDeg);

    const Eigen::Vector2d& centre() const { return centre_; }
    const Eigen::Vector2d& heading() const { return heading_; }
    /// The heading turned 90° clockwise (the vehicle's right).
    Eigen::Vector2d right() const { return {heading_.y(), -heading_.x()}; }
    double halfLength() const { return halfLength_; }
    double halfWidth() const { return halfWidth_; }
    Eigen::Vector2d frontBumper() const { return centre_ + halfLength_ * heading_; }
    /// Front left, front right, rear right, rear left.
    std::array<Eigen::Vector2d, 4> corners() const;

    /// The footprint after driving `distance` m straight along the heading (negative: backwards).
    Footprint moved(double distance) const {
        Footprint f = *this;
        f.centre_ += distance * heading_;
        return f;
    }
    /// The footprint after `seconds` at constant `speed` (m/s) along the heading.
    Footprint movedFor(double speed, double seconds) const { return moved(speed * seconds); }
    /// The footprint after driving `distance` m along the circular arc of signed `curvature`
    /// (1/m, positive turning left, i.e. counter-clockwise; not 0) that starts at its centre
    /// along its heading; the heading turns with the arc.
    Footprint turned(double distance, double curvature) const;
    /// turned(distance, curvature).centre(), without working out the heading (no cosine).
    Eigen::Vector2d turnedCentre(double distance, double curvature) const;
    /// The footprint after `seconds` at constant `speed` (m/s) along that arc.
    Footprint turnedFor(double speed, double curvature, double seconds) const {
        return turned(speed * seconds, curvature);
    }

private:
    /// The centre after turning `angle` radians (sin: its sine) on the arc of `curvature`.
    Eigen::Vector2d centreOnArc(double angle, double sin, double curvature) const;

    Eigen::Vector2d centre_;
    Eigen::Vector2d heading_;
    double halfLength_;
    double halfWidth_;
};

/// Whether two footprints share at least one point (separating axis theorem); touching overlaps.
bool overlaps(const Footprint& a, const Footprint& b);

/// The half extent of `f` projected on the unit `axis`: f covers centre·axis ± this.
double projectedHalfExtent(const Footprint& f, const Eigen::Vector2d& axis);

}  // namespace sbsim::storyboard::geometry
