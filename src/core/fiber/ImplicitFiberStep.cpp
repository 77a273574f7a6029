#include "fiber/ImplicitFiberStep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dropletFiber
{

namespace
{

// Threshold partial pivoting (see BandedLU): with the constraint rows scaled to their
// points' rows, the diagonal passes this in (almost) every column, so U keeps the
// band's own width instead of the up to kl extra columns each row exchange adds.
// The pentadiagonal bending part alone needs a threshold below 1/2: the LU of its
// stencil (1, -4, 6, -4, 1) has multipliers of 2.
constexpr double pivotThreshold = 0.1;

} // namespace

ImplicitFiberStep::ImplicitFiberStep()
{
    lu_.setPivotThreshold(pivotThreshold);
}

void ImplicitFiberStep::prepare(const Fiber& fiber, double h, const PointDrag& drag,
                                const FiberSolverSettings& settings)
{
    takeFiber(fiber, h, settings.theta);
    setScales();
    setConstantTerms(fiber, drag, settings.gravity);
    resizeWork();
    buildConstantJacobian();
}

void ImplicitFiberStep::takeFiber(const Fiber& fiber, double h, double theta)
{
    const FiberState& state = fiber.state();
    const Eigen::Index n = fiber.pointCount();
    n_ = n;
    h_ = h;
    theta_ = theta;
    vn_ = &state.velocities;
    l_ = &state.restLengths;
    const Eigen::Matrix3Xd& vn = state.velocities;

    // Work relative to the first point: keeps round-off at the scale of the fiber.
    const Eigen::Vector3d origin = state.positions.col(0);
    xn_ = state.positions.colwise() - origin;
    fiber.pointMasses(m_);
    fiber.nodalLengths(nodal_);
    bendingJoints(fiber, joints_);
    jointOffsetNorm_.resize(joints_.size());
    for (std::size_t k = 0; k < joints_.size(); ++k)
        jointOffsetNorm_[k] = joints_[k].offset.norm();
    held_.resize(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
        held_[static_cast<std::size_t>(i)] = fiber.pointHeld(i);

    // First iterate: every point moves on at its present (held: prescribed) velocity.
    y_.resize(3, n);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        y_.col(i) = xn_.col(i) + h * (held(i) ? fiber.heldPointVelocity(i) : Eigen::Vector3d(vn.col(i)));
    }
    lambda_ = state.tension;
}

void ImplicitFiberStep::setScales()
{
    const Eigen::Index n = n_;
    const Eigen::Index s = n - 1;
    const double h = h_, theta = theta_;
    rowScale_.resize(n);
    lambdaScale_.resize(s);
    for (Eigen::Index i = 0; i < n; ++i)
        rowScale_(i) = theta * h / m_(i);
    for (Eigen::Index j = 0; j < s; ++j)
        lambdaScale_(j) = 0.5 * (m_(j) + m_(j + 1)) / (theta * h * h);
}

void ImplicitFiberStep::setConstantTerms(const Fiber& fiber, const PointDrag& drag,
                                         const Eigen::Vector3d& gravity)
{
    const FiberState& state = fiber.state();
    const Eigen::Index n = n_;
    const double h = h_;
    const Eigen::Matrix3Xd& vn = *vn_;
    const Eigen::Vector3d g = gravity;
    load_.resize(3, n);
    loadNorm_.resize(n);
    xnNorm_.resize(n);
    vnNorm_.resize(n);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        load_.col(i) = h * (m_(i) * g + state.externalForce.col(i));
        loadNorm_(i) = load_.col(i).norm();
        xnNorm_(i) = xn_.col(i).norm();
        vnNorm_(i) = vn.col(i).norm();
    }
    cn_.setZero(n);
    ct_.setZero(n);
    airNorm_.setZero(n);
    if (drag.airVelocity != nullptr)
    {
        for (Eigen::Index i = 0; i < n; ++i)
        {
            cn_(i) = nodal_(i) * drag.normal(i);
            ct_(i) = nodal_(i) * drag.tangential(i);
            airNorm_(i) = drag.airVelocity->col(i).norm();
        }
    }
}

