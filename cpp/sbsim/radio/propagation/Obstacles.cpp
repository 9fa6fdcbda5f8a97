#include "sbsim/radio/propagation/Obstacles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace sbsim::radio {

namespace {

/// Boxes are widened, and a line's cells taken, this much beyond the exact geometry, so that
/// rounding never loses a building whose walls the line crosses (the culling only ever keeps
/// more buildings than cross, never fewer; a kept building that does not cross adds nothing).
constexpr double kMargin = 1e-3;  // m
/// The grid never has more cells than this (a few buildings spread over a huge area).
constexpr double kMaxCells = 4e6;

/// Whether p is inside the ring (even-odd rule; the ring's last point joins its first).
bool inside(const Eigen::Vector2d* ring, std::size_t n, const Eigen::Vector2d& p) {
    bool in = false;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const Eigen::Vector2d& a = ring[i];
        const Eigen::Vector2d& b = ring[j];
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
            in = !in;
    }
    return in;
}

/// The parameter t in [0, 1] along a→b (r = b - a) where it crosses the edge c→d, if it does.
/// The bounds are tested on the numerators, so only a crossing pays a division.
bool cross(const Eigen::Vector2d& a, const Eigen::Vector2d& r, const Eigen::Vector2d& c, const Eigen::Vector2d& d,
           double& t) {
    const Eigen::Vector2d s = d - c;
    double denominator = r.x() * s.y() - r.y() * s.x();
    if (denominator == 0) return false;  // parallel: grazing a wall is not crossing it
    const Eigen::Vector2d q = c - a;
    double tn = q.x() * s.y() - q.y() * s.x();
    double un = q.x() * r.y() - q.y() * r.x();
    if (denominator < 0) {
        denominator = -denominator;
        tn = -tn;
        un = -un;
    }
    // t = tn / den in [0, 1], u = un / den in [0, 1): u < 1, a shared corner counts for one edge.
    if (!(tn >= 0 && tn <= denominator && un >= 0 && un < denominator)) return false;
    t = tn / denominator;
    return true;
}

/// Whether p is inside the box (min x, min y, max x, max y).
bool within(const Eigen::Vector2d& p, const Eigen::Vector4d& box) {
    return p.x() >= box[0] && p.y() >= box[1] && p.x() <= box[2] && p.y() <= box[3];
}

/// The segment a→a+d, with what the slab test needs per box computed once per link.
struct Ray {
    Eigen::Vector2d a, d, inverse;
    Ray(const Eigen::Vector2d& from, const Eigen::Vector2d& delta)
        : a(from), d(delta), inverse(delta.x() != 0 ? 1 / delta.x() : 0, delta.y() != 0 ? 1 / delta.y() : 0) {}

    /// Whether the segment meets the box (min x, min y, max x, max y): the slab test.
    bool meets(const Eigen::Vector4d& box) const {
        double t0 = 0;
        double t1 = 1;
        for (int axis = 0; axis < 2; ++axis) {
            const double lo = box[axis];
            const double hi = box[axis + 2];
            if (d[axis] == 0) {
                if (a[axis] < lo || a[axis] > hi) return false;
                continue;
            }
            double tLo = (lo - a[axis]) * inverse[axis];
            double tHi = (hi - a[axis]) * inverse[axis];
            if (tLo > tHi) std::swap(tLo, tHi);
            t0 = std::max(t0, tLo);
            t1 = std::min(t1, tHi);
            if (t0 > t1) return false;
        }
        return true;
    }
};

/// Per thread: which buildings the current query has seen (a stamp per building, the query's
/// serial number), so a building listed in several of the line's cells is tested once.
struct Seen {
    const void* owner = nullptr;
    std::uint32_t serial = 0;
    std::vector<std::uint32_t> stamp;
    std::vector<double> ts;
    std::vector<std::pair<std::uint32_t, Obstacles::Crossing>> hits;
};

/// This thread's scratch, looked up once per link: a thread_local in a shared library costs a
/// call at each use, and inlined, the compiler repeated that call at each of them.
[[gnu::noinline]] Seen& threadSeen() {
    thread_local Seen seen;
    return seen;
}

}  // namespace

