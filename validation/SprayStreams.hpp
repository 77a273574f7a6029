// SprayStreams: the paper's spray (sec. 6): parallel streams injected at the top of the box
// over [-2.49, 2.49] cm, moving straight down at constant speed, in steady state.
//
// Stream i (of N) sits at the centre of its strip of the injection width W:
//     x_i = -W/2 + (i + 1/2) s,    s = W / N,
// so the streams stand for a spray spread uniformly over W: mass density
//     rho = (mass injected per unit time) / (W * speed * depth),
// the analytic density of the validation. Parcel k of a stream is injected at
// t_k = (k + phase) * injectionInterval; at the end of step n (time n dt) it is at
// y = yInjection - speed (n dt - t_k). Injection has gone on forever, so every step is
// already in steady state (no spin-up to simulate). With injectionInterval = dt the paths
// of successive parcels tile the stream line exactly.
//
// Randomness per parcel (polydisperse radius, lateral jitter) comes from a hash of
// (seed, stream, k), so a parcel keeps its properties from step to step and any step can
// be produced on its own.
#pragma once

#include "grid/Parcel.hpp"

#include <cstdint>
#include <vector>

namespace dropletFiber
{
namespace validation
{

struct SprayDefinition
{
    int streams = 100;
    double injectionHalfWidth = 0.0249;
    double yInjection = 0.07;
    double speed = 1.0; // downward
    double dt = 1e-3;
    double injectionInterval = 1e-3;
    double injectionPhase = 0.37;
    double zMid = 0.0; // slab centre (flat direction of the grid)
    double dropletDensity = 1000.0;

    // Monodisperse: every parcel has dropletsPerParcel droplets of dropletRadius.
    double dropletRadius = 1e-5;
    double dropletsPerParcel = 10.0; // may be fractional (O'Rourke parcels)

    // Polydisperse (when radiusHigh > radiusLow): each parcel carries parcelMass, its radius
    // is uniform in [radiusLow, radiusHigh], n = parcelMass / m(r).
    bool polydisperse = false;
    double radiusLow = 0.0, radiusHigh = 0.0, parcelMass = 0.0;

    // Lateral jitter: each parcel is injected at a uniformly random x within its stream's
    // strip [x_i - s/2, x_i + s/2] (the uniform spray the streams stand for).
    bool jitter = false;
    std::uint64_t seed = 0;
};

// One parcel and its identity (for per-droplet random numbers of the geometric count).
struct SprayParcel
{
    Parcel parcel;
    std::uint64_t id = 0;
};

class SprayStreams
{
public:
    explicit SprayStreams(const SprayDefinition& definition);

    const SprayDefinition& definition() const { return def_; }
    double streamSpacing() const { return spacing_; }
    double streamX(int stream) const;
    // Expected droplet mass injected per step in all streams, kg (the flow rate times dt).
    double massPerStep() const;
    // Mass-weighted and number-weighted mean radius of the injected droplets (analytic).
    double meanRadiusMass() const;
    double meanRadiusNumber() const;
    // Analytic mass density of the spray below the injection, kg/m^3, for a slab of `depth`.
    double analyticDensity(double depth) const;

    // Parcels at the end of step `step` whose path during the step (from position -
    // velocity dt to position) reaches into [yLow, yHigh] and whose stream lies within
    // [xLow, xHigh] (widened by the jitter when on). Parcels not yet injected at the end of
    // the step are left out; a parcel injected during the step has a path that starts above
    // the injection height (outside the box: the grid deposits the share of the step spent
    // inside).
    std::vector<SprayParcel> parcels(std::int64_t step, double xLow, double xHigh, double yLow,
                                     double yHigh) const;
    // All parcels in the box [yLow, yInjection].
    std::vector<SprayParcel> parcels(std::int64_t step, double yLow) const;

private:
    SprayDefinition def_;
    double spacing_;
};

// Deterministic uniform numbers in [0, 1) from a key (splitmix64 mixing).
double hashUniform(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t d);

} // namespace validation
} // namespace dropletFiber
