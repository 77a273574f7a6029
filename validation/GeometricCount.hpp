// GeometricCount: the explicit reference of the paper's sec. 6 - count the droplets whose
// path during a step enters the fiber, times their mass.
//
// A droplet of radius r hits the fiber (circle of radius r_F) when its centre comes within
// r_F + r of the fiber's centre. It is counted in the step in which its path (straight,
// from position - velocity dt to position) enters the circle of radius r_F + r: the start
// lies outside, some point of the path inside. No depletion (the paper does none): the
// droplet flies on and is counted once per pass.
//
// Two ways to place a parcel's droplets:
//   ParcelPoint - all n droplets at the parcel's position (the paper's geometric method);
//   Spread      - ceil(n) droplets (each n/ceil(n) of a droplet's mass) at fixed random
//                 offsets, uniform in the disc of radius r_min (eq. 14, the parcel's
//                 densest-packing extent), drawn per parcel and droplet from the seed.
// With SprayDefinition::jitter, Spread also moves each parcel to a random x within its
// stream's strip: the count then samples the uniform spray the streams stand for, and its
// mean over seeds converges to the analytic expected mass (the fine reference).
#pragma once

#include "FiberCircle.hpp"
#include "SprayStreams.hpp"

#include <cstdint>
#include <vector>

namespace dropletFiber
{
namespace validation
{

enum class DropletPlacement
{
    ParcelPoint,
    Spread
};

// True when the path from start to end enters the circle (centre c, radius R): the start
// is outside (|start - c| >= R) and the path's closest point to c is inside (< R).
bool pathEntersCircle(const Eigen::Vector2d& start, const Eigen::Vector2d& end, const Eigen::Vector2d& centre,
                      double radius);

// Mass entering the fiber during one step from the given parcels (positions at the end of
// the step). seed: the droplet offsets of Spread.
double geometricStepMass(const std::vector<SprayParcel>& parcels, const FiberCircle& fiber, double dt,
                         DropletPlacement placement, std::uint64_t seed);

// Mean and standard error of a sample.
struct MeanAndError
{
    double mean = 0.0;
    double standardError = 0.0;
    int samples = 0;
};

// The count over `steps` consecutive steps (from step 0) per seed, for `seeds` seeds
// (the spray's seed and the droplet offsets change together); the mean per step of each
// seed is one sample. Only parcels that can reach the fiber are generated.
MeanAndError geometricMass(const SprayDefinition& spray, const FiberCircle& fiber, DropletPlacement placement,
                           int seeds, int steps);

} // namespace validation
} // namespace dropletFiber
