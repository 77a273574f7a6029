// TurbulentAir: the turbulent velocity fluctuation u' the fibers' drag sees on top of
// the mean air velocity of a RANS (or LES) case (docs/model.md sec. 8, eqs. P24-P28). Per fiber point
// an isotropic Ornstein-Uhlenbeck velocity: zero mean, variance sigma^2 = 2k/3 per
// component, autocorrelation exp(-tau/T_L) in time with T_L = C_T k/epsilon, and
// correlation exp(-|s - s'|/L) along the fiber's arc length s with L = C_L k^(3/2)/epsilon.
// The update over a step dt is exact for the Ornstein-Uhlenbeck process at any dt:
//     u'_{n+1} = a u'_n + sqrt(1 - a^2) sigma eta,   a = exp(-dt/T_L),
// with eta unit normal innovations correlated along the fiber by the AR(1) filter
//     eta_0 = xi_0,  eta_i = r_i eta_{i-1} + sqrt(1 - r_i^2) xi_i,  r_i = exp(-l_{i-1}/L_i)
// (xi independent unit normals, l_{i-1} the rest length between points i-1 and i), which
// keeps every eta_i of unit variance and costs O(points). A fiber without a state yet
// (born this step, or restarted from a state written without turbulence) starts from the
// stationary distribution (a = 0). The xi are drawn by CounterRandom, keyed by (seed,
// fiber id, point, step), so the realisation does not depend on the decomposition, the
// order fibers are processed in, or restarts. k = 0 gives u' = 0 exactly.
#pragma once

#include "fiber/Fiber.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace dropletFiber
{

enum class TurbulenceModelType
{
    none,
    ornsteinUhlenbeck
};

struct TurbulenceSettings
{
    TurbulenceModelType model = TurbulenceModelType::none;
    // T_L = timeScaleCoeff k/epsilon. 0.5: the Lagrangian integral time of OpenFOAM's
    // stochasticDispersionRAS eddies (velocity held for k/epsilon, triangular
    // autocorrelation of integral k/(2 epsilon)), so fibers and droplets of one case
    // disperse alike (docs/model.md sec. 8).
    double timeScaleCoeff = 0.5;
    // L = lengthScaleCoeff k^(3/2)/epsilon. C_mu^(3/4) = 0.16432: the eddy size of the
    // same model (its cps) and the dissipation length of k-epsilon.
    double lengthScaleCoeff = 0.16432;
    std::uint32_t seed = 0;
};

// k and epsilon at points, laid out as AirSample (fiber order, then point order).
struct TurbulenceSample
{
    Eigen::VectorXd kineticEnergy; // k [m^2/s^2]
    Eigen::VectorXd dissipation;   // epsilon [m^2/s^3]

    Eigen::Index pointCount() const { return kineticEnergy.size(); }
};

// Advances one fiber's u' (its FiberState::turbulentVelocity) over dt to step `step`,
// with k and epsilon of its points (n values each, negative values taken as 0).
void advanceTurbulentVelocity(FiberState& state, const TurbulenceSettings& settings,
                              const Eigen::Ref<const Eigen::VectorXd>& kineticEnergy,
                              const Eigen::Ref<const Eigen::VectorXd>& dissipation, std::uint64_t fiberId,
                              std::uint64_t step, double dt);

// The same for all movable fibers, fiberIds[f] naming fibers[f]; sample laid out as
// airSamplePoints(fibers). Model none: every fiber's u' is dropped (a run switched to
// none, or restarted with none from a turbulent state, sees the mean air only). Throws
// std::invalid_argument on a sample or id list that does not fit.
void advanceTurbulentVelocities(std::vector<Fiber>& fibers, const std::vector<std::uint64_t>& fiberIds,
                                const TurbulenceSample& sample, const TurbulenceSettings& settings,
                                std::uint64_t step, double dt);

// Drops every fiber's u' (FiberState::turbulentVelocity emptied).
void clearTurbulentVelocities(std::vector<Fiber>& fibers);

TurbulenceModelType turbulenceModelFromName(const std::string& name); // throws on unknown
std::string turbulenceModelName(TurbulenceModelType model);

} // namespace dropletFiber
