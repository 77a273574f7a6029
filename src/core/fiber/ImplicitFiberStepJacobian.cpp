// ImplicitFiberStep's Jacobian (see ImplicitFiberStep.hpp): the exact derivative of the
// scaled residual rows in the band, its constant part (mass, the linear bending force, the
// rows of held points) once per sub-step, and drag and tension added to a copy of it at
// every Newton iteration that needs an update.
#include "fiber/ImplicitFiberStep.hpp"

namespace dropletFiber
{

void ImplicitFiberStep::buildConstantJacobian()
{
    const Eigen::Index n = n_;
    const Eigen::Index s = n - 1;
    const double h = h_, theta = theta_;

    // In the order the full assembly adds it: mass, then bending (linear force:
    // constant coefficients), then the rows of held points and of segments between
    // two held points (identity, nothing else).
    BandedLU& J = constantJacobian_;
    J.reset(4 * n - 1, bandwidth, bandwidth);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        if (held(i))
            continue;
        const double diagonal = rowScale_(i) * (m_(i) / (theta * h));
        for (int a = 0; a < 3; ++a)
            J.add(pointRow(i) + a, pointRow(i) + a, diagonal);
    }
    addBendingJacobian(J);
    for (Eigen::Index j = 0; j < s; ++j)
    {
        if (held(j) && held(j + 1))
            J.add(tensionRow(j), tensionRow(j), 1.0);
    }
    // Constraint rows in units of their points' rows: the mean of the two points'
    // diagonal (1 + the bending stiffness over h^2 theta^2 / m, up to ~1e3 for thin
    // glass fibers at the CFD step). Unscaled, the constraint rows are that much
    // smaller than the point rows and their pivots fail any threshold.
    constraintScale_.resize(s);
    for (Eigen::Index j = 0; j < s; ++j)
    {
        const double here = held(j) ? 1.0 : J.coeff(pointRow(j), pointRow(j));
        const double next = held(j + 1) ? 1.0 : J.coeff(pointRow(j + 1), pointRow(j + 1));
        constraintScale_(j) = 0.5 * (here + next);
    }
    for (Eigen::Index i = 0; i < n; ++i)
    {
        if (!held(i))
            continue;
        for (int a = 0; a < 3; ++a)
            J.add(pointRow(i) + a, pointRow(i) + a, 1.0);
    }
}

void ImplicitFiberStep::addBendingJacobian(BandedLU& J) const
{
    const double h = h_, theta = theta_;
    for (const BendingJoint& joint : joints_)
    {
        for (int a = 0; a < joint.pointCount; ++a)
        {
            const Eigen::Index p = joint.point[static_cast<std::size_t>(a)];
            const double ca = joint.coefficient[static_cast<std::size_t>(a)];
            for (int c = 0; c < joint.pointCount; ++c)
            {
                const Eigen::Index q = joint.point[static_cast<std::size_t>(c)];
                if (held(p) || held(q))
                    continue;
                const double cc = joint.coefficient[static_cast<std::size_t>(c)];
                const double value = rowScale_(p) * (h * theta * joint.stiffness * ca * cc);
                for (int b = 0; b < 3; ++b)
                    J.add(pointRow(p) + b, pointRow(q) + b, value);
            }
        }
    }
}

void ImplicitFiberStep::assembleJacobian(const PointDrag& drag)
{
    lu_.assignMatrix(constantJacobian_);
    if (drag.airVelocity != nullptr)
        addDragJacobian();
    addTensionJacobian();
}

void ImplicitFiberStep::addDragJacobian()
{
    BandedLU& J = lu_;
    for (Eigen::Index i = 0; i < n_; ++i)
    {
        if (held(i))
            continue;
        const double cn = cn_(i), ct = ct_(i);
        if (cn == 0.0 && ct == 0.0)
            continue;
        const Eigen::Vector3d t = tangent_.col(i);
        const double scale = rowScale_(i);
        // d(-h f)/dy through v_theta = (y - x_n) / h: (c_n I + (c_t - c_n) t t^T)
        for (int a = 0; a < 3; ++a)
        {
            const double outer = (ct - cn) * t(a);
            for (int b = 0; b < 3; ++b)
            {
                const double value = (a == b ? cn : 0.0) + outer * t(b);
                J.add(pointRow(i) + a, pointRow(i) + b, scale * value);
            }
        }
        if (ct == cn)
            continue;
        addDragTangentJacobian(i);
    }
}

