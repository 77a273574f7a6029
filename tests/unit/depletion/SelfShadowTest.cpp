// The self-shadow of a fiber's depth (docs/model.md sec. 7, P21; depletion/SelfShadow.hpp):
// the strip across the flow per grid direction, and sigma per corner such that the lanes
// crossing a fiber collect the integral of f + f^2 / 2 (f the fiber's smeared lane depth),
// checked here against the lane integrals by quadrature, at faces and inside.
#include "depletion/SelfShadow.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace dropletFiber;

namespace
{
// A 2D grid across x (columns spacings of 1 mm), one spacing along y, flat in z.
GridSpec columnsGrid(int columns)
{
    GridSpec spec;
    spec.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
    spec.upper = Eigen::Vector3d(columns * 1e-3, 1e-3, 1e-3);
    spec.nodes = {{columns + 1, 2, 1}};
    return spec;
}

double hat(double u)
{
    return std::max(0.0, 1.0 - std::abs(u));
}
} // namespace

TEST(SelfShadow, StripIsAcrossTheSegmentAndTheFlow)
{
    const double c = 1.4e-4;
    const Eigen::Vector3d alongZ(0.0, 0.0, 2e-3), flowY(0.0, 1.0, 0.0);
    const Eigen::Vector3d strip = stripAcrossFlow(c, alongZ, flowY);
    EXPECT_NEAR(strip.x(), c, 1e-18);
    EXPECT_EQ(strip.y(), 0.0);
    EXPECT_EQ(strip.z(), 0.0);
    // A fiber at 45 degrees in the x-z plane: half of the strip in each direction
    const Eigen::Vector3d oblique = stripAcrossFlow(c, Eigen::Vector3d(1e-3, 0.0, 1e-3), flowY);
    EXPECT_NEAR(oblique.x(), 0.5 * c, 1e-18);
    EXPECT_NEAR(oblique.z(), 0.5 * c, 1e-18);
    EXPECT_NEAR(oblique.sum(), c, 1e-18);
    // Along the flow, or without one: no strip
    EXPECT_EQ(stripAcrossFlow(c, Eigen::Vector3d(0.0, 1e-3, 0.0), flowY).norm(), 0.0);
    EXPECT_EQ(stripAcrossFlow(c, alongZ, Eigen::Vector3d::Zero()).norm(), 0.0);
}

TEST(SelfShadow, LanesCollectTheFibersDepthAndHalfItsSquare)
{
    // A fiber at x_F across a flow along y: column n takes phi_n = (c/h) hat_n(x_F) / H_n;
    // with phi'_n = phi_n (1 + sigma_n) the lanes must collect int f + int f^2 / 2 (f =
    // sum phi_n hat_n): at a face, beside it and inside, for several x_F.
    const int columns = 4;
    const GridSpec spec = columnsGrid(columns);
    const double h = 1e-3, c = 1.4e-4;
    const Eigen::Vector3d strip(c, 0.0, 0.0);
    for (const double xF : {0.0, 0.3e-3, 1.0e-3, 1.5e-3, 2.7e-3, 4.0e-3})
    {
        const CornerWeights corners = multilinearWeights(spec, Eigen::Vector3d(xF, 0.4e-3, 0.5e-3));
        const std::array<double, 8> sigma = selfShadow(spec, corners, strip);
        std::array<double, columns + 1> phi{}, shadowed{};
        for (int k = 0; k < corners.count; ++k)
        {
            const int n = static_cast<int>(corners.node[static_cast<std::size_t>(k)] % (columns + 1));
            const double dual = n == 0 || n == columns ? 0.5 : 1.0;
            const double value = c / h * hat(xF / h - n) / dual;
            // the corners along y (k and k + 2) share a column and sigma
            if (k < 2)
            {
                phi[static_cast<std::size_t>(n)] += value;
                shadowed[static_cast<std::size_t>(n)] += value * (1.0 + sigma[static_cast<std::size_t>(k)]);
            }
            EXPECT_EQ(sigma[static_cast<std::size_t>(k)], sigma[static_cast<std::size_t>(k % 2)]);
        }
        // Lane integrals by the midpoint rule (exact to 1e-9 here)
        const int pieces = 40000;
        double linear = 0.0, square = 0.0, collected = 0.0;
        for (int k = 0; k < pieces; ++k)
        {
            const double x = columns * (k + 0.5) / pieces; // spacings
            double f = 0.0, g = 0.0;
            for (int n = 0; n <= columns; ++n)
            {
                f += phi[static_cast<std::size_t>(n)] * hat(x - n);
                g += shadowed[static_cast<std::size_t>(n)] * hat(x - n);
            }
            linear += f * columns / pieces;
            square += f * f * columns / pieces;
            collected += g * columns / pieces;
        }
        EXPECT_NEAR(linear, c / h, 1e-9) << "x_F " << xF;
        EXPECT_NEAR(collected, linear + 0.5 * square, 1e-9) << "x_F " << xF;
    }
}

TEST(SelfShadow, MeanOverTheFibersPositionIsAQuarterOfTheStripOverTheSpacing)
{
    // P20's excess, c / 4h on average over x_F inside: the hat-weighted mean of sigma
    const GridSpec spec = columnsGrid(4);
    const double h = 1e-3, c = 1.4e-4;
    const int positions = 1000;
    double mean = 0.0;
    for (int k = 0; k < positions; ++k)
    {
        const double xF = (1.0 + (k + 0.5) / positions) * h;
        const CornerWeights corners = multilinearWeights(spec, Eigen::Vector3d(xF, 0.5e-3, 0.5e-3));
        const std::array<double, 8> sigma = selfShadow(spec, corners, Eigen::Vector3d(c, 0.0, 0.0));
        for (int i = 0; i < corners.count; ++i)
        {
            mean += corners.weight[static_cast<std::size_t>(i)] * sigma[static_cast<std::size_t>(i)]
                / positions;
        }
    }
    EXPECT_NEAR(mean, c / (4.0 * h), 1e-7);
}

TEST(SelfShadow, FlatDirectionIsUniformAcrossItsThickness)
{
    // A fiber lying in the plane of a one-layer grid, across the flow: its strip is across
    // the layer (thickness T = 1 mm), smeared uniformly over it: sigma = c / (2T) everywhere
    const GridSpec spec = columnsGrid(4);
    const double c = 1.4e-4;
    const CornerWeights corners = multilinearWeights(spec, Eigen::Vector3d(1.3e-3, 0.5e-3, 0.5e-3));
    const std::array<double, 8> sigma = selfShadow(spec, corners, Eigen::Vector3d(0.0, 0.0, c));
    for (int i = 0; i < corners.count; ++i)
    {
        EXPECT_NEAR(sigma[static_cast<std::size_t>(i)], c / 2e-3, 1e-15);
    }
}

TEST(SelfShadow, DepthIsLinearToSecondOrderAndSaturatesAtTheWholeNode)
{
    const double sigma = 0.05;
    for (const double a : {1e-6, 1e-3, 0.02})
    {
        // a (1 + sigma) + a^3 / 3 + ...
        EXPECT_NEAR(shadowedDepth(a, sigma), a * (1.0 + sigma), 0.4 * a * a * a) << a;
    }
    EXPECT_TRUE(std::isinf(shadowedDepth(1.0, sigma)));
    EXPECT_GT(shadowedDepth(1.0 - 1e-9, sigma), 15.0); // tends to saturation
    // A part without a strip: P13's -ln(1 - a)
    EXPECT_EQ(shadowedDepth(0.3, 0.0), -std::log1p(-0.3));
}
