#include "fiber/Fiber.hpp"

#include "fiber/VelocityProjection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

Fiber::Fiber(const Eigen::Matrix3Xd& points, const FiberMaterial& material, const EndCondition& startEnd,
             const EndCondition& endEnd)
{
    if (points.cols() < 2)
    {
        throw std::invalid_argument("Fiber: needs at least 2 points");
    }
    const Eigen::Index n = points.cols();
    state_.positions = points;
    state_.velocities = Eigen::Matrix3Xd::Zero(3, n);
    state_.restLengths.resize(n - 1);
    for (Eigen::Index j = 0; j + 1 < n; ++j)
    {
        state_.restLengths(j) = (points.col(j + 1) - points.col(j)).norm();
    }
    state_.segmentCapturedMass = Eigen::VectorXd::Zero(n - 1);
    state_.segmentHits = Eigen::VectorXd::Zero(n - 1);
    state_.segmentExpectedMass = Eigen::VectorXd::Zero(n - 1);
    state_.tension = Eigen::VectorXd::Zero(n - 1);
    state_.externalForce = Eigen::Matrix3Xd::Zero(3, n);
    state_.material = material;
    state_.startEnd = startEnd;
    state_.endEnd = endEnd;
    completeClampDirections();
    validate();
    projectVelocities(*this); // held ends may move: start with consistent velocities
}

Fiber Fiber::immobileFiber(const Eigen::Matrix3Xd& points, const FiberMaterial& material)
{
    Fiber fiber(points, material);
    fiber.state_.immobile = true;
    return fiber;
}

Fiber::Fiber(const FiberState& state) : state_(state)
{
    if (state_.segmentHits.size() == 0 && state_.positions.cols() > 1)
    {
        state_.segmentHits = Eigen::VectorXd::Zero(state_.positions.cols() - 1);
    }
    if (state_.segmentExpectedMass.size() == 0)
    {
        state_.segmentExpectedMass = state_.segmentCapturedMass;
    }
    validate();
}

void Fiber::completeClampDirections()
{
    const Eigen::Index n = pointCount();
    if (state_.startEnd.type == EndType::clamped && state_.startEnd.clampDirection.isZero())
    {
        state_.startEnd.clampDirection = (state_.positions.col(1) - state_.positions.col(0)).normalized();
    }
    if (state_.endEnd.type == EndType::clamped && state_.endEnd.clampDirection.isZero())
    {
        state_.endEnd.clampDirection
            = (state_.positions.col(n - 1) - state_.positions.col(n - 2)).normalized();
    }
    for (EndCondition* end : {&state_.startEnd, &state_.endEnd})
    {
        if (end->type == EndType::clamped)
        {
            end->clampDirection.normalize();
        }
    }
}

void Fiber::validate() const
{
    const Eigen::Index n = state_.positions.cols();
    auto fail = [](const std::string& what) { throw std::invalid_argument("Fiber: " + what); };
    if (n < 2)
        fail("needs at least 2 points");
    if (state_.velocities.cols() != n)
        fail("velocities: wrong number of points");
    if (state_.externalForce.cols() != n)
        fail("externalForce: wrong number of points");
    if (state_.restLengths.size() != n - 1)
        fail("restLengths: wrong number of segments");
    if (state_.turbulentVelocity.cols() != 0 && state_.turbulentVelocity.cols() != n)
        fail("turbulentVelocity: wrong number of points (none or one per point)");
    if (state_.segmentCapturedMass.size() != n - 1)
        fail("segmentCapturedMass: wrong number of segments");
    if (state_.tension.size() != n - 1)
        fail("tension: wrong number of segments");
    if (state_.segmentHits.size() != n - 1)
        fail("segmentHits: wrong number of segments");
    if (state_.segmentHits.size() > 0 && state_.segmentHits.minCoeff() < 0.0)
        fail("negative hit count");
    if (state_.segmentExpectedMass.size() != n - 1)
        fail("segmentExpectedMass: wrong number of segments");
    if (state_.segmentExpectedMass.size() > 0 && state_.segmentExpectedMass.minCoeff() < 0.0)
        fail("negative expected mass");
    if (!(state_.restLengths.minCoeff() > 0.0))
        fail("zero-length segment (coincident points)");
    if (!(state_.material.radius > 0.0))
        fail("radius must be > 0");
    if (!(state_.material.density > 0.0))
        fail("density must be > 0");
    if (!(state_.material.youngsModulus >= 0.0))
        fail("Young's modulus must be >= 0");
    if (state_.segmentCapturedMass.minCoeff() < 0.0)
        fail("negative captured mass");
    if (!(state_.represents > 0.0) || !std::isfinite(state_.represents))
        fail("represents (the physical fibers it stands for) must be finite and > 0");
    for (const EndCondition* end : {&state_.startEnd, &state_.endEnd})
    {
        if (end->type == EndType::clamped && std::abs(end->clampDirection.norm() - 1.0) > 1e-12)
        {
            fail("clamp direction must be a unit vector");
        }
    }
}