void ImplicitFiberStep::addDragTangentJacobian(Eigen::Index i)
{
    // d(-h f)/dy through the tangent t = chord / |chord| at x_theta:
    //   df/dchord = (c_t - c_n) / |chord| (wt I + t w^T)(I - t t^T)
    //             = (c_t - c_n) / |chord| (wt (I - t t^T) + t w_n^T),
    // w_n = w - wt t (w^T t = wt), written out instead of a matrix product.
    BandedLU& J = lu_;
    const double cn = cn_(i), ct = ct_(i);
    const Eigen::Vector3d t = tangent_.col(i);
    const double scale = rowScale_(i);
    Eigen::Index hi, lo;
    tangentStencil(i, n_, hi, lo);
    const double wt = wt_(i);
    const Eigen::Vector3d wn = relativeAir_.col(i) - wt * t;
    const double dForce = scale * h_ * theta_ * (ct - cn) / chordLength_(i);
    double block[3][3]; // scale * h theta df/dchord
    for (int a = 0; a < 3; ++a)
    {
        for (int b = 0; b < 3; ++b)
        {
            block[a][b] = dForce * (wt * ((a == b ? 1.0 : 0.0) - t(a) * t(b)) + t(a) * wn(b));
        }
    }
    if (!held(hi))
    {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                J.add(pointRow(i) + a, pointRow(hi) + b, -block[a][b]);
    }
    if (!held(lo))
    {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                J.add(pointRow(i) + a, pointRow(lo) + b, block[a][b]);
    }
}

void ImplicitFiberStep::addTensionJacobian()
{
    const Eigen::Index s = n_ - 1;
    const double h = h_, theta = theta_;
    const Eigen::VectorXd& l = *l_;
    BandedLU& J = lu_;
    for (Eigen::Index j = 0; j < s; ++j)
    {
        const bool heldJ = held(j), heldNext = held(j + 1);
        const double k = h * theta * lambda_(j) / l(j);
        if (!heldJ)
        {
            for (int a = 0; a < 3; ++a)
                J.add(pointRow(j) + a, pointRow(j) + a, rowScale_(j) * k);
        }
        if (!heldJ && !heldNext)
        {
            for (int a = 0; a < 3; ++a)
                J.add(pointRow(j) + a, pointRow(j + 1) + a, rowScale_(j) * -k);
        }
        if (!heldNext)
        {
            for (int a = 0; a < 3; ++a)
                J.add(pointRow(j + 1) + a, pointRow(j + 1) + a, rowScale_(j + 1) * k);
        }
        if (!heldJ && !heldNext)
        {
            for (int a = 0; a < 3; ++a)
                J.add(pointRow(j + 1) + a, pointRow(j) + a, rowScale_(j + 1) * -k);
        }
        const Eigen::Vector3d d = segment_.col(j);
        if (!heldJ)
        {
            const double scale = rowScale_(j) * lambdaScale_(j);
            for (int a = 0; a < 3; ++a)
                J.add(pointRow(j) + a, tensionRow(j), scale * (-h / l(j) * d(a)));
        }
        if (!heldNext)
        {
            const double scale = rowScale_(j + 1) * lambdaScale_(j);
            for (int a = 0; a < 3; ++a)
                J.add(pointRow(j + 1) + a, tensionRow(j), scale * (h / l(j) * d(a)));
        }
        if (heldJ && heldNext)
            continue; // constant row (in constantJacobian_)
        const Eigen::Vector3d dy = dy_.col(j);
        const double rowScale = constraintScale_(j) / l(j);
        if (!heldNext)
        {
            for (int b = 0; b < 3; ++b)
                J.add(tensionRow(j), pointRow(j + 1) + b, rowScale * dy(b));
        }
        if (!heldJ)
        {
            for (int b = 0; b < 3; ++b)
                J.add(tensionRow(j), pointRow(j) + b, -rowScale * dy(b));
        }
    }
}

} // namespace dropletFiber
