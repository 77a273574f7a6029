// ImplicitFiberStep: one implicit (sub-)step of docs/model.md eqs. 2-3 for one fiber.
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
// entries are lengths of order one (makes the pivoting meaningful); a stiff fiber's
// bending makes its point rows larger than that, so each constraint row is scaled by
// the mean diagonal of its two points' rows, and the LU pivots with a threshold (0.1:
// the diagonal is kept unless ten times smaller than the column's largest entry),
// which on these systems leaves U as narrow as the band.
//
// Cost: each Newton iteration evaluates the residual, and only when another update is
// needed the Jacobian (so the converged iterate costs no Jacobian). The Jacobian's
// constant part (mass and the linear bending force, plus the rows of held points) is
// built once per sub-step and copied; each iteration adds drag and tension to it,
// written straight into the band (ImplicitFiberStepJacobian.cpp). All work storage
// is kept in the object (Eigen work arrays are resized only when the point count
// changes from one fiber to the next; the band storage only grows).
#pragma once

#include "fiber/BandedLU.hpp"
#include "fiber/DragReaction.hpp"
#include "fiber/BendingJoints.hpp"
#include "fiber/Fiber.hpp"
#include "fiber/FiberSolverSettings.hpp"

#include <algorithm>
#include <vector>

namespace dropletFiber
{

// Air and drag resistances at this fiber's points for this sub-step.
struct PointDrag
{
    const Eigen::Matrix3Xd* airVelocity = nullptr; // nullptr: no drag
    Eigen::VectorXd normal;                        // c_n [N s/m^2] per point
    Eigen::VectorXd tangential;                    // c_t
};

struct SubStepResult
{
    bool converged = false;
    bool loose = false;       // accepted at acceptableConstraintError only
    int iterations = 0;       // linear solves
    double maxRotation = 0.0; // largest segment turn in the step [rad, chord]
};

class ImplicitFiberStep
{
public:
    ImplicitFiberStep();

    // Advances fiber by h when it converges; leaves it untouched otherwise.
    SubStepResult advance(Fiber& fiber, double h, const PointDrag& drag, const FiberSolverSettings& settings);

    // The drag of the sub-step advance() last took, at its converged iterate (the
    // force its equations balanced), times h, added to reaction's columns firstPoint
    // on; a held point's too, at its prescribed velocity (its support takes it, the
    // air feels it all the same).
    void addDragImpulse(const PointDrag& drag, DragReaction& reaction, Eigen::Index firstPoint) const;

private:
    // Per sub-step: geometry, scales, constant terms, first iterate, constant Jacobian.
    void prepare(const Fiber& fiber, double h, const PointDrag& drag, const FiberSolverSettings& settings);
    // The fiber's state relative to its first point, masses, joints, held points,
    // and the first iterate (y, lambda).
    void takeFiber(const Fiber& fiber, double h, double theta);
    // Row scales of the point rows and of the multipliers.
    void setScales();
    // Residual terms fixed during the iteration: loads, norms, drag resistances.
    void setConstantTerms(const Fiber& fiber, const PointDrag& drag, const Eigen::Vector3d& gravity);
    void resizeWork();
    // Mass, bending and held rows of the Jacobian, and the constraint rows' scales.
    void buildConstantJacobian();
    void addBendingJacobian(BandedLU& J) const;

    // Newton's iteration from the first iterate; result says whether it converged.
    void solve(const PointDrag& drag, const FiberSolverSettings& settings, SubStepResult& result);
    // Convergence test at the iterate evaluateResidual<false> saw.
    bool hasConverged(const PointDrag& drag, const FiberSolverSettings& settings, double shortest,
                      double lastUpdate, double& constraintError);
    // One Newton update of (y_, lambda_); false when it fails (singular, not finite).
    bool newtonUpdate(const PointDrag& drag, double shortest, double& lastUpdate, SubStepResult& result);
    // Largest segment turn from x_n to y [rad, chord].
    double maxSegmentRotation() const;
    // The converged iterate into the fiber.
    void accept(Fiber& fiber) const;

