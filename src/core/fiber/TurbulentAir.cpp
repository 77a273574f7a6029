#include "fiber/TurbulentAir.hpp"

#include "fiber/AirSample.hpp"
#include "fiber/CounterRandom.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dropletFiber
{

namespace
{

// exp(-x / scale) with scale = coeff * k^power / epsilon, written without dividing by
// epsilon (epsilon = 0: scale infinite, factor 1) and 0 where k = 0 (no turbulence:
// nothing to remember, nothing correlated).
double decayFactor(double x, double coeff, double k, double power, double epsilon)
{
    if (!(k > 0.0))
        return 0.0;
    return std::exp(-x * epsilon / (coeff * std::pow(k, power)));
}

} // namespace

void advanceTurbulentVelocity(FiberState& state, const TurbulenceSettings& settings,
                              const Eigen::Ref<const Eigen::VectorXd>& kineticEnergy,
                              const Eigen::Ref<const Eigen::VectorXd>& dissipation, std::uint64_t fiberId,
                              std::uint64_t step, double dt)
{
    const Eigen::Index n = state.positions.cols();
    if (kineticEnergy.size() != n || dissipation.size() != n)
        throw std::invalid_argument("advanceTurbulentVelocity: k and epsilon needed at every point");
    const bool fresh = state.turbulentVelocity.cols() != n;
    if (fresh)
        state.turbulentVelocity = Eigen::Matrix3Xd::Zero(3, n);
    Eigen::Vector3d eta = Eigen::Vector3d::Zero();
    for (Eigen::Index i = 0; i < n; ++i)
    {
        const double k = std::max(kineticEnergy(i), 0.0);
        const double epsilon = std::max(dissipation(i), 0.0);
        const std::array<double, 4> g = fiberPointGaussians(settings.seed, fiberId, std::uint32_t(i), step);
        const Eigen::Vector3d xi(g[0], g[1], g[2]);
        const double r = i == 0
            ? 0.0
            : decayFactor(state.restLengths(i - 1), settings.lengthScaleCoeff, k, 1.5, epsilon);
        eta = r * eta + std::sqrt(1.0 - r * r) * xi;
        const double a = fresh ? 0.0 : decayFactor(dt, settings.timeScaleCoeff, k, 1.0, epsilon);
        const double sigma = std::sqrt(2.0 * k / 3.0);
        state.turbulentVelocity.col(i)
            = a * state.turbulentVelocity.col(i) + std::sqrt(1.0 - a * a) * sigma * eta;
    }
}

void advanceTurbulentVelocities(std::vector<Fiber>& fibers, const std::vector<std::uint64_t>& fiberIds,
                                const TurbulenceSample& sample, const TurbulenceSettings& settings,
                                std::uint64_t step, double dt)
{
    if (settings.model == TurbulenceModelType::none)
    {
        clearTurbulentVelocities(fibers);
        return;
    }
    const AirSampleLayout layout = airSampleLayout(fibers);
    if (fiberIds.size() != fibers.size())
        throw std::invalid_argument("advanceTurbulentVelocities: one id per fiber expected");
    if (sample.pointCount() != layout.pointCount || sample.dissipation.size() != layout.pointCount)
    {
        throw std::invalid_argument("advanceTurbulentVelocities: k and epsilon needed at the "
                                    + std::to_string(layout.pointCount) + " points of airSamplePoints");
    }
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        const Eigen::Index n = airSamplePointCount(fibers[f]);
        if (n == 0)
            continue;
        const Eigen::Index first = layout.firstPoint[f];
        advanceTurbulentVelocity(fibers[f].mutableState(), settings, sample.kineticEnergy.segment(first, n),
                                 sample.dissipation.segment(first, n), fiberIds[f], step, dt);
    }
}

void clearTurbulentVelocities(std::vector<Fiber>& fibers)
{
    for (Fiber& fiber : fibers)
        fiber.mutableState().turbulentVelocity.resize(3, 0);
}

TurbulenceModelType turbulenceModelFromName(const std::string& name)
{
    if (name == "none")
        return TurbulenceModelType::none;
    if (name == "ornsteinUhlenbeck")
        return TurbulenceModelType::ornsteinUhlenbeck;
    throw std::invalid_argument("unknown fiber turbulence model '" + name
                                + "' (valid: none ornsteinUhlenbeck)");
}

std::string turbulenceModelName(TurbulenceModelType model)
{
    return model == TurbulenceModelType::ornsteinUhlenbeck ? "ornsteinUhlenbeck" : "none";
}

} // namespace dropletFiber