void ImplicitFiberStep::resizeWork()
{
    const Eigen::Index n = n_;
    const Eigen::Index s = n - 1;
    rhs_.resize(4 * n - 1);
    residual_.resize(3, n);
    magnitude_.resize(n);
    noise_.resize(n);
    xTheta_.resize(3, n);
    vTheta_.resize(3, n);
    xThetaNorm_.resize(n);
    tangent_.resize(3, n);
    relativeAir_.resize(3, n);
    chordLength_.resize(n);
    wt_.resize(n);
    segment_.resize(3, s);
    dy_.resize(3, s);
}

template <bool withSizes>
void ImplicitFiberStep::evaluateResidual(const PointDrag& drag, double& constraintError)
{
    xTheta_ = xn_ + theta_ * (y_ - xn_);
    vTheta_ = (y_ - xn_) / h_;
    residual_.setZero();
    if (withSizes)
    {
        for (Eigen::Index i = 0; i < n_; ++i)
            xThetaNorm_(i) = xTheta_.col(i).norm();
        magnitude_.setZero();
        noise_.setZero();
    }
    addInertiaAndLoad<withSizes>();
    addBendingForce<withSizes>();
    if (drag.airVelocity != nullptr)
        addDragForce<withSizes>(drag);
    addTensionForce<withSizes>();
    constraintError = evaluateConstraints();
    scaleResidualRows();
}

template <bool withSizes>
void ImplicitFiberStep::addInertiaAndLoad()
{
    const double h = h_, theta = theta_;
    const Eigen::Matrix3Xd& vn = *vn_;
    for (Eigen::Index i = 0; i < n_; ++i)
    {
        if (held(i))
            continue;
        const Eigen::Vector3d inertia = m_(i) * (vTheta_.col(i) - vn.col(i)) / theta;
        residual_.col(i) += inertia - load_.col(i);
        if (withSizes)
        {
            magnitude_(i) += inertia.norm() + loadNorm_(i);
            noise_(i) += m_(i) * (y_.col(i).norm() + xnNorm_(i) + h * vnNorm_(i)) / (theta * h);
        }
    }
}

template <bool withSizes>
void ImplicitFiberStep::addBendingForce()
{
    const double h = h_;
    for (std::size_t k = 0; k < joints_.size(); ++k)
    {
        const BendingJoint& joint = joints_[k];
        const Eigen::Vector3d b = jointVector(joint, xTheta_);
        double bScale = 0.0;
        if (withSizes)
        {
            bScale = jointOffsetNorm_[k];
            for (int a = 0; a < joint.pointCount; ++a)
            {
                bScale += std::abs(joint.coefficient[static_cast<std::size_t>(a)])
                    * xThetaNorm_(joint.point[static_cast<std::size_t>(a)]);
            }
        }
        for (int a = 0; a < joint.pointCount; ++a)
        {
            const Eigen::Index p = joint.point[static_cast<std::size_t>(a)];
            if (held(p))
                continue;
            const double ca = joint.coefficient[static_cast<std::size_t>(a)];
            const Eigen::Vector3d term = h * joint.stiffness * ca * b; // -h * force
            residual_.col(p) += term;
            if (withSizes)
            {
                magnitude_(p) += term.norm();
                noise_(p) += h * joint.stiffness * std::abs(ca) * bScale;
            }
        }
    }
}

ImplicitFiberStep::PointDragForce ImplicitFiberStep::dragForceAt(Eigen::Index i, const PointDrag& drag) const
{
    PointDragForce f;
    Eigen::Index hi, lo;
    tangentStencil(i, n_, hi, lo);
    const Eigen::Vector3d chord = xTheta_.col(hi) - xTheta_.col(lo);
    f.chordLength = chord.norm();
    f.tangent = chord / f.chordLength;
    f.relativeAir = drag.airVelocity->col(i) - vTheta_.col(i);
    f.wt = f.tangent.dot(f.relativeAir);
    const double cn = cn_(i), ct = ct_(i);
    f.force = cn * f.relativeAir + (ct - cn) * f.wt * f.tangent;
    return f;
}

