#include "fiber/VelocityProjection.hpp"

#include <vector>

namespace dropletFiber
{

void projectVelocities(Fiber& fiber)
{
    if (fiber.immobile())
    {
        fiber.mutableState().velocities.setZero();
        return;
    }
    FiberState& state = fiber.mutableState();
    const Eigen::Index n = fiber.pointCount();
    const Eigen::Index s = n - 1;
    const Eigen::VectorXd m = fiber.pointMasses();
    Eigen::VectorXd inverseMass(n);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        if (fiber.pointHeld(i))
        {
            state.velocities.col(i) = fiber.heldPointVelocity(i);
            inverseMass(i) = 0.0;
        }
        else
        {
            inverseMass(i) = 1.0 / m(i);
        }
    }
    Eigen::Matrix3Xd e(3, s);
    for (Eigen::Index j = 0; j < s; ++j)
    {
        e.col(j) = (state.positions.col(j + 1) - state.positions.col(j)).normalized();
    }
    // Tridiagonal system: diag a, off-diagonal c (symmetric), rhs r.
    std::vector<double> a(static_cast<std::size_t>(s)), c(static_cast<std::size_t>(s), 0.0),
        r(static_cast<std::size_t>(s));
    for (Eigen::Index j = 0; j < s; ++j)
    {
        const auto J = static_cast<std::size_t>(j);
        a[J] = inverseMass(j) + inverseMass(j + 1);
        r[J] = e.col(j).dot(state.velocities.col(j + 1) - state.velocities.col(j));
        if (j + 1 < s)
            c[J] = -inverseMass(j + 1) * e.col(j).dot(e.col(j + 1));
        if (a[J] == 0.0)
        { // both ends held: nothing to project
            a[J] = 1.0;
            r[J] = 0.0;
            if (j + 1 < s)
                c[J] = 0.0;
            if (j > 0)
                c[J - 1] = 0.0;
        }
    }
    // Thomas algorithm (SPD, no pivoting needed).
    std::vector<double> cp(static_cast<std::size_t>(s), 0.0), mu(static_cast<std::size_t>(s));
    for (std::size_t j = 0; j < static_cast<std::size_t>(s); ++j)
    {
        const double sub = j > 0 ? c[j - 1] : 0.0;
        const double denom = a[j] - (j > 0 ? sub * cp[j - 1] : 0.0);
        cp[j] = c[j] / denom;
        mu[j] = (r[j] - (j > 0 ? sub * mu[j - 1] : 0.0)) / denom;
    }
    for (std::size_t j = static_cast<std::size_t>(s) - 1; j-- > 0;)
    {
        mu[j] -= cp[j] * mu[j + 1];
    }
    for (Eigen::Index j = 0; j < s; ++j)
    {
        const double impulse = mu[static_cast<std::size_t>(j)];
        state.velocities.col(j) += inverseMass(j) * impulse * e.col(j);
        state.velocities.col(j + 1) -= inverseMass(j + 1) * impulse * e.col(j);
    }
}

} // namespace dropletFiber
