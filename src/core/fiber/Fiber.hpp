// Fiber: one inextensible elastic fiber as a line strip of points (docs/model.md sec. 1,
// the FIDYST model): positions, velocities, fixed segment lengths, lumped point
// masses that grow with captured droplet mass, tension per segment, and a boundary
// condition at each end. Any number of points >= 2.
#pragma once

#include "fiber/FiberState.hpp"

namespace dropletFiber
{

class Fiber
{
public:
    // Points at rest; segment rest lengths are taken from the points as given.
    Fiber(const Eigen::Matrix3Xd& points, const FiberMaterial& material,
          const EndCondition& startEnd = EndCondition::freeEnd(),
          const EndCondition& endEnd = EndCondition::freeEnd());

    // A fully fixed fiber: never moves, still captures mass (filter fibers).
    static Fiber immobileFiber(const Eigen::Matrix3Xd& points, const FiberMaterial& material);

    // Restart: validated copy of a saved state, taken as it is.
    explicit Fiber(const FiberState& state);
    const FiberState& state() const { return state_; }

    // Geometry and state.
    Eigen::Index pointCount() const { return state_.positions.cols(); }
    Eigen::Index segmentCount() const { return pointCount() - 1; }
    const Eigen::Matrix3Xd& positions() const { return state_.positions; }
    const Eigen::Matrix3Xd& velocities() const { return state_.velocities; }
    const Eigen::VectorXd& restLengths() const { return state_.restLengths; }
    const Eigen::VectorXd& tension() const { return state_.tension; }
    const Eigen::VectorXd& capturedMassPerSegment() const { return state_.segmentCapturedMass; }
    const FiberMaterial& material() const { return state_.material; }
    const EndCondition& startEnd() const { return state_.startEnd; }
    const EndCondition& endEnd() const { return state_.endEnd; }
    bool immobile() const { return state_.immobile; }
    // The physical fibers it stands for (FiberState::represents).
    double represents() const { return state_.represents; }
    // Throws std::invalid_argument unless n is finite and > 0.
    void setRepresents(double n);
    // Its population's hat half-width [m] (FiberState::populationSpread).
    double populationSpread() const { return state_.populationSpread; }
    // Throws std::invalid_argument unless H is finite and >= 0.
    void setPopulationSpread(double H);
    double length() const { return state_.restLengths.sum(); }

    // Initial conditions and loads set by the user. Velocities are made consistent
    // with inextensibility and the held ends (the mass-weighted projection, i.e. what
    // an impulsive start would do): the midpoint scheme keeps consistent velocities
    // consistent but would carry an inconsistent part along for ever.
    void setVelocities(const Eigen::Matrix3Xd& velocities);
    void setExternalForce(const Eigen::Matrix3Xd& force); // [N] per point
    const Eigen::Matrix3Xd& externalForce() const { return state_.externalForce; }

    // Is point i held (an end with a pinned/clamped condition, or an immobile fiber)?
    bool pointHeld(Eigen::Index i) const;
    // Prescribed velocity of a held point.
    Eigen::Vector3d heldPointVelocity(Eigen::Index i) const;

    // Mass.
    double segmentMass(Eigen::Index j) const; // base + captured [kg]
    Eigen::VectorXd pointMasses() const;      // lumped [kg]
    Eigen::VectorXd nodalLengths() const;     // length each point stands for [m]
    // The same into existing storage (the solver's work vectors: no allocation).
    void pointMasses(Eigen::VectorXd& m) const;
    void nodalLengths(Eigen::VectorXd& w) const;
    Eigen::VectorXd lineDensityAtPoints() const; // sigma [kg/m] per point
    double totalMass() const;
    double totalCapturedMass() const; // all segments [kg]

    // Kinematics.
    Eigen::Vector3d centreOfMass() const;
    Eigen::Vector3d momentum() const;
    // max_j | |x_{j+1}-x_j| - l_j | / l_j
    double maxSegmentLengthError() const;

    // Write access for the solver (and for restart tooling that knows what it does).
    FiberState& mutableState() { return state_; }

private:
    void validate() const;
    void completeClampDirections();

    FiberState state_;
};

} // namespace dropletFiber
