#include "sbsim/radio/propagation/Obstacles.h"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <stdexcept>
#include <utility>

namespace sbsim::radio {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using Point = bg::model::point<double, 2, bg::cs::cartesian>;
using Box = bg::model::box<Point>;
using Segment = bg::model::segment<Point>;

struct Obstacles::Index {
    bgi::rtree<std::pair<Box, std::size_t>, bgi::rstar<16>> tree;
};

namespace {

/// Whether p is inside the ring (even-odd rule; the ring's last point joins its first).
bool inside(const Obstacles::Shape& ring, const Eigen::Vector2d& p) {
    bool in = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Eigen::Vector2d& a = ring[i];
        const Eigen::Vector2d& b = ring[j];
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
            in = !in;
    }
    return in;
}

/// The parameter t in [0, 1] along a→b where it crosses the edge c→d, if it does.
bool cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d,
           double& t) {
    const Eigen::Vector2d r = b - a;
    const Eigen::Vector2d s = d - c;
    const double denominator = r.x() * s.y() - r.y() * s.x();
    if (denominator == 0) return false;  // parallel: grazing a wall is not crossing it
    const Eigen::Vector2d q = c - a;
    t = (q.x() * s.y() - q.y() * s.x()) / denominator;
    const double u = (q.x() * r.y() - q.y() * r.x()) / denominator;
    return t >= 0 && t <= 1 && u >= 0 && u < 1;  // u < 1: a shared corner counts for one edge
}

}  // namespace

Obstacles::Obstacles(double perWallDb, double perMetreDb)
    : perWallDb_(perWallDb), perMetreDb_(perMetreDb), index_(std::make_unique<Index>()) {
    if (!(perWallDb >= 0) || !(perMetreDb >= 0)) throw std::invalid_argument("obstacle losses must be >= 0 dB");
}
Obstacles::~Obstacles() = default;
Obstacles::Obstacles(Obstacles&&) noexcept = default;
Obstacles& Obstacles::operator=(Obstacles&&) noexcept = default;

void Obstacles::add(Shape shape) {
    if (shape.size() >= 2 && shape.front() == shape.back()) shape.pop_back();
    if (shape.size() < 3) return;
    Box box(Point(shape[0].x(), shape[0].y()), Point(shape[0].x(), shape[0].y()));
    for (const Eigen::Vector2d& p : shape) bg::expand(box, Point(p.x(), p.y()));
    index_->tree.insert({box, shapes_.size()});
    shapes_.push_back(std::move(shape));
}

std::size_t Obstacles::size() const { return shapes_.size(); }

Obstacles::Crossing Obstacles::crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
    Crossing total;
    if (shapes_.empty()) return total;
    const Box lineBox(Point(std::min(a.x(), b.x()), std::min(a.y(), b.y())),
                      Point(std::max(a.x(), b.x()), std::max(a.y(), b.y())));
    const Segment line(Point(a.x(), a.y()), Point(b.x(), b.y()));
    const double length = (b - a).norm();
    std::vector<double> ts;
    // The line's bounding box first (cheap in the tree), then the exact box-segment test.
    for (auto it = index_->tree.qbegin(bgi::intersects(lineBox)); it != index_->tree.qend(); ++it) {
        if (!bg::intersects(it->first, line)) continue;
        const Shape& ring = shapes_[it->second];
        ts.clear();
        for (std::size_t i = 0; i < ring.size(); ++i) {
            double t = 0;
            if (cross(a, b, ring[i], ring[(i + 1) % ring.size()], t)) ts.push_back(t);
        }
        const bool startsInside = inside(ring, a);
        if (ts.empty() && !startsInside) continue;
        std::sort(ts.begin(), ts.end());
        total.walls += static_cast<int>(ts.size());
        // Alternate in and out along the line from where a is.
        bool in = startsInside;
        double last = 0;
        for (const double t : ts) {
            if (in) total.insideMetres += (t - last) * length;
            in = !in;
            last = t;
        }
        if (in) total.insideMetres += (1 - last) * length;
    }
    return total;
}

double Obstacles::lossDb(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
    const Crossing c = crossing(a, b);
    return c.walls * perWallDb_ + c.insideMetres * perMetreDb_;
}

}  // namespace sbsim::radio