template <bool withSizes>
void ImplicitFiberStep::addDragForce(const PointDrag& drag)
{
    const Eigen::Index n = n_;
    const double h = h_;
    for (Eigen::Index i = 0; i < n; ++i)
    {
        if (held(i))
            continue;
        const double cn = cn_(i), ct = ct_(i);
        if (cn == 0.0 && ct == 0.0)
            continue;
        PointDragForce f = dragForceAt(i, drag);
        const Eigen::Vector3d& t = f.tangent;
        const Eigen::Vector3d& w = f.relativeAir;
        const Eigen::Vector3d& force = f.force;
        const double chordLength = f.chordLength, wt = f.wt;
        residual_.col(i) -= h * force;
        if (withSizes)
        {
            magnitude_(i) += h * force.norm();
            noise_(i) += h * std::max(cn, ct) * (airNorm_(i) + vTheta_.col(i).norm());
        }
        // Kept for the Jacobian.
        tangent_.col(i) = t;
        relativeAir_.col(i) = w;
        chordLength_(i) = chordLength;
        wt_(i) = wt;
    }
}

template <bool withSizes>
void ImplicitFiberStep::addTensionForce()
{
    const Eigen::Index s = n_ - 1;
    const double h = h_;
    const Eigen::VectorXd& l = *l_;
    for (Eigen::Index j = 0; j < s; ++j)
    {
        const Eigen::Vector3d d = xTheta_.col(j + 1) - xTheta_.col(j);
        segment_.col(j) = d;
        const Eigen::Vector3d pull = lambda_(j) / l(j) * d; // tension force on point j
        double pullNoise = 0.0, pullSize = 0.0;
        if (withSizes)
        {
            pullNoise = h * std::abs(lambda_(j)) / l(j) * (xThetaNorm_(j + 1) + xThetaNorm_(j));
            pullSize = h * pull.norm();
        }
        if (!held(j))
        {
            residual_.col(j) -= h * pull;
            if (withSizes)
            {
                magnitude_(j) += pullSize;
                noise_(j) += pullNoise;
            }
        }
        if (!held(j + 1))
        {
            residual_.col(j + 1) += h * pull;
            if (withSizes)
            {
                magnitude_(j + 1) += pullSize;
                noise_(j + 1) += pullNoise;
            }
        }
    }
}

double ImplicitFiberStep::evaluateConstraints()
{
    const Eigen::Index s = n_ - 1;
    const Eigen::VectorXd& l = *l_;
    double constraintError = 0.0;
    for (Eigen::Index j = 0; j < s; ++j)
    {
        if (held(j) && held(j + 1))
        {
            rhs_(tensionRow(j)) = 0.0;
            continue;
        }
        const Eigen::Vector3d dy = y_.col(j + 1) - y_.col(j);
        dy_.col(j) = dy;
        const double dyLength = dy.norm();
        const double c = (dyLength - l(j)) * (dyLength + l(j)) / (2.0 * l(j));
        rhs_(tensionRow(j)) = constraintScale_(j) * c;
        constraintError = std::max(constraintError, std::abs(c) / l(j));
    }
    return constraintError;
}

void ImplicitFiberStep::scaleResidualRows()
{
    for (Eigen::Index i = 0; i < n_; ++i)
    {
        if (held(i))
        {
            rhs_.segment<3>(pointRow(i)).setZero();
        }
        else
        {
            rhs_.segment<3>(pointRow(i)) = rowScale_(i) * residual_.col(i);
        }
    }
}

bool ImplicitFiberStep::residualSmall(double residualTolerance) const
{
    for (Eigen::Index i = 0; i < n_; ++i)
    {
        if (held(i))
            continue;
        const double allowed
            = residualTolerance * magnitude_(i) + 64.0 * std::numeric_limits<double>::epsilon() * noise_(i);
        if (residual_.col(i).norm() > allowed)
            return false;
    }
    return true;
}

SubStepResult ImplicitFiberStep::advance(Fiber& fiber, double h, const PointDrag& drag,
                                         const FiberSolverSettings& settings)
{
    SubStepResult result;
    prepare(fiber, h, drag, settings);
    solve(drag, settings, result);
    if (!result.converged)
        return result;
    result.maxRotation = maxSegmentRotation();
    accept(fiber);
    return result;
}