void Fiber::setRepresents(double n)
{
    if (!(n > 0.0) || !std::isfinite(n))
    {
        throw std::invalid_argument(
            "Fiber: represents (the physical fibers it stands for) must be finite and > 0, got "
            + std::to_string(n));
    }
    state_.represents = n;
}

void Fiber::setPopulationSpread(double H)
{
    if (!(H >= 0.0) || !std::isfinite(H))
    {
        throw std::invalid_argument("Fiber: the population's spread must be finite and >= 0, got "
                                    + std::to_string(H));
    }
    state_.populationSpread = H;
}

void Fiber::setVelocities(const Eigen::Matrix3Xd& velocities)
{
    if (velocities.cols() != pointCount())
    {
        throw std::invalid_argument("Fiber::setVelocities: wrong number of points");
    }
    state_.velocities = velocities;
    projectVelocities(*this);
}

void Fiber::setExternalForce(const Eigen::Matrix3Xd& force)
{
    if (force.cols() != pointCount())
    {
        throw std::invalid_argument("Fiber::setExternalForce: wrong number of points");
    }
    state_.externalForce = force;
}

bool Fiber::pointHeld(Eigen::Index i) const
{
    if (state_.immobile)
        return true;
    if (i == 0 && state_.startEnd.holdsPosition())
        return true;
    if (i == pointCount() - 1 && state_.endEnd.holdsPosition())
        return true;
    return false;
}

Eigen::Vector3d Fiber::heldPointVelocity(Eigen::Index i) const
{
    if (state_.immobile)
        return Eigen::Vector3d::Zero();
    if (i == 0 && state_.startEnd.holdsPosition())
        return state_.startEnd.anchorVelocity;
    if (i == pointCount() - 1 && state_.endEnd.holdsPosition())
        return state_.endEnd.anchorVelocity;
    return Eigen::Vector3d::Zero();
}

namespace
{

// Lumps a per-segment quantity onto the points: half of segment j to each of its ends.
template <class SegmentValue>
void spreadHalvesToPoints(Eigen::Index pointCount, SegmentValue segmentValue, Eigen::VectorXd& out)
{
    out.setZero(pointCount);
    for (Eigen::Index j = 0; j + 1 < pointCount; ++j)
    {
        const double half = 0.5 * segmentValue(j);
        out(j) += half;
        out(j + 1) += half;
    }
}

} // namespace

double Fiber::segmentMass(Eigen::Index j) const
{
    return state_.material.baseLineDensity() * state_.restLengths(j) + state_.segmentCapturedMass(j);
}

Eigen::VectorXd Fiber::pointMasses() const
{
    Eigen::VectorXd m;
    pointMasses(m);
    return m;
}

void Fiber::pointMasses(Eigen::VectorXd& m) const
{
    spreadHalvesToPoints(
        pointCount(), [this](Eigen::Index j) { return segmentMass(j); }, m);
}

Eigen::VectorXd Fiber::nodalLengths() const
{
    Eigen::VectorXd w;
    nodalLengths(w);
    return w;
}

void Fiber::nodalLengths(Eigen::VectorXd& w) const
{
    spreadHalvesToPoints(
        pointCount(), [this](Eigen::Index j) { return state_.restLengths(j); }, w);
}

Eigen::VectorXd Fiber::lineDensityAtPoints() const
{
    return pointMasses().cwiseQuotient(nodalLengths());
}

double Fiber::totalMass() const
{
    return state_.material.baseLineDensity() * length() + totalCapturedMass();
}

double Fiber::totalCapturedMass() const
{
    return state_.segmentCapturedMass.sum();
}

Eigen::Vector3d Fiber::centreOfMass() const
{
    const Eigen::VectorXd m = pointMasses();
    return state_.positions * m / m.sum();
}

Eigen::Vector3d Fiber::momentum() const
{
    return state_.velocities * pointMasses();
}

double Fiber::maxSegmentLengthError() const
{
    double worst = 0.0;
    for (Eigen::Index j = 0; j + 1 < pointCount(); ++j)
    {
        const double l = (state_.positions.col(j + 1) - state_.positions.col(j)).norm();
        worst = std::max(worst, std::abs(l - state_.restLengths(j)) / state_.restLengths(j));
    }
    return worst;
}

} // namespace dropletFiber
