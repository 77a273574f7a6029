// DragReaction: the fibers' drag over one CFD step as the air feels it (docs/model.md
// sec. 10). Per air-sample point: the impulse the air's drag gave the fiber point over
// the step, and the time integral of the drag's isotropic linear coefficient, the part
// of the air's momentum source taken implicitly. Both are for one physical fiber; the
// caller weights them by what the fiber represents, divides by the step and hands them
// to the cells the air was sampled from, where minus the impulse is what the air lost.
//
// The drag on a point is f = l_i [c_n w + (c_t - c_n)(w.t) t], w = u_air - v: linear in
// the air's velocity with the tensor C = l_i [c_n I + (c_t - c_n) t t], whose
// orientation mean (trace / 3) is the isotropic coefficient l_i (2 c_n + c_t) / 3.
#pragma once

#include "fiber/AirSample.hpp"
#include "fiber/DragModel.hpp"
#include "fiber/Fiber.hpp"

#include <Eigen/Core>

namespace dropletFiber
{

struct DragReaction
{
    Eigen::Matrix3Xd impulse;        // integral of the drag on each point over the step [N s]
    Eigen::VectorXd coefficientTime; // integral of its isotropic coefficient [N s^2 / m]

    Eigen::Index pointCount() const { return impulse.cols(); }
    // n points, all zero.
    void reset(Eigen::Index points);
};

// The orientation mean of the drag tensor l_i [c_n I + (c_t - c_n) t t] (trace / 3),
// from the point's nodal resistances l_i c_n and l_i c_t [N s/m].
inline double isotropicDragCoefficient(double normal, double tangential)
{
    return (2.0 * normal + tangential) / 3.0;
}

// The drag over dt on the points of an immobile fiber (which the solver does not
// advance: it stands still, w = u_air), with the air at its points, columns firstAir
// on of air, added to reaction's columns firstPoint on. The coefficients are the drag
// law's at each point's air, as for moving fibers (DragModel.hpp).
void addImmobileFiberReaction(const Fiber& fiber, const AirSample& air, Eigen::Index firstAir,
                              const DragSettings& drag, double dt, DragReaction& reaction,
                              Eigen::Index firstPoint);

} // namespace dropletFiber