void ImplicitFiberStep::solve(const PointDrag& drag, const FiberSolverSettings& settings,
                              SubStepResult& result)
{
    const double shortest = l_->minCoeff();
    double lastUpdate = std::numeric_limits<double>::infinity();
    double constraintError = 0.0;
    double previousConstraintError = std::numeric_limits<double>::infinity();
    for (int iteration = 0;; ++iteration)
    {
        evaluateResidual<false>(drag, constraintError);
        if (hasConverged(drag, settings, shortest, lastUpdate, constraintError))
        {
            result.converged = true;
            return;
        }
        // Stalled at round-off (no more progress, tiny updates): accept if the
        // constraints hold to the hard limit.
        const bool stalled
            = iteration > 0 && constraintError > 0.5 * previousConstraintError && lastUpdate <= 1e-8;
        if (stalled || iteration >= settings.maxNewtonIterations)
        {
            if (constraintError <= settings.acceptableConstraintError && lastUpdate <= 1e-8)
            {
                result.converged = true;
                result.loose = true;
            }
            return;
        }
        previousConstraintError = constraintError;
        if (!newtonUpdate(drag, shortest, lastUpdate, result))
            return;
    }
}

bool ImplicitFiberStep::hasConverged(const PointDrag& drag, const FiberSolverSettings& settings,
                                     double shortest, double lastUpdate, double& constraintError)
{
    // Segment lengths cannot be computed closer than round-off in the coordinates
    // (relative to point 0): never ask for better than that.
    // (sqrt of the largest squared norm: the same bits as the largest norm)
    const double roundOff = 16.0 * std::numeric_limits<double>::epsilon()
        * std::sqrt(y_.colwise().squaredNorm().maxCoeff()) / shortest;
    const double constraintTarget = std::max(settings.constraintTolerance, roundOff);
    const bool updateSmall = lastUpdate <= std::max(settings.updateTolerance, roundOff);
    if (!(constraintError <= constraintTarget))
        return false; // NaN: not converged
    if (updateSmall)
        return true;
    // The residual test needs the size of every term (a dozen square roots per
    // point): evaluated again with them only when it decides.
    evaluateResidual<true>(drag, constraintError);
    return residualSmall(settings.residualTolerance);
}

bool ImplicitFiberStep::newtonUpdate(const PointDrag& drag, double shortest, double& lastUpdate,
                                     SubStepResult& result)
{
    assembleJacobian(drag);
    if (!lu_.factorize())
        return false;
    rhs_ = -rhs_;
    lu_.solveInPlace(rhs_);
    ++result.iterations;
    double biggest = 0.0;
    for (Eigen::Index i = 0; i < n_; ++i)
    {
        if (held(i))
            continue;
        const Eigen::Vector3d step = rhs_.segment<3>(pointRow(i));
        y_.col(i) += step;
        biggest = std::max(biggest, step.norm());
    }
    for (Eigen::Index j = 0; j < n_ - 1; ++j)
        lambda_(j) += lambdaScale_(j) * rhs_(tensionRow(j));
    lastUpdate = biggest / shortest;
    return std::isfinite(lastUpdate) && lambda_.allFinite();
}

double ImplicitFiberStep::maxSegmentRotation() const
{
    const Eigen::VectorXd& l = *l_;
    double largest = 0.0;
    for (Eigen::Index j = 0; j < n_ - 1; ++j)
    {
        const Eigen::Vector3d before = (xn_.col(j + 1) - xn_.col(j)) / l(j);
        const Eigen::Vector3d after = (y_.col(j + 1) - y_.col(j)) / l(j);
        largest = std::max(largest, (after - before).norm());
    }
    return largest;
}

void ImplicitFiberStep::addDragImpulse(const PointDrag& drag, DragReaction& reaction,
                                       Eigen::Index firstPoint) const
{
    if (drag.airVelocity == nullptr)
        return;
    const double h = h_;
    for (Eigen::Index i = 0; i < n_; ++i)
    {
        // The force of addDragForce (the same function: the same bits)
        reaction.impulse.col(firstPoint + i) += h * dragForceAt(i, drag).force;
        reaction.coefficientTime(firstPoint + i) += h * isotropicDragCoefficient(cn_(i), ct_(i));
    }
}

void ImplicitFiberStep::accept(Fiber& fiber) const
{
    FiberState& state = fiber.mutableState();
    const double h = h_, theta = theta_;
    const Eigen::Vector3d origin = state.positions.col(0);
    for (Eigen::Index i = 0; i < n_; ++i)
    {
        if (held(i))
        {
            state.velocities.col(i) = fiber.heldPointVelocity(i);
        }
        else
        {
            state.velocities.col(i)
                = ((y_.col(i) - xn_.col(i)) / h - (1.0 - theta) * state.velocities.col(i)) / theta;
        }
    }
    state.positions = y_.colwise() + origin;
    state.tension = lambda_;
}

} // namespace dropletFiber
