// The batched node weights (PathWeightBatch, compiled for AVX2 + FMA in every x86-64 build,
// KernelBuild.hpp) against the per-node PathWeight::omegaFromOffset, for many random
// parcels: 2D and 3D, moving (from nearly stationary to many reaches) and stationary, with
// and without the negligible-weight cut, reach 1, 3 and 10 node spacings. The two differ
// only by the inline exp and erfc (~1 ulp), so they agree to 1e-13 of the parcel's largest
// weight. On a CPU without AVX2 + FMA (or a build without the batched code) the test
// reports a skip.
#include "grid/PathWeight.hpp"
#include "grid/PathWeightBatch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace dropletFiber;

TEST(PathWeightBatch, MatchesPerNodeOmega)
{
    if (!PathWeightBatch::cpuSupported())
    {
        GTEST_SKIP() << "this CPU has no AVX2 + FMA (or this build no batched kernel): nothing to test";
    }
    constexpr std::size_t laneCount = PathWeightBatch::laneCount;
    std::mt19937_64 random(20261123);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    PathWeightBatch batch; // reused across parcels, as in the deposit
    std::vector<Eigen::Vector3d> offsets;
    std::vector<double> lambdaM, d0Squared, omega;
    double worst = 0.0;
    long comparedNodes = 0, weightedNodes = 0, stationaryParcels = 0;
    for (int dimension : {2, 3})
    {
        for (double reach : {1.0, 3.0, 10.0}) // node spacing 1
        {
            for (bool cut : {false, true})
            {
                const int parcels = (dimension == 3 && reach == 10.0) ? 60 : 400;
                for (int p = 0; p < parcels; ++p)
                {
                    // alpha from 0.3 to 1000, log-uniform.
                    const double alpha = 0.3 * std::pow(1000.0 / 0.3, unit(random));
                    const ParcelKernel kernel = ParcelKernel::fromShape(alpha / (reach * reach), reach);
                    Eigen::Vector3d start(unit(random), unit(random), dimension == 3 ? unit(random) : 0.0);
                    // Path length: 0 (stationary), 1e-10 reach (regime B), up to 5 reaches.
                    const int kind = p % 10;
                    const double length = kind == 0 ? 0.0
                        : kind == 1                 ? 1e-10 * reach
                                                    : reach * 5.0 * std::pow(1e-4, unit(random));
                    Eigen::Vector3d direction(unit(random) - 0.5, unit(random) - 0.5,
                                              dimension == 3 ? unit(random) - 0.5 : 0.0);
                    direction.normalize();
                    PathWeight path(kernel, start, length * direction);
                    if (cut)
                    {
                        path.limitTo(reach * (0.3 + 0.7 * unit(random)));
                    }
                    // The nodes of the bounding box of the swept capsule (as the deposit).
                    offsets.clear();
                    const Eigen::Vector3d end = start + length * direction;
                    const int kLo = dimension == 3
                        ? static_cast<int>(std::floor(std::min(start.z(), end.z()) - reach))
                        : 0;
                    const int kHi = dimension == 3
                        ? static_cast<int>(std::ceil(std::max(start.z(), end.z()) + reach))
                        : 0;
                    for (int k = kLo; k <= kHi; ++k)
                    {
                        for (int j = static_cast<int>(std::floor(std::min(start.y(), end.y()) - reach));
                             j <= static_cast<int>(std::ceil(std::max(start.y(), end.y()) + reach)); ++j)
                        {
                            for (int i = static_cast<int>(std::floor(std::min(start.x(), end.x()) - reach));
                                 i <= static_cast<int>(std::ceil(std::max(start.x(), end.x()) + reach)); ++i)
                            {
                                offsets.emplace_back(Eigen::Vector3d(i, j, k) - start);
                            }
                        }
                    }
                    if (path.stationary())
                    {
                        // The deposit evaluates stationary parcels with omegaFromOffset in
                        // every case (DensityGrid::deposit); nothing batched to compare.
                        ++stationaryParcels;
                        continue;
                    }
                    const std::size_t count = offsets.size();
                    const std::size_t padded = (count + laneCount - 1) / laneCount * laneCount;
                    lambdaM.assign(padded, 0.0);
                    d0Squared.assign(padded, 2.0 * reach * reach);
                    omega.assign(padded, -1.0);
                    for (std::size_t n = 0; n < count; ++n)
                    {
                        path.project(offsets[n], lambdaM[n], d0Squared[n]);
                    }
                    batch.omegas(path, lambdaM.data(), d0Squared.data(), omega.data(), padded);
                    std::vector<double> reference(count);
                    double largest = 0.0;
                    for (std::size_t n = 0; n < count; ++n)
                    {
                        reference[n] = path.omegaFromOffset(offsets[n]);
                        largest = std::max(largest, std::abs(reference[n]));
                    }
                    if (largest == 0.0)
                    {
                        // The cut left nothing (a random cut can; the deposit's cannot): the
                        // batched weights must be 0 too.
                        for (std::size_t n = 0; n < count; ++n)
                        {
                            ASSERT_EQ(omega[n], 0.0);
                        }
                        continue;
                    }
                    for (std::size_t n = 0; n < count; ++n)
                    {
                        const double error = std::abs(omega[n] - reference[n]) / largest;
                        worst = std::max(worst, error);
                        ASSERT_LE(error, 1e-13)
                            << "dimension " << dimension << " reach " << reach << " cut " << cut << " alpha "
                            << alpha << " length " << length << " node " << n << ": batched " << omega[n]
                            << " per node " << reference[n];
                        if (reference[n] == 0.0 && path.cutoffSquared() < reach * reach
                            && !(d0Squared[n] < path.cutoffSquared()))
                        {
                            ASSERT_EQ(omega[n], 0.0); // beyond the cut: exactly 0, as per node
                        }
                        weightedNodes += reference[n] > 0.0 ? 1 : 0;
                    }
                    for (std::size_t n = count; n < padded; ++n)
                    {
                        ASSERT_EQ(omega[n], 0.0); // padding
                    }
                    comparedNodes += static_cast<long>(count);
                }
            }
        }
    }
    EXPECT_GT(weightedNodes, 100000);
    EXPECT_GT(stationaryParcels, 0);
    char text[64];
    std::snprintf(text, sizeof text, "%.3e over %ld nodes", worst, comparedNodes);
    RecordProperty("worstRelativeToLargest", text);
    std::printf("worst |batched - per node| / largest = %s (%ld weighted)\n", text, weightedNodes);
}
