// Bilinear/trilinear interpolation reproduces linear fields exactly (the defining
// property), both for the raw weights and for DensityGrid::sample of rho and of the
// momentum density rho u.
#include "grid/DensityGrid.hpp"
#include "grid/MultilinearWeights.hpp"

#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace dropletFiber;

namespace
{

double linear(const Eigen::Vector3d& p, bool planar)
{
    return 1.5 + 2.0 * p.x() - 3.0 * p.y() + (planar ? 0.0 : 0.7 * p.z());
}

} // namespace

TEST(MultilinearWeights, ReproduceLinearFieldsExactly)
{
    std::mt19937_64 rng(1);
    for (const GridSpec& spec : {test::offsetGrid3D(), test::offsetGrid2D()})
    {
        const bool planar = spec.flat(2);
        std::uniform_real_distribution<double> ux(spec.lower.x(), spec.upper.x()),
            uy(spec.lower.y(), spec.upper.y()), uz(spec.lower.z(), spec.upper.z());
        for (int n = 0; n < 2000; ++n)
        {
            Eigen::Vector3d p(ux(rng), uy(rng), uz(rng));
            if (n % 10 == 0)
            {
                p.x() = spec.upper.x(); // on the boundary
            }
            const CornerWeights w = multilinearWeights(spec, p);
            EXPECT_EQ(w.count, planar ? 4 : 8);
            double value = 0.0, weightSum = 0.0;
            for (int c = 0; c < w.count; ++c)
            {
                const std::size_t node = w.node[static_cast<std::size_t>(c)];
                const int i = static_cast<int>(node % static_cast<std::size_t>(spec.nodes[0]));
                const int j = static_cast<int>((node / static_cast<std::size_t>(spec.nodes[0]))
                                               % static_cast<std::size_t>(spec.nodes[1]));
                const int k
                    = static_cast<int>(node / static_cast<std::size_t>(spec.nodes[0] * spec.nodes[1]));
                EXPECT_GE(w.weight[static_cast<std::size_t>(c)], 0.0);
                value += w.weight[static_cast<std::size_t>(c)] * linear(spec.nodePosition(i, j, k), planar);
                weightSum += w.weight[static_cast<std::size_t>(c)];
            }
            EXPECT_NEAR(weightSum, 1.0, 1e-14);
            EXPECT_NEAR(value, linear(p, planar), 1e-13);
        }
    }
}

TEST(MultilinearWeights, DensityGridSampleReproducesLinearRhoAndMomentumDensity)
{
    for (const GridSpec& spec : {test::offsetGrid3D(), test::offsetGrid2D()})
    {
        const bool planar = spec.flat(2);
        DensityGrid grid(spec);
        // One committed step whose node sums are a linear rho and a linear momentum density:
        // mass_g = V_g rho(g), momentum_g = V_g (rho u)(g), V_g the node's (dual-cell) volume.
        std::vector<double> values;
        for (int k = 0; k < spec.nodes[2]; ++k)
            for (int j = 0; j < spec.nodes[1]; ++j)
                for (int i = 0; i < spec.nodes[0]; ++i)
                {
                    const Eigen::Vector3d g = spec.nodePosition(i, j, k);
                    const double V = spec.dualVolume(i, j, k);
                    const double rho = linear(g, planar);
                    values.insert(values.end(),
                                  {V * rho, V * 10.0, V * 10.0 * 1e-5, V * rho * 2e-5, V * (0.1 + g.x()),
                                   V * (0.2 - g.y()), V * 0.3});
                }
        grid.unpackStep(spec.fullBox(), values);
        grid.commitStep();
        std::mt19937_64 rng(2);
        std::uniform_real_distribution<double> ux(spec.lower.x(), spec.upper.x()),
            uy(spec.lower.y(), spec.upper.y()), uz(spec.lower.z(), spec.upper.z());
        for (int n = 0; n < 500; ++n)
        {
            const Eigen::Vector3d p(ux(rng), uy(rng), uz(rng));
            const DropletFieldValue f = grid.sample(p);
            ASSERT_TRUE(f.inside);
            EXPECT_NEAR(f.rho, linear(p, planar), 1e-12);
            EXPECT_NEAR(f.rho * f.velocity.x(), 0.1 + p.x(), 1e-12);
            EXPECT_NEAR(f.rho * f.velocity.y(), 0.2 - p.y(), 1e-12);
            EXPECT_NEAR(f.rho * f.velocity.z(), 0.3, 1e-12);
            EXPECT_NEAR(f.numberDensity, 10.0, 1e-12);
            EXPECT_NEAR(f.rMeanNumber, 1e-5, 1e-18);
            EXPECT_NEAR(f.rMeanMass, 2e-5, 1e-18);
        }
        // Outside the box in an active direction: no droplets known.
        const DropletFieldValue out = grid.sample(spec.upper + Eigen::Vector3d(0.01, 0.0, 0.0));
        EXPECT_FALSE(out.inside);
        EXPECT_EQ(out.rho, 0.0);
    }
}

TEST(MultilinearWeights, FlatDirectionIsIgnoredWhenSampling)
{
    const GridSpec spec = test::offsetGrid2D();
    const Eigen::Vector3d p(0.01, 0.03, 0.0005);
    const CornerWeights a = multilinearWeights(spec, p);
    const CornerWeights b = multilinearWeights(spec, Eigen::Vector3d(0.01, 0.03, 5.0));
    for (int c = 0; c < 4; ++c)
    {
        EXPECT_EQ(a.node[static_cast<std::size_t>(c)], b.node[static_cast<std::size_t>(c)]);
        EXPECT_EQ(a.weight[static_cast<std::size_t>(c)], b.weight[static_cast<std::size_t>(c)]);
    }
    EXPECT_TRUE(insideActiveBox(spec, Eigen::Vector3d(0.01, 0.03, 5.0)));
}
