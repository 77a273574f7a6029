// ImplicitFiberStep: one implicit (sub-)step of MODEL.md eqs. 2-3 for one fiber.
//
// Scheme (theta-method on the constrained equations of motion, theta = 1/2: implicit
// midpoint), unknowns y = x_{n+1} and the tensions lambda_j:
//   x_theta = x_n + theta (y - x_n),   v_theta = (y - x_n) / h,
//   M (v_theta - v_n) / theta = h [ F(x_theta, v_theta) + sum_j lambda_j G_j(x_theta)^T ]
//   (|y_{j+1} - y_j|^2 - l_j^2) / (2 l_j) = 0          (inextensible, eq. 3)
//   v_{n+1} = (v_theta - (1 - theta) v_n) / theta
// F = gravity + external + bending (linear, implicit) + drag (implicit, tangent taken
// at x_theta). The tension multiplies the segment direction at x_theta; for theta = 1/2
// and quadratic constraints g(y) - g(x_n) = G(x_mid)(y - x_n) exactly, so tension does
// no work and the midpoint step conserves kinetic + bending + gravitational energy
// (and momentum) to solver precision: no bending-CFL limit, no drift.
//
// The nonlinear system is solved by Newton's method with the exact Jacobian, a banded
// saddle-point system ordered per point [y_i (3), lambda_i] so that its bandwidth is
// 10 whatever the point count; it is solved with BandedLU (partial pivoting), O(n).
// Rows are scaled by theta h / m_i and the multipliers by m / (theta h^2) so all
// entries are lengths of order one (makes the pivoting meaningful).
#pragma once

#include "fiber/BandedLU.hpp"
#include "fiber/Fiber.hpp"
#include "fiber/FiberSolverSettings.hpp"

namespace dropletFiber {

// Air and drag resistances at this fiber's points for this sub-step.
struct PointDrag {
    const Eigen::Matrix3Xd* airVelocity = nullptr;  // nullptr: no drag
    Eigen::VectorXd normal;                          // c_n [N s/m^2] per point
    Eigen::VectorXd tangential;                      // c_t
};

struct SubStepResult {
    bool converged = false;
    bool loose = false;         // accepted at acceptableConstraintError only
    int iterations = 0;         // linear solves
    double maxRotation = 0.0;   // largest segment turn in the step [rad, chord]
};

class ImplicitFiberStep {
public:
    // Advances fiber by h when it converges; leaves it untouched otherwise.
    SubStepResult advance(Fiber& fiber, double h, const PointDrag& drag,
                          const FiberSolverSettings& settings);

private:
    BandedLU lu_;  // work storage, reused between fibers and steps
};

}  // namespace dropletFiber
