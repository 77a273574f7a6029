// ExplicitCollision: the explicit geometric droplet-fiber collision count that the
// stochastic grid method replaces (Schroeder et al. 2011, sec. 1 and 6: "simulate each
// droplet and each fiber separately, calculating their collisions geometrically"). A
// reference for the benchmarks only, not part of the core.
//
// Test: a droplet of radius r_p hits a fiber of radius r_F during a step when the distance
// between its path during the step (a segment, Parcel convention: from position - v dt to
// position) and a fiber segment is below r_F + r_p (segment-segment distance, Ericson,
// Real-Time Collision Detection, sec. 5.1.9).
//
// Counting a passage once: a droplet passing a fiber is within r_F + r_p of it for
// several steps when the path per step is shorter than the fiber's diameter, and near a
// joint of two segments it is within reach of both. So a droplet hits a fiber in the step
// that holds its closest approach to the fiber: the smallest distance from the step's path
// to all segments of the fiber is below r_F + r_p and is attained at an interior point of
// the path (0 < s < 1); it is assigned to the segment that attains it. Each straight passage
// is then counted exactly once, and the expected count equals eq. 9's (up to the ends of the
// fiber's silhouette, O(r / fiber size)).
//
// Two implementations with identical results:
//   BruteForce - every droplet path against every fiber segment;
//   SegmentHash - the segments are binned in a uniform grid of cubic cells (each segment in
//                 every cell its bounding box, grown by the collision radius, overlaps);
//                 a droplet path is tested only against the segments of the cells its own
//                 bounding box overlaps, each segment once (a stamp per segment).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace bench
{

struct ClosestPoints
{
    double distanceSquared;
    double s; // parameter on the first segment (the droplet path), in [0, 1]
    double t; // parameter on the second segment (the fiber segment), in [0, 1]
};

// Closest points of segments p1 + s d1 and p2 + t d2, s, t in [0, 1] (Ericson 5.1.9).
inline ClosestPoints closestPointsSegmentSegment(const Eigen::Vector3d& p1, const Eigen::Vector3d& d1,
                                                 const Eigen::Vector3d& p2, const Eigen::Vector3d& d2)
{
    constexpr double eps = 1e-300;
    const Eigen::Vector3d r = p1 - p2;
    const double a = d1.squaredNorm();
    const double e = d2.squaredNorm();
    const double f = d2.dot(r);
    double s = 0.0, t = 0.0;
    if (a <= eps && e <= eps)
    {
        return {r.squaredNorm(), 0.0, 0.0};
    }
    if (a <= eps)
    {
        t = std::clamp(f / e, 0.0, 1.0);
    }
    else
    {
        const double c = d1.dot(r);
        if (e <= eps)
        {
            s = std::clamp(-c / a, 0.0, 1.0);
        }
        else
        {
            const double b = d1.dot(d2);
            const double denominator = a * e - b * b;
            s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0)
            {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            }
            else if (t > 1.0)
            {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return {(p1 + s * d1 - (p2 + t * d2)).squaredNorm(), s, t};
}

// Fiber segments of all fibers, flat.
struct FiberSegments
{
    std::vector<Eigen::Vector3d> start;
    std::vector<Eigen::Vector3d> vector; // end - start
    std::vector<int> fiber;              // fiber index of each segment
    std::size_t size() const { return start.size(); }
    void add(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int fiberIndex)
    {
        start.push_back(a);
        vector.push_back(b - a);
        fiber.push_back(fiberIndex);
    }
};

// Result of one droplet path against the fibers: the segment that holds the closest
// approach, or -1 when the droplet does not hit (by the rule in the header).
struct PathHit
{
    int segment = -1;
};

// Tracks the closest approach per fiber while candidate segments are tested.
class ClosestApproach
{
public:
    void reset() { best_.clear(); }
    void offer(int fiber, int segment, const ClosestPoints& c)
    {
        for (Entry& e : best_)
        {
            if (e.fiber == fiber)
            {
                if (c.distanceSquared < e.distanceSquared)
                {
                    e = {fiber, segment, c.distanceSquared, c.s};
                }
                return;
            }
        }
        best_.push_back({fiber, segment, c.distanceSquared, c.s});
    }
    // Calls hit(segment) for every fiber whose closest approach is a hit.
    template <class OnHit>
    void collect(double reachSquared, OnHit&& hit) const
    {
        for (const Entry& e : best_)
        {
            if (e.distanceSquared < reachSquared && e.s > 0.0 && e.s < 1.0)
            {
                hit(e.segment);
            }
        }
    }

private:
    struct Entry
    {
        int fiber;
        int segment;
        double distanceSquared;
        double s;
    };
    std::vector<Entry> best_;
};

class BruteForce
{
public:
    explicit BruteForce(const FiberSegments& segments) : segments_(segments) {}

    // path from `start` along `displacement`; reach = r_F + r_p
    template <class OnHit>
    void query(const Eigen::Vector3d& start, const Eigen::Vector3d& displacement, double reach, OnHit&& hit)
    {
        approach_.reset();
        const double reachSquared = reach * reach;
        for (std::size_t k = 0; k < segments_.size(); ++k)
        {
            const ClosestPoints c
                = closestPointsSegmentSegment(start, displacement, segments_.start[k], segments_.vector[k]);
            if (c.distanceSquared < reachSquared)
            {
                approach_.offer(segments_.fiber[k], static_cast<int>(k), c);
            }
        }
        approach_.collect(reachSquared, hit);
    }

private:
    const FiberSegments& segments_;
    ClosestApproach approach_;
};

// A candidate within reach of the path near a segment's end is only a candidate: the
// closest approach to the fiber may lie on its neighbour. For the closest-approach rule
// all segments within reach of the path must be offered, which both classes do.
class SegmentHash
{
public:
    // lower/upper: the region to bin (droplet paths outside it are clipped to its cells);
    // cell: edge of the cubic cells; reachMax: largest r_F + r_p that will be queried.
    SegmentHash(const FiberSegments& segments, const Eigen::Vector3d& lower, const Eigen::Vector3d& upper,
                double cell, double reachMax)
        : segments_(segments), lower_(lower), inverseCell_(1.0 / cell)
    {
        for (int d = 0; d < 3; ++d)
        {
            dims_[d] = std::max(1, static_cast<int>(std::ceil((upper[d] - lower[d]) * inverseCell_)));
        }
        const std::size_t cells = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
        offsets_.assign(cells + 1, 0);
        stamp_.assign(segments.size(), -1);
        // two passes: count, then fill (CSR)
        for (int pass = 0; pass < 2; ++pass)
        {
            std::vector<std::uint32_t> cursor;
            if (pass == 1)
            {
                for (std::size_t c = 0; c < cells; ++c)
                {
                    offsets_[c + 1] += offsets_[c];
                }
                items_.resize(offsets_[cells]);
                cursor.assign(offsets_.begin(), offsets_.end() - 1);
            }
            for (std::size_t k = 0; k < segments.size(); ++k)
            {
                const Eigen::Vector3d a = segments.start[k];
                const Eigen::Vector3d b = a + segments.vector[k];
                std::array<int, 3> lo{}, hi{};
                cellRange(a.cwiseMin(b).array() - reachMax, a.cwiseMax(b).array() + reachMax, lo, hi);
                for (int z = lo[2]; z <= hi[2]; ++z)
                {
                    for (int y = lo[1]; y <= hi[1]; ++y)
                    {
                        for (int x = lo[0]; x <= hi[0]; ++x)
                        {
                            const std::size_t c = flat(x, y, z);
                            if (pass == 0)
                            {
                                ++offsets_[c + 1];
                            }
                            else
                            {
                                items_[cursor[c]++] = static_cast<std::uint32_t>(k);
                            }
                        }
                    }
                }
            }
        }
    }

    template <class OnHit>
    void query(const Eigen::Vector3d& start, const Eigen::Vector3d& displacement, double reach, OnHit&& hit)
    {
        ++queryId_;
        const Eigen::Vector3d end = start + displacement;
        std::array<int, 3> lo{}, hi{};
        cellRange(start.cwiseMin(end), start.cwiseMax(end), lo, hi);
        const double reachSquared = reach * reach;
        bool any = false;
        for (int z = lo[2]; z <= hi[2]; ++z)
        {
            for (int y = lo[1]; y <= hi[1]; ++y)
            {
                for (int x = lo[0]; x <= hi[0]; ++x)
                {
                    const std::size_t c = flat(x, y, z);
                    for (std::uint32_t i = offsets_[c]; i < offsets_[c + 1]; ++i)
                    {
                        const std::uint32_t k = items_[i];
                        if (stamp_[k] == queryId_)
                        {
                            continue;
                        }
                        stamp_[k] = queryId_;
                        const ClosestPoints cp = closestPointsSegmentSegment(
                            start, displacement, segments_.start[k], segments_.vector[k]);
                        if (cp.distanceSquared < reachSquared)
                        {
                            if (!any)
                            {
                                approach_.reset();
                                any = true;
                            }
                            approach_.offer(segments_.fiber[k], static_cast<int>(k), cp);
                        }
                    }
                }
            }
        }
        if (any)
        {
            approach_.collect(reachSquared, hit);
        }
    }

    std::size_t storedEntries() const { return items_.size(); }

private:
    template <class V1, class V2>
    void cellRange(const V1& low, const V2& high, std::array<int, 3>& lo, std::array<int, 3>& hi) const
    {
        for (int d = 0; d < 3; ++d)
        {
            lo[d] = std::clamp(static_cast<int>(std::floor((low[d] - lower_[d]) * inverseCell_)), 0,
                               dims_[d] - 1);
            hi[d] = std::clamp(static_cast<int>(std::floor((high[d] - lower_[d]) * inverseCell_)), 0,
                               dims_[d] - 1);
        }
    }
    std::size_t flat(int x, int y, int z) const
    {
        return static_cast<std::size_t>(x)
            + static_cast<std::size_t>(dims_[0]) * (y + static_cast<std::size_t>(dims_[1]) * z);
    }

    const FiberSegments& segments_;
    Eigen::Vector3d lower_;
    double inverseCell_;
    std::array<int, 3> dims_{};
    std::vector<std::uint32_t> offsets_;
    std::vector<std::uint32_t> items_;
    std::vector<std::int64_t> stamp_;
    std::int64_t queryId_ = 0;
    ClosestApproach approach_;
};

} // namespace bench
