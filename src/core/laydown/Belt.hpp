// Belt: the conveyor the fibers are laid on (docs/model.md sec. 11). A plane through
// `point` with unit `normal` pointing out of the air, moving in its plane with `velocity`.
// A fiber is laid when its centre of mass reaches the plane (signed distance along the
// normal >= 0), at the centre's foot on the plane. The belt's frame:
//   along  = V t - (foot - point).e_a     (e_a = velocity / V, V = |velocity|: the
//            distance from the point of the mat that passed `point` at t = 0, so that
//            fibers laid later lie at larger `along`)
//   across = (foot - point).e_c            (e_c = normal x e_a)
// A belt at rest (V = 0) takes e_a from `across`'s fallback: any unit vector in the
// plane (alongDirection), and along = -(foot - point).e_a.
#pragma once

#include "fiber/Fiber.hpp"

#include <Eigen/Core>

namespace dropletFiber
{

struct Belt
{
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, out of the air
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero(); // in the plane

    // Throws std::invalid_argument unless the normal is a unit vector (to 1e-9) and the
    // velocity lies in the plane (to 1e-9 of its size).
    void validate() const;

    double speed() const { return velocity.norm(); }
    // e_a: along the belt's motion (or a fixed direction in the plane when at rest).
    Eigen::Vector3d alongDirection() const;
    // e_c = normal x e_a.
    Eigen::Vector3d acrossDirection() const;
};

// Whether the fiber's centre of mass has reached the belt.
bool reachesBelt(const Fiber& fiber, const Belt& belt);

// One fiber laid: where and when, what it is and what it carries (one physical fiber's
// figures; `represents` physical fibers were laid with it).
struct LaidFiber
{
    double time = 0.0;
    double across = 0.0, along = 0.0;                      // m, the belt's frame (above)
    Eigen::Vector3d orientation = Eigen::Vector3d::Zero(); // unit end-to-end, (across, along, normal)
    double length = 0.0;                                   // m
    double endToEnd = 0.0;                                 // m, between its ends
    double glassMass = 0.0;                                // kg, without binder
    double binderMass = 0.0;                               // kg, captured
    double represents = 1.0;
    double bareFraction = 0.0;   // of its length, no binder
    double sigmaVariation = 0.0; // CoV of its captured mass per length
    long id = -1;                // the fiber's birth number
    // The half-width of its population's hat [m] (FiberState::populationSpread; 0: the
    // represents fibers all lie on its line)
    double spread = 0.0;
};

// The record of a fiber laid at `time` (its centre's foot on the plane).
LaidFiber layFiber(const Fiber& fiber, const Belt& belt, double time, long id);

} // namespace dropletFiber
