// Eq. 23: the closed form of PathWeight against an independent reference, adaptive
// Gauss-Legendre quadrature of eq. 23 itself in long double: the integrand is phi(dist(tau)) with
// dist computed from p + tau v dt - g, and the limits tau_1, tau_2 are the roots of
// dist(tau) = reach (eq. 22), clipped to [0, 1].
#include "grid/PathWeight.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace dropletFiber;

namespace
{

using Real = long double;

// Gauss-Legendre nodes and weights on [-1, 1] in long double (Newton on P_n).
struct GaussRule
{
    static constexpr int n = 20;
    Real x[n];
    Real w[n];
};

const GaussRule& gauss()
{
    static const GaussRule rule = []
    {
        GaussRule r{};
        const Real pi = 3.141592653589793238462643383279502884L;
        for (int i = 0; i < GaussRule::n; ++i)
        {
            Real x = std::cos(pi * (i + 0.75L) / (GaussRule::n + 0.5L)), dp = 1.0L;
            for (int it = 0; it < 100; ++it)
            {
                Real p0 = 1.0L, p1 = x;
                for (int k = 2; k <= GaussRule::n; ++k)
                {
                    const Real p2 = ((2.0L * k - 1.0L) * x * p1 - (k - 1.0L) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                dp = GaussRule::n * (x * p1 - p0) / (x * x - 1.0L);
                const Real dx = p1 / dp;
                x -= dx;
                if (std::fabs(dx) < 1e-21L)
                {
                    break;
                }
            }
            r.x[i] = x;
            r.w[i] = 2.0L / ((1.0L - x * x) * dp * dp);
        }
        return r;
    }();
    return rule;
}

struct Reference
{
    Real gamma;
    Real reach;
    Real px, py, pz; // path start minus node
    Real dx, dy, dz; // displacement v dt

    Real phi(Real tau) const
    {
        const Real x = px + tau * dx, y = py + tau * dy, z = pz + tau * dz;
        const Real d2 = x * x + y * y + z * z;
        if (d2 >= reach * reach)
        {
            return 0.0L;
        }
        return std::exp(-gamma * d2) - std::exp(-gamma * reach * reach);
    }

    // Adaptive Gauss-Legendre (20 points, long double): accept an interval when the rule on
    // it and the sum of the rule on its halves agree to the absolute tolerance.
    Real rule(Real a, Real b) const
    {
        const GaussRule& g = gauss();
        const Real c = 0.5L * (a + b), h = 0.5L * (b - a);
        Real sum = 0.0L;
        for (int i = 0; i < GaussRule::n; ++i)
        {
            sum += g.w[i] * phi(c + h * g.x[i]);
        }
        return h * sum;
    }

    Real adaptive(Real a, Real b, Real whole, Real tolerance, int depth) const
    {
        const Real m = 0.5L * (a + b);
        const Real left = rule(a, m), right = rule(m, b);
        if (depth <= 0 || std::fabs(left + right - whole) <= tolerance)
        {
            return left + right;
        }
        return adaptive(a, m, left, tolerance, depth - 1) + adaptive(m, b, right, tolerance, depth - 1);
    }

    Real omega() const
    {
        const Real a = dx * dx + dy * dy + dz * dz;
        if (a == 0.0L)
        {
            return phi(0.0L);
        }
        // dist(tau)^2 = reach^2: a tau^2 + b tau + c = 0 (eq. 22), stable roots.
        const Real b = 2.0L * (dx * px + dy * py + dz * pz);
        const Real c = px * px + py * py + pz * pz - reach * reach;
        const Real disc = b * b - 4.0L * a * c;
        if (disc <= 0.0L)
        {
            return 0.0L; // eq. 20: the path never comes within reach
        }
        const Real q = -0.5L * (b + std::copysign(std::sqrt(disc), b));
        Real t1 = q / a, t2 = c / q;
        if (t1 > t2)
        {
            std::swap(t1, t2);
        }
        t1 = std::max(t1, 0.0L);
        t2 = std::min(t2, 1.0L);
        if (!(t2 > t1))
        {
            return 0.0L;
        }
        // First pass for the scale, then the tolerance relative to it.
        const Real coarse = rule(t1, t2);
        const Real tolerance = 1e-16L * std::fabs(coarse) + 1e-4900L;
        return adaptive(t1, t2, coarse, tolerance, 40);
    }
};

struct Case
{
    double gamma, reach;
    Eigen::Vector3d start, displacement, node;
};

double referenceOmega(const Case& c)
{
    const Eigen::Vector3d p = c.start - c.node;
    Reference r{c.gamma,           c.reach, p.x(), p.y(), p.z(), c.displacement.x(), c.displacement.y(),
                c.displacement.z()};
    return static_cast<double>(r.omega());
}

double closedForm(const Case& c)
{
    const ParcelKernel kernel = ParcelKernel::fromShape(c.gamma, c.reach);
    return PathWeight(kernel, c.start, c.displacement).omega(c.node);
}

// Squared closest distance of the node to the path segment, over reach^2, in long double.
Real rimGap(const Case& c)
{
    const Real px = c.node.x() - static_cast<Real>(c.start.x());
    const Real py = c.node.y() - static_cast<Real>(c.start.y());
    const Real pz = c.node.z() - static_cast<Real>(c.start.z());
    const Real dx = c.displacement.x(), dy = c.displacement.y(), dz = c.displacement.z();
    const Real dd = dx * dx + dy * dy + dz * dz;
    Real t = dd > 0.0L ? (px * dx + py * dy + pz * dz) / dd : 0.0L;
    t = std::min(1.0L, std::max(0.0L, t));
    const Real ex = px - t * dx, ey = py - t * dy, ez = pz - t * dz;
    const Real reach = c.reach;
    return 1.0L - (ex * ex + ey * ey + ez * ez) / (reach * reach);
}

// Relative agreement 1e-10. Two exceptions, both about the double range and the inputs,
// not the method: (1) values below 1e-280 (weights that underflow, physically nothing) are
// compared absolutely; (2) for a node within a relative gap g = 1 - d^2/reach^2 < 1e-5 of
// the rim of the support, the rounding of the double inputs alone changes omega by about
// 1e-16 / g relative (condition number of eq. 23 there), so the tolerance is 1e-15 / g.
::testing::AssertionResult agrees(const Case& c, double tolerance = 1e-10)
{
    const double ref = referenceOmega(c);
    const double got = closedForm(c);
    const double gap = static_cast<double>(rimGap(c));
    const double relTolerance = std::max(tolerance, 1e-15 / std::max(gap, 1e-300));
    const bool ok = std::abs(ref) > 1e-280 ? std::abs(got - ref) <= relTolerance * std::abs(ref)
                                           : std::abs(got) < 1e-270;
    if (ok)
    {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
        << "omega " << got << " reference " << ref << " rel.err " << (got - ref) / ref << " gamma " << c.gamma
        << " reach " << c.reach << " start " << c.start.transpose() << " disp " << c.displacement.transpose()
        << " node " << c.node.transpose() << " rim gap " << gap;
}

Eigen::Vector3d randomUnit(std::mt19937_64& rng, bool planar)
{
    std::normal_distribution<double> n(0.0, 1.0);
    Eigen::Vector3d v(n(rng), n(rng), planar ? 0.0 : n(rng));
    return v / v.norm();
}

} // namespace

TEST(PathWeight, MatchesQuadratureForRandomPathsAndNodes)
{
    std::mt19937_64 rng(20240601);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int tested = 0, nonZero = 0;
    for (int i = 0; i < 20000; ++i)
    {
        Case c;
        // alpha from 0.3 (n ~ 1) to 1000 (beyond the beta = 0.025 limit 800), reach from um to cm.
        const double alpha = std::exp(std::log(0.3) + unit(rng) * std::log(1000.0 / 0.3));
        c.reach = std::exp(std::log(1e-6) + unit(rng) * std::log(1e4));
        c.gamma = alpha / (c.reach * c.reach);
        const bool planar = (i % 2) == 0;
        c.node = Eigen::Vector3d(unit(rng), unit(rng), planar ? 0.0 : unit(rng)) * c.reach;
        // Path length from 1e-14 reach (point limit) to 5 reach, any direction.
        const double length = c.reach * std::exp(std::log(1e-14) + unit(rng) * std::log(5e14));
        c.displacement = length * randomUnit(rng, planar);
        // Start anywhere such that the path may or may not reach the node, may end inside.
        c.start = c.node + 1.3 * c.reach * randomUnit(rng, planar) * unit(rng) - unit(rng) * c.displacement;
        ASSERT_TRUE(agrees(c)) << "case " << i;
        ++tested;
        nonZero += referenceOmega(c) > 0.0 ? 1 : 0;
    }
    EXPECT_EQ(tested, 20000);
    EXPECT_GT(nonZero, 10000); // most cases really test a weight, not a zero
}

TEST(PathWeight, MatchesQuadratureForVanishingPathLength)
{
    // L -> 0: k = sqrt(alpha) L / r_max -> 0, where erf differences would cancel.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 1000; ++i)
    {
        Case c;
        c.reach = 1e-3;
        c.gamma = (0.5 + 800.0 * unit(rng)) / (c.reach * c.reach);
        c.node = Eigen::Vector3d::Zero();
        const double length = c.reach * std::pow(10.0, -16.0 + 15.0 * unit(rng));
        c.displacement = length * randomUnit(rng, false);
        c.start = 0.9 * c.reach * unit(rng) * randomUnit(rng, false);
        ASSERT_TRUE(agrees(c)) << "case " << i << " L/reach " << length / c.reach;
    }
}

TEST(PathWeight, ZeroVelocityGivesPhiOfDistance)
{
    const ParcelKernel kernel = ParcelKernel::fromShape(151.9 / 1e-4, 1e-2);
    const Eigen::Vector3d p(1e-3, -2e-3, 0.0);
    const PathWeight w(kernel, p, Eigen::Vector3d::Zero());
    for (double dx : {0.0, 1e-3, 5e-3, 9.9e-3, 1.0001e-2, 2e-2})
    {
        const Eigen::Vector3d g = p + Eigen::Vector3d(dx, 0.0, 0.0);
        const long double d = (g - p).norm();   // the distance as represented, not dx
        const long double gamma = 151.9 / 1e-4; // the double value the kernel holds
        const long double reach = 1e-2;
        const long double ref
            = d < reach ? std::exp(-gamma * d * d) - std::exp(-gamma * reach * reach) : 0.0L;
        EXPECT_NEAR(w.omega(g), static_cast<double>(ref), 1e-10 * static_cast<double>(ref)) << dx;
    }
}

TEST(PathWeight, NearestPointBeyondThePathEnds)
{
    // Node ahead of the end point and behind the start point (tau_min outside [0, 1]);
    // also a node the path line passes within reach of but only beyond its end.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 500; ++i)
    {
        Case c;
        c.reach = 1.0;
        c.gamma = 20.0 + 300.0 * unit(rng);
        c.start = Eigen::Vector3d::Zero();
        c.displacement = Eigen::Vector3d(0.2 + 2.0 * unit(rng), 0.0, 0.0);
        const double side = (i % 2 == 0) ? c.displacement.x() + 0.9 * unit(rng) : -0.9 * unit(rng);
        c.node = Eigen::Vector3d(side, 0.9 * (unit(rng) - 0.5), 0.0);
        ASSERT_TRUE(agrees(c)) << "case " << i;
    }
    Case beyond{100.0, 1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 0.0, 0.0),
                Eigen::Vector3d(2.5, 0.1, 0.0)};
    EXPECT_EQ(closedForm(beyond), 0.0); // distance to the segment 1.5 > reach
}

TEST(PathWeight, GrazingTheEdgeOfTheSupport)
{
    // Paths whose closest approach d_0 lies just inside the reach: the Gaussian and the
    // constant of eq. 12 nearly cancel (regime A of PathWeight.cpp). Gaps from 1e-6 to
    // 0.1 of reach^2; below 1e-5 the tolerance follows the conditioning (see agrees()).
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 1000; ++i)
    {
        Case c;
        c.reach = 2e-3;
        c.gamma = (0.5 + 800.0 * unit(rng)) / (c.reach * c.reach);
        const double gap = std::pow(10.0, -6.0 + 5.0 * unit(rng)); // (reach^2 - d0^2) / reach^2
        const double d0 = c.reach * std::sqrt(1.0 - gap);
        c.node = Eigen::Vector3d(0.0, d0, 0.0);
        const double length = c.reach * std::pow(10.0, -6.0 + 7.0 * unit(rng));
        c.displacement = Eigen::Vector3d(length, 0.0, 0.0);
        c.start = Eigen::Vector3d(-length * unit(rng) * 1.5 + 0.2 * c.reach * (unit(rng) - 0.5), 0.0, 0.0);
        ASSERT_TRUE(agrees(c)) << "case " << i << " gap " << gap;
    }
}

TEST(PathWeight, LongPathTendsToGaussianLineIntegral)
{
    // A long path passing a node at distance d_0: L omega -> int phi dlambda over the chord
    // = exp(-gamma d0^2) sqrt(pi/gamma) erf(sqrt(gamma) h) - 2 h exp(-gamma reach^2),
    // h = sqrt(reach^2 - d0^2) (analytic, independent of the code's regimes).
    const double gamma = 150.0, reach = 1.0, d0 = 0.3, length = 10.0;
    const ParcelKernel kernel = ParcelKernel::fromShape(gamma, reach);
    const PathWeight w(kernel, Eigen::Vector3d(-5.0, 0.0, 0.0), Eigen::Vector3d(length, 0.0, 0.0));
    const double h = std::sqrt(reach * reach - d0 * d0);
    const double expected = (std::exp(-gamma * d0 * d0) * std::sqrt(3.14159265358979323846 / gamma)
                                 * std::erf(std::sqrt(gamma) * h)
                             - 2.0 * h * std::exp(-gamma * reach * reach))
        / length;
    EXPECT_NEAR(w.omega(Eigen::Vector3d(0.0, d0, 0.0)), expected, 1e-14 * expected);
}
