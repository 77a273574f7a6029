// NodeWeightBatch against PathWeight::omegaFromOffset, node by node: the batch copies the
// formulas stage by stage and must give the same bits (PathWeightTest checks those
// against adaptive quadrature of eq. 23). Random boxes of nodes around random paths cover
// every regime: out of reach, one-sided (before and after), two-sided, clipped ends,
// the Taylor series and the edge quadrature, stationary and grid-aligned paths.
#include "grid/NodeWeightBatch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

using namespace dropletFiber;

namespace
{

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Census
{
    long nodes = 0;
    long nonZero = 0;
};

// Box of (2m + 1)^2 nodes (2D) or ^3 (3D) at spacing h around the path, compared node by node.
void compareBox(const PathWeight& path, const Eigen::Vector3d& start, double h, int m, bool planar,
                NodeWeightBatch& batch, Census& census)
{
    const int mz = planar ? 0 : m;
    std::vector<double> x;
    for (int i = -m; i <= m; ++i)
    {
        x.push_back(std::round(start.x() / h + i) * h);
    }
    const std::size_t rowLength = x.size();
    batch.start(path, rowLength * (2 * m + 1) * (2 * mz + 1));
    std::vector<Eigen::Vector3d> offsets;
    for (int k = -mz; k <= mz; ++k)
    {
        const double z = planar ? start.z() : std::round(start.z() / h + k) * h;
        for (int j = -m; j <= m; ++j)
        {
            const double y = std::round(start.y() / h + j) * h;
            batch.addRow(x.data(), rowLength, start.x(), y - start.y(), z - start.z());
            for (const double xi : x)
            {
                offsets.emplace_back(xi - start.x(), y - start.y(), z - start.z());
            }
        }
    }
    const double* omega = batch.evaluate();
    for (std::size_t s = 0; s < offsets.size(); ++s)
    {
        const double expected = path.omegaFromOffset(offsets[s]);
        ASSERT_TRUE(sameBits(omega[s], expected))
            << "slot " << s << ": batch " << omega[s] << " one node " << expected;
        ++census.nodes;
        census.nonZero += expected > 0.0 ? 1 : 0;
    }
}

} // namespace

TEST(NodeWeightBatch, BitIdenticalToOneNodeEvaluationForRandomPaths)
{
    std::mt19937_64 rng(20261123);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    NodeWeightBatch batch; // reused: the scratch must not leak between parcels
    Census census;
    for (int i = 0; i < 3000; ++i)
    {
        const bool planar = (i % 3) != 0;
        const double h = 1e-3;
        // Reach 0.5 to 6 spacings, alpha 0.3 to 300 (edge quadrature and Taylor included).
        const double reach = h * (0.5 + 5.5 * unit(rng));
        const double alpha = std::exp(std::log(0.3) + unit(rng) * std::log(1000.0));
        const ParcelKernel kernel = ParcelKernel::fromShape(alpha / (reach * reach), reach);
        // Path length 0 (stationary), 1e-13 reach, or up to 3 reach; every 7th grid-aligned.
        const int kind = i % 10;
        const double length = kind == 0 ? 0.0 : kind == 1 ? 1e-13 * reach : 3.0 * reach * unit(rng);
        Eigen::Vector3d direction(unit(rng) - 0.5, unit(rng) - 0.5, planar ? 0.0 : unit(rng) - 0.5);
        if (i % 7 == 0)
        {
            direction = Eigen::Vector3d(1.0, 0.0, 0.0);
        }
        direction.normalize();
        Eigen::Vector3d start(0.05 + h * unit(rng), 0.05 + h * unit(rng), planar ? 0.0 : 0.05 + h * unit(rng));
        if (i % 11 == 0)
        {
            start = Eigen::Vector3d(0.05, 0.051, planar ? 0.0 : 0.052); // on a node
        }
        PathWeight path(kernel, start, length * direction);
        if (i % 5 == 0)
        {
            path.limitTo(0.7 * reach); // negligible-weight cut
        }
        const int m = static_cast<int>(std::ceil((reach + length) / h)) + 1;
        compareBox(path, start, h, m, planar, batch, census);
        if (HasFatalFailure())
        {
            FAIL() << "case " << i;
        }
    }
    EXPECT_GT(census.nonZero, 300000); // 4 % of the 13 M nodes: the boxes are generous
}

TEST(NodeWeightBatch, SingleNodesMatchPathWeight)
{
    const ParcelKernel kernel = ParcelKernel::fromShape(42.0 / 9e-6, 3e-3);
    const PathWeight path(kernel, Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(2e-3, 1e-3, 0.0));
    NodeWeightBatch batch;
    batch.start(path, 4);
    const Eigen::Vector3d nodes[4] = {{-2e-3, 0.0, 0.0}, {1e-3, 0.5e-3, 0.0}, {4e-3, 2e-3, 0.0}, {9e-3, 0.0, 0.0}};
    for (const auto& node : nodes)
    {
        batch.add(node);
    }
    const double* omega = batch.evaluate();
    for (int s = 0; s < 4; ++s)
    {
        EXPECT_TRUE(sameBits(omega[s], path.omega(nodes[s]))) << s;
    }
    EXPECT_GT(omega[1], omega[0]); // on the path vs behind its start
    EXPECT_EQ(omega[3], 0.0);      // 9 mm from the path, reach 3 mm
}
