#include "fiber/ImplicitFiberStep.hpp"

#include "fiber/BendingJoints.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace dropletFiber {

namespace {

constexpr Eigen::Index bandwidth = 10;  // bending couples points i and i+2: 4*2 + 2

Eigen::Index pointRow(Eigen::Index i) { return 4 * i; }
Eigen::Index tensionRow(Eigen::Index j) { return 4 * j + 3; }

// Nodal tangent for the drag: neighbours' chord (one-sided at the ends).
void tangentStencil(Eigen::Index i, Eigen::Index n, Eigen::Index& hi, Eigen::Index& lo)
{
    hi = std::min(i + 1, n - 1);
    lo = std::max(i - 1, Eigen::Index(0));
}

}  // namespace

SubStepResult ImplicitFiberStep::advance(Fiber& fiber, double h, const PointDrag& drag,
                                         const FiberSolverSettings& settings)
{
    SubStepResult result;
    FiberState& state = fiber.mutableState();
    const Eigen::Index n = fiber.pointCount();
    const Eigen::Index s = n - 1;
    const double theta = settings.theta;
    const Eigen::Vector3d g = settings.gravity;

    // Work relative to the first point: keeps round-off at the scale of the fiber.
    const Eigen::Vector3d origin = state.positions.col(0);
    const Eigen::Matrix3Xd xn = state.positions.colwise() - origin;
    const Eigen::Matrix3Xd& vn = state.velocities;
    const Eigen::VectorXd& l = state.restLengths;
    const Eigen::VectorXd m = fiber.pointMasses();
    const Eigen::VectorXd nodal = fiber.nodalLengths();
    const std::vector<BendingJoint> joints = bendingJoints(fiber);
    const double shortest = l.minCoeff();

    std::vector<char> held(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) held[static_cast<std::size_t>(i)] = fiber.pointHeld(i);
    auto isHeld = [&held](Eigen::Index i) { return held[static_cast<std::size_t>(i)] != 0; };

    Eigen::Matrix3Xd y(3, n);
    for (Eigen::Index i = 0; i < n; ++i) {
        y.col(i) = xn.col(i) + h * (isHeld(i) ? fiber.heldPointVelocity(i) : Eigen::Vector3d(vn.col(i)));
    }
    Eigen::VectorXd lambda = state.tension;

    Eigen::VectorXd rowScale(n), lambdaScale(s);
    for (Eigen::Index i = 0; i < n; ++i) rowScale(i) = theta * h / m(i);
    for (Eigen::Index j = 0; j < s; ++j) lambdaScale(j) = 0.5 * (m(j) + m(j + 1)) / (theta * h * h);

    const Eigen::Index size = 4 * n - 1;
    Eigen::VectorXd rhs(size);
    Eigen::Matrix3Xd residual(3, n);
    Eigen::VectorXd magnitude(n);  // size of the terms of each residual row
    Eigen::VectorXd noise(n);      // their round-off scale (before cancellation)
    Eigen::Matrix3Xd xTheta(3, n), vTheta(3, n);
    const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();

    auto addPointPoint = [&](Eigen::Index i, Eigen::Index q, const Eigen::Matrix3d& block) {
        if (isHeld(i) || isHeld(q)) return;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                lu_.add(pointRow(i) + a, pointRow(q) + b, rowScale(i) * block(a, b));
    };
    auto addPointTension = [&](Eigen::Index i, Eigen::Index j, const Eigen::Vector3d& column) {
        if (isHeld(i)) return;
        for (int a = 0; a < 3; ++a)
            lu_.add(pointRow(i) + a, tensionRow(j), rowScale(i) * lambdaScale(j) * column(a));
    };
    auto addTensionPoint = [&](Eigen::Index j, Eigen::Index q, const Eigen::Vector3d& row) {
        if (isHeld(q)) return;
        for (int b = 0; b < 3; ++b) lu_.add(tensionRow(j), pointRow(q) + b, row(b));
    };

    double lastUpdate = std::numeric_limits<double>::infinity();
    double constraintError = 0.0;
    double previousConstraintError = std::numeric_limits<double>::infinity();
    for (int iteration = 0;; ++iteration) {
        // ---- residual and Jacobian at the current iterate --------------------------
        lu_.reset(size, bandwidth, bandwidth);
        xTheta = xn + theta * (y - xn);
        vTheta = (y - xn) / h;
        residual.setZero();
        magnitude.setZero();
        noise.setZero();

        for (Eigen::Index i = 0; i < n; ++i) {
            if (isHeld(i)) continue;
            const Eigen::Vector3d inertia = m(i) * (vTheta.col(i) - vn.col(i)) / theta;
            const Eigen::Vector3d load = h * (m(i) * g + state.externalForce.col(i));
            residual.col(i) += inertia - load;
            magnitude(i) += inertia.norm() + load.norm();
            noise(i) += m(i) * (y.col(i).norm() + xn.col(i).norm() + h * vn.col(i).norm()) / (theta * h);
            addPointPoint(i, i, m(i) / (theta * h) * identity);
        }
        for (const BendingJoint& joint : joints) {
            const Eigen::Vector3d b = jointVector(joint, xTheta);
            double bScale = joint.offset.norm();
            for (int a = 0; a < joint.pointCount; ++a) {
                bScale += std::abs(joint.coefficient[static_cast<std::size_t>(a)]) *
                          xTheta.col(joint.point[static_cast<std::size_t>(a)]).norm();
            }
            for (int a = 0; a < joint.pointCount; ++a) {
                const Eigen::Index p = joint.point[static_cast<std::size_t>(a)];
                const double ca = joint.coefficient[static_cast<std::size_t>(a)];
                const Eigen::Vector3d term = h * joint.stiffness * ca * b;  // -h * force
                if (!isHeld(p)) {
                    residual.col(p) += term;
                    magnitude(p) += term.norm();
                    noise(p) += h * joint.stiffness * std::abs(ca) * bScale;
                }
                for (int c = 0; c < joint.pointCount; ++c) {
                    const double cc = joint.coefficient[static_cast<std::size_t>(c)];
                    addPointPoint(p, joint.point[static_cast<std::size_t>(c)],
                                  h * theta * joint.stiffness * ca * cc * identity);
                }
            }
        }
        if (drag.airVelocity != nullptr) {
            for (Eigen::Index i = 0; i < n; ++i) {
                if (isHeld(i)) continue;
                const double cn = nodal(i) * drag.normal(i);
                const double ct = nodal(i) * drag.tangential(i);
                if (cn == 0.0 && ct == 0.0) continue;
                Eigen::Index hi, lo;
                tangentStencil(i, n, hi, lo);
                const Eigen::Vector3d chord = xTheta.col(hi) - xTheta.col(lo);
                const double chordLength = chord.norm();
                const Eigen::Vector3d t = chord / chordLength;
                const Eigen::Vector3d w = drag.airVelocity->col(i) - vTheta.col(i);
                const double wt = t.dot(w);
                const Eigen::Vector3d force = cn * w + (ct - cn) * wt * t;
                residual.col(i) -= h * force;
                magnitude(i) += h * force.norm();
                noise(i) += h * std::max(cn, ct) * (drag.airVelocity->col(i).norm() + vTheta.col(i).norm());
                addPointPoint(i, i, cn * identity + (ct - cn) * t * t.transpose());
                if (ct != cn) {
                    const Eigen::Matrix3d dForceDChord = (ct - cn) / chordLength *
                        (wt * identity + t * w.transpose()) * (identity - t * t.transpose());
                    addPointPoint(i, hi, -h * theta * dForceDChord);
                    addPointPoint(i, lo, h * theta * dForceDChord);
                }
            }
        }
        constraintError = 0.0;
        for (Eigen::Index j = 0; j < s; ++j) {
            const Eigen::Vector3d d = xTheta.col(j + 1) - xTheta.col(j);
            const Eigen::Vector3d pull = lambda(j) / l(j) * d;  // tension force on point j
            const double pullNoise =
                h * std::abs(lambda(j)) / l(j) * (xTheta.col(j + 1).norm() + xTheta.col(j).norm());
            if (!isHeld(j)) {
                residual.col(j) -= h * pull;
                magnitude(j) += h * pull.norm();
                noise(j) += pullNoise;
            }
            if (!isHeld(j + 1)) {
                residual.col(j + 1) += h * pull;
                magnitude(j + 1) += h * pull.norm();
                noise(j + 1) += pullNoise;
            }
            const double k = h * theta * lambda(j) / l(j);
            addPointPoint(j, j, k * identity);
            addPointPoint(j, j + 1, -k * identity);
            addPointPoint(j + 1, j + 1, k * identity);
            addPointPoint(j + 1, j, -k * identity);
            addPointTension(j, j, -h / l(j) * d);
            addPointTension(j + 1, j, h / l(j) * d);

            const Eigen::Vector3d dy = y.col(j + 1) - y.col(j);
            if (isHeld(j) && isHeld(j + 1)) {
                lu_.add(tensionRow(j), tensionRow(j), 1.0);
                rhs(tensionRow(j)) = 0.0;
                continue;
            }
            const double dyLength = dy.norm();
            const double c = (dyLength - l(j)) * (dyLength + l(j)) / (2.0 * l(j));
            rhs(tensionRow(j)) = c;
            constraintError = std::max(constraintError, std::abs(c) / l(j));
            addTensionPoint(j, j + 1, dy / l(j));
            addTensionPoint(j, j, -dy / l(j));
        }
        bool residualSmall = true;
        for (Eigen::Index i = 0; i < n; ++i) {
            if (isHeld(i)) {
                for (int a = 0; a < 3; ++a) {
                    lu_.add(pointRow(i) + a, pointRow(i) + a, 1.0);
                    rhs(pointRow(i) + a) = 0.0;
                }
                continue;
            }
            const double allowed = settings.residualTolerance * magnitude(i) +
                                   64.0 * std::numeric_limits<double>::epsilon() * noise(i);
            if (residual.col(i).norm() > allowed) residualSmall = false;
            rhs.segment<3>(pointRow(i)) = rowScale(i) * residual.col(i);
        }

        // ---- convergence -----------------------------------------------------------
        // Segment lengths cannot be computed closer than round-off in the coordinates
        // (relative to point 0): never ask for better than that.
        const double roundOff = 16.0 * std::numeric_limits<double>::epsilon() *
                                y.colwise().norm().maxCoeff() / shortest;
        const double constraintTarget = std::max(settings.constraintTolerance, roundOff);
        const bool updateSmall = lastUpdate <= std::max(settings.updateTolerance, roundOff);
        if (constraintError <= constraintTarget && (residualSmall || updateSmall)) {
            result.converged = true;
            break;
        }
        // Stalled at round-off (no more progress, tiny updates): accept if the
        // constraints hold to the hard limit.
        const bool stalled = iteration > 0 && constraintError > 0.5 * previousConstraintError &&
                             lastUpdate <= 1e-8;
        if (stalled || iteration >= settings.maxNewtonIterations) {
            if (constraintError <= settings.acceptableConstraintError && lastUpdate <= 1e-8) {
                result.converged = true;
                result.loose = true;
            }
            break;
        }
        previousConstraintError = constraintError;

        // ---- Newton update ---------------------------------------------------------
        if (!lu_.factorize()) break;
        rhs = -rhs;
        lu_.solveInPlace(rhs);
        ++result.iterations;
        double biggest = 0.0;
        for (Eigen::Index i = 0; i < n; ++i) {
            if (isHeld(i)) continue;
            const Eigen::Vector3d step = rhs.segment<3>(pointRow(i));
            y.col(i) += step;
            biggest = std::max(biggest, step.norm());
        }
        for (Eigen::Index j = 0; j < s; ++j) lambda(j) += lambdaScale(j) * rhs(tensionRow(j));
        lastUpdate = biggest / shortest;
        if (!std::isfinite(lastUpdate) || !lambda.allFinite()) break;
    }
    if (!result.converged) return result;

    // ---- accept ---------------------------------------------------------------------
    for (Eigen::Index j = 0; j < s; ++j) {
        const Eigen::Vector3d before = (xn.col(j + 1) - xn.col(j)) / l(j);
        const Eigen::Vector3d after = (y.col(j + 1) - y.col(j)) / l(j);
        result.maxRotation = std::max(result.maxRotation, (after - before).norm());
    }
    for (Eigen::Index i = 0; i < n; ++i) {
        if (isHeld(i)) {
            state.velocities.col(i) = fiber.heldPointVelocity(i);
        } else {
            state.velocities.col(i) = ((y.col(i) - xn.col(i)) / h - (1.0 - theta) * vn.col(i)) / theta;
        }
    }
    state.positions = y.colwise() + origin;
    state.tension = lambda;
    return result;
}

}  // namespace dropletFiber
