// EndCondition: how one end of a fiber is held (docs/model.md sec. 1 boundary conditions).
//   free    - no force, no moment (natural conditions of the bending operator);
//   pinned  - end point position held, free rotation (no end moment);
//   clamped - end point position and tangent held. The tangent is held in the
//             ghost-point / Hencky sense: a rotational spring 2 S_b / l_0 between the end
//             segment and the clamp direction, which is the discrete form of x'(0) = d
//             that keeps the scheme second-order (holding the whole first segment
//             rigid would clamp half a segment too far out: first order).
// A held end may move with a prescribed constant anchor velocity (a fiber spun from a
// moving nozzle); the clamp direction itself does not turn.
#pragma once

#include <Eigen/Core>

namespace dropletFiber
{

enum class EndType
{
    free,
    pinned,
    clamped
};

struct EndCondition
{
    EndType type = EndType::free;
    // Velocity of the held end point [m/s] (pinned/clamped only).
    Eigen::Vector3d anchorVelocity = Eigen::Vector3d::Zero();
    // Clamp tangent (unit), pointing along the fiber away from the clamp at the
    // start end and out of the fiber at the last end, i.e. always in the direction of
    // increasing point index. Zero on input means "take it from the initial geometry".
    Eigen::Vector3d clampDirection = Eigen::Vector3d::Zero();

    bool holdsPosition() const { return type != EndType::free; }

    static EndCondition freeEnd() { return {}; }
    static EndCondition pinnedEnd(const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero())
    {
        EndCondition e;
        e.type = EndType::pinned;
        e.anchorVelocity = velocity;
        return e;
    }
    static EndCondition clampedEnd(const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero())
    {
        EndCondition e;
        e.type = EndType::clamped;
        e.anchorVelocity = velocity;
        return e;
    }
};

} // namespace dropletFiber