/// Building indices by cell, compressed rows: cell (i, j)'s buildings are
/// items[start[j * nx + i] .. start[j * nx + i + 1]), ascending.
struct Obstacles::Grid {
    double x0 = 0, y0 = 0, cell = 1;
    long nx = 0, ny = 0;
    std::vector<std::uint32_t> start, items;

    long column(double x) const { return clamp(std::floor((x - x0) / cell), nx); }
    long row(double y) const { return clamp(std::floor((y - y0) / cell), ny); }
    static long clamp(double v, long n) { return static_cast<long>(std::clamp(v, 0.0, static_cast<double>(n - 1))); }
};

Obstacles::Obstacles(double perWallDb, double perMetreDb, double cellMetres)
    : perWallDb_(perWallDb), perMetreDb_(perMetreDb), cellMetres_(cellMetres) {
    if (!(perWallDb >= 0) || !(perMetreDb >= 0)) throw std::invalid_argument("obstacle losses must be >= 0 dB");
    if (!(cellMetres >= 0)) throw std::invalid_argument("the obstacle grid's cell must be >= 0 m");
    firstPoint_.push_back(0);
}
Obstacles::~Obstacles() = default;

void Obstacles::add(Shape shape) {
    if (shape.size() >= 2 && shape.front() == shape.back()) shape.pop_back();
    if (shape.size() < 3) return;
    Eigen::Vector4d box(shape[0].x(), shape[0].y(), shape[0].x(), shape[0].y());
    for (const Eigen::Vector2d& p : shape) {
        box = Eigen::Vector4d(std::min(box[0], p.x()), std::min(box[1], p.y()), std::max(box[2], p.x()),
                              std::max(box[3], p.y()));
    }
    boxes_.push_back(box + Eigen::Vector4d(-kMargin, -kMargin, kMargin, kMargin));
    points_.insert(points_.end(), shape.begin(), shape.end());
    firstPoint_.push_back(static_cast<std::uint32_t>(points_.size()));
    gridReady_.store(false, std::memory_order_release);
}

std::size_t Obstacles::size() const { return boxes_.size(); }

double Obstacles::gridCellMetres() const { return grid().cell; }

const Obstacles::Grid& Obstacles::grid() const {
    if (gridReady_.load(std::memory_order_acquire)) return *grid_;
    const std::lock_guard lock(gridMutex_);
    if (gridReady_.load(std::memory_order_relaxed)) return *grid_;
    auto grid = std::make_unique<Grid>();
    const std::size_t n = boxes_.size();
    Eigen::Vector4d bounds(0, 0, 1, 1);
    std::vector<double> sides;
    for (std::size_t k = 0; k < n; ++k) {
        const Eigen::Vector4d& b = boxes_[k];
        bounds = k == 0 ? b
                        : Eigen::Vector4d(std::min(bounds[0], b[0]), std::min(bounds[1], b[1]),
                                          std::max(bounds[2], b[2]), std::max(bounds[3], b[3]));
        sides.push_back(std::max(b[2] - b[0], b[3] - b[1]));
    }
    // A cell about twice a typical building's side: a line's cells list few buildings it misses,
    // and a long line crosses few empty cells (bench/obstacles.py --cell measured 25-100 m).
    double cell = cellMetres_;
    if (cell <= 0) {
        if (sides.empty()) {
            cell = 50;
        } else {
            std::nth_element(sides.begin(), sides.begin() + static_cast<long>(sides.size() / 2), sides.end());
            cell = std::max(2 * sides[sides.size() / 2], 8.0);
        }
    }
    const double width = bounds[2] - bounds[0];
    const double height = bounds[3] - bounds[1];
    while ((std::floor(width / cell) + 1) * (std::floor(height / cell) + 1) > kMaxCells) cell *= 2;
    grid->x0 = bounds[0];
    grid->y0 = bounds[1];
    grid->cell = cell;
    grid->nx = static_cast<long>(std::floor(width / cell)) + 1;
    grid->ny = static_cast<long>(std::floor(height / cell)) + 1;
    // Two passes: count per cell, then place (buildings in ascending order within a cell).
    std::vector<std::uint32_t> count(static_cast<std::size_t>(grid->nx * grid->ny) + 1, 0);
    const auto forCells = [&](const Eigen::Vector4d& b, auto&& f) {
        for (long j = grid->row(b[1]); j <= grid->row(b[3]); ++j) {
            for (long i = grid->column(b[0]); i <= grid->column(b[2]); ++i)
                f(static_cast<std::size_t>(j * grid->nx + i));
        }
    };
    for (std::size_t k = 0; k < n; ++k) forCells(boxes_[k], [&](std::size_t c) { ++count[c + 1]; });
    for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
    grid->start = count;
    grid->items.resize(count.back());
    for (std::size_t k = 0; k < n; ++k) {
        forCells(boxes_[k], [&](std::size_t c) { grid->items[count[c]++] = static_cast<std::uint32_t>(k); });
    }
    grid_ = std::move(grid);
    gridReady_.store(true, std::memory_order_release);
    return *grid_;
}