    // The drag P3 on point i at (x_theta, v_theta) (nodal resistances cn_, ct_) and
    // the terms the Jacobian reuses.
    struct PointDragForce
    {
        Eigen::Vector3d force, tangent, relativeAir;
        double chordLength = 0.0, wt = 0.0;
    };
    PointDragForce dragForceAt(Eigen::Index i, const PointDrag& drag) const;

    // Residual rows at (y_, lambda_) into rhs_ (scaled as the Jacobian's rows) and
    // the largest relative constraint error; withSizes: also the size of each point
    // row's terms and their round-off (magnitude_, noise_) for residualSmall().
    template <bool withSizes>
    void evaluateResidual(const PointDrag& drag, double& constraintError);
    // Its parts, each adding one force to residual_ (and its sizes).
    template <bool withSizes>
    void addInertiaAndLoad();
    template <bool withSizes>
    void addBendingForce();
    template <bool withSizes>
    void addDragForce(const PointDrag& drag);
    template <bool withSizes>
    void addTensionForce();
    // Constraint rows into rhs_; returns the largest relative constraint error.
    double evaluateConstraints();
    void scaleResidualRows();
    // Is every point's residual below its tolerance? (after evaluateResidual<true>)
    bool residualSmall(double residualTolerance) const;

    // Jacobian at the iterate evaluateResidual saw, into lu_: the constant part plus
    // drag and tension.
    void assembleJacobian(const PointDrag& drag);
    void addDragJacobian();
    void addDragTangentJacobian(Eigen::Index i);
    void addTensionJacobian();
    bool held(Eigen::Index i) const { return held_[static_cast<std::size_t>(i)] != 0; }

    // The system's order per point [y_i (3), lambda_i]: the row of point i's first
    // coordinate, the row of segment j's constraint (its tension), the band's half-width.
    static constexpr Eigen::Index bandwidth = 10; // bending couples points i and i+2: 4*2 + 2
    static Eigen::Index pointRow(Eigen::Index i) { return 4 * i; }
    static Eigen::Index tensionRow(Eigen::Index j) { return 4 * j + 3; }
    // Nodal tangent for the drag: neighbours' chord (one-sided at the ends).
    static void tangentStencil(Eigen::Index i, Eigen::Index n, Eigen::Index& hi, Eigen::Index& lo)
    {
        hi = std::min(i + 1, n - 1);
        lo = std::max(i - 1, Eigen::Index(0));
    }

    // The sub-step being solved.
    Eigen::Index n_ = 0;
    double h_ = 0.0, theta_ = 0.5;
    const Eigen::Matrix3Xd* vn_ = nullptr; // v_n (the fiber's velocities)
    const Eigen::VectorXd* l_ = nullptr;   // rest lengths

    // Work storage, reused between sub-steps, fibers and steps (sized per fiber).
    BandedLU lu_;
    BandedLU constantJacobian_;
    std::vector<BendingJoint> joints_;
    std::vector<double> jointOffsetNorm_;
    std::vector<char> held_;
    Eigen::Matrix3Xd xn_, y_, xTheta_, vTheta_, residual_, load_;
    Eigen::Matrix3Xd tangent_, relativeAir_, segment_, dy_; // residual terms the Jacobian reuses
    Eigen::VectorXd m_, nodal_, rowScale_, lambdaScale_, lambda_, rhs_;
    Eigen::VectorXd magnitude_, noise_; // size of each residual row's terms, their round-off
    Eigen::VectorXd loadNorm_, xnNorm_, vnNorm_, airNorm_, xThetaNorm_;
    Eigen::VectorXd cn_, ct_, chordLength_, wt_;
    Eigen::VectorXd constraintScale_; // of each constraint row (tension row)
};

} // namespace dropletFiber