void Obstacles::addCrossing(std::size_t k, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double length,
                            std::vector<double>& ts, Crossing& total) const {
    const Eigen::Vector2d* ring = points_.data() + firstPoint_[k];
    const std::size_t n = firstPoint_[k + 1] - firstPoint_[k];
    const Eigen::Vector2d r = b - a;
    // A wall whose ends lie both on one side of the line, farther than a micrometre from it,
    // cannot cross it: the side is (p - a) x r, distance times length, one product per corner
    // instead of the full test per wall. The tolerance is far above the rounding of either.
    const double tolerance = 1e-6 * length;
    const auto side = [&](const Eigen::Vector2d& p) { return (p.x() - a.x()) * r.y() - (p.y() - a.y()) * r.x(); };
    const auto apart = [&](double u, double v) {
        return (u > tolerance && v > tolerance) || (u < -tolerance && v < -tolerance);
    };
    ts.clear();
    const double first = side(ring[0]);
    double here = first;
    for (std::size_t i = 0; i < n; ++i) {
        const double next = i + 1 == n ? first : side(ring[i + 1]);
        double t = 0;
        if (!apart(here, next) && cross(a, r, ring[i], ring[i + 1 == n ? 0 : i + 1], t)) ts.push_back(t);
        here = next;
    }
    // Outside the (widened) box, the even-odd walk cannot find a inside: no need to walk.
    const bool startsInside = within(a, boxes_[k]) && inside(ring, n, a);
    if (ts.empty() && !startsInside) return;
    for (std::size_t i = 1; i < ts.size(); ++i) {  // a few crossings: insertion sort
        for (std::size_t j = i; j > 0 && ts[j] < ts[j - 1]; --j) std::swap(ts[j], ts[j - 1]);
    }
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

namespace {
/// Whether the link is walked from b: the lesser end (by x, then y) is its start, so the result is
/// the same from either end to the bit, and a pair's loss computed once serves both ways.
bool reversed(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return b.x() < a.x() || (b.x() == a.x() && b.y() < a.y());
}
}  // namespace

Obstacles::Crossing Obstacles::crossingEveryBuilding(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
    if (reversed(a, b)) return crossingEveryBuilding(b, a);
    Crossing total;
    const double length = (b - a).norm();
    std::vector<double> ts;
    for (std::size_t k = 0; k < size(); ++k) {
        Crossing one;
        addCrossing(k, a, b, length, ts, one);
        total.walls += one.walls;
        total.insideMetres += one.insideMetres;
    }
    return total;
}

Obstacles::Crossing Obstacles::crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b, int stopAtWalls) const {
    if (reversed(a, b)) return crossing(b, a, stopAtWalls);
    linksEvaluated_.fetch_add(1, std::memory_order_relaxed);
    Crossing total;
    if (boxes_.empty()) return total;
    const Grid& g = grid();
    Seen& seen = threadSeen();
    if (seen.owner != this || seen.stamp.size() != boxes_.size()) {
        seen.owner = this;
        seen.serial = 0;
        seen.stamp.assign(boxes_.size(), 0);
    }
    if (++seen.serial == 0) {  // wrapped: every stamp could look current
        std::fill(seen.stamp.begin(), seen.stamp.end(), 0);
        seen.serial = 1;
    }
    seen.hits.clear();
    const Eigen::Vector2d d = b - a;
    const Ray ray(a, d);
    const double length = d.norm();
    const double yLow = std::min(a.y(), b.y());
    const double yHigh = std::max(a.y(), b.y());
    const double xLow = std::min(a.x(), b.x());
    const double xHigh = std::max(a.x(), b.x());
    // Outside the grid's bounds entirely: no building's box.
    if (yHigh < g.y0 || xHigh < g.x0 || yLow > g.y0 + static_cast<double>(g.ny) * g.cell ||
        xLow > g.x0 + static_cast<double>(g.nx) * g.cell)
        return total;
    // Plain pointers: the stamps' stores would otherwise make the compiler reload the grid's.
    const std::uint32_t* start = g.start.data();
    const std::uint32_t* items = g.items.data();
    const Eigen::Vector4d* boxes = boxes_.data();
    std::uint32_t* stamp = seen.stamp.data();
    const std::uint32_t serial = seen.serial;
    int wallsFound = 0;
    // Band by band of cells across the line's lesser extent (rows for a line more along x than
    // y, else columns), the stretch of the other axis it covers within the band, widened by the
    // margin: a cell's index along an axis as the grid placed the boxes by.
    const int v = std::abs(d.y()) <= std::abs(d.x()) ? 1 : 0;  // the bands' axis
    const int u = 1 - v;
    const double origin[2] = {g.x0, g.y0};
    const long count[2] = {g.nx, g.ny};
    const std::size_t stride[2] = {1, static_cast<std::size_t>(g.nx)};
    const double low[2] = {xLow, yLow};
    const double high[2] = {xHigh, yHigh};
    const auto index = [&](int axis, double value) {
        return Grid::clamp(std::floor((value - origin[axis]) / g.cell), count[axis]);
    };
    const double slope = d[v] != 0 ? d[u] / d[v] : 0;
    const long lastBand = index(v, high[v]);
    for (long j = index(v, low[v]); j <= lastBand; ++j) {
        double from = low[u];
        double to = high[u];
        if (d[v] != 0) {
            const double v0 = std::max(low[v], origin[v] + static_cast<double>(j) * g.cell);
            const double v1 = std::min(high[v], origin[v] + static_cast<double>(j + 1) * g.cell);
            from = a[u] + (v0 - a[v]) * slope;
            to = a[u] + (v1 - a[v]) * slope;
            if (from > to) std::swap(from, to);
            from = std::max(from, low[u]);
            to = std::min(to, high[u]);
        }
        const long last = index(u, to + kMargin);
        const std::size_t bandStart = static_cast<std::size_t>(j) * stride[v];
        for (long i = index(u, from - kMargin); i <= last; ++i) {
            const std::size_t c = bandStart + static_cast<std::size_t>(i) * stride[u];
            for (std::uint32_t m = start[c], end = start[c + 1]; m < end; ++m) {
                const std::uint32_t k = items[m];
                if (stamp[k] == serial) continue;
                stamp[k] = serial;
                if (!ray.meets(boxes[k])) continue;
                Crossing one;
                addCrossing(k, a, b, length, seen.ts, one);
                if (one.walls > 0 || one.insideMetres != 0) {
                    seen.hits.emplace_back(k, one);
                    wallsFound += one.walls;
                    if (wallsFound >= stopAtWalls) return {wallsFound, 0};  // partial: see the header
                }
            }
        }
    }
    // Summed in the buildings' order, as crossingEveryBuilding() does: the same result to the bit.
    auto& hits = seen.hits;
    for (std::size_t i = 1; i < hits.size(); ++i) {  // a few buildings: insertion sort
        for (std::size_t j = i; j > 0 && hits[j].first < hits[j - 1].first; --j) std::swap(hits[j], hits[j - 1]);
    }
    for (const auto& [k, one] : seen.hits) {
        total.walls += one.walls;
        total.insideMetres += one.insideMetres;
    }
    return total;
}

double Obstacles::lossDb(const Eigen::Vector2d& a, const Eigen::Vector2d& b, int stopAtWalls) const {
    const Crossing c = crossing(a, b, stopAtWalls);
    return c.walls * perWallDb_ + c.insideMetres * perMetreDb_;
}

}  // namespace sbsim::radio
