// Weighted fibers in depletion (docs/model.md sec. 9, P40-P41): a demand part asked by N
// physical fibers (CaptureLimit::addDemand's interceptors; here parts without a strip, so
// P13's depth, no self-shadow) must act as N independent
// interceptors, i.e. as N parts of the same mass added one by one (P13's product), and
// not as one fiber N times as thick (N d_sn / s_n in one factor) nor as N times one
// fiber's removal. The discrete hits' realised removal (P31) must follow the same weights.
#include "depletion/CaptureLimit.hpp"
#include "depletion/RealisedCapture.hpp"

#include "../grid/TestGrids.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace dropletFiber;

namespace
{

// Three parcels sitting on nodes A, B, C of a 2D grid, one step in the window: the mass
// per step at each node is one parcel's, s (cloud-in-cell: a parcel on a node gives it
// all its mass).
struct ThreeNodes
{
    GridSpec spec = test::grid2D();
    DensityGrid grid;
    std::vector<Parcel> parcels;
    std::size_t nodeA, nodeB, nodeC;
    double s = 0.0;

    ThreeNodes() : grid(spec, cloudInCell(), 1)
    {
        nodeA = spec.flatIndex(5, 5, 0);
        nodeB = spec.flatIndex(9, 5, 0);
        nodeC = spec.flatIndex(13, 5, 0);
        Parcel p;
        p.diameter = 2e-5;
        p.nParticle = 4.0;
        p.rhoDroplet = 1000.0;
        for (const int i : {5, 9, 13})
        {
            p.position = spec.nodePosition(i, 5, 0);
            grid.deposit(p, 1e-3);
            parcels.push_back(p);
        }
        grid.commitStep();
        s = parcelMass(p);
    }

    static KernelSettings cloudInCell()
    {
        KernelSettings settings;
        settings.cloudInCellBelow = 0.5;
        return settings;
    }
};

} // namespace

TEST(WeightedCapture, NPhysicalFibersAreNIndependentInterceptors)
{
    // A: one part of 0.1 s asked by 7 fibers; B: the same part added 7 times (7 computed
    // fibers of weight 1); C: one part of 0.1 s asked by 2.5 fibers (a weight from a mass
    // flow need not be whole).
    ThreeNodes weighted, separate;
    const double s = weighted.s;
    CaptureLimit one, many;
    one.addDemand(weighted.nodeA, 0.1 * s, 0.0, 7.0);
    one.addDemand(weighted.nodeC, 0.1 * s, 0.0, 2.5);
    for (int k = 0; k < 7; ++k)
    {
        many.addDemand(separate.nodeA, 0.1 * s);
    }
    CaptureLimitReport reportOne = one.limit(weighted.grid);
    CaptureLimitReport reportMany = many.limit(separate.grid);
    // P40: (1 - 0.1)^7 survive, whether one part of weight 7 or seven parts
    EXPECT_NEAR(one.opticalDepth(weighted.nodeA), -7.0 * std::log(0.9), 1e-14);
    EXPECT_NEAR(one.opticalDepth(weighted.nodeA), many.opticalDepth(separate.nodeA), 1e-14);
    EXPECT_NEAR(one.opticalDepth(weighted.nodeC), -2.5 * std::log(0.9), 1e-14);
    EXPECT_NEAR(reportOne.massDemanded, (0.7 + 0.25) * s, 1e-15 * s);
    EXPECT_NEAR(reportMany.massDemanded, 0.7 * s, 1e-15 * s);
    const std::vector<double> cOne = one.removeFromParcels(weighted.grid, weighted.parcels, 1e-3, reportOne);
    const std::vector<double> cMany
        = many.removeFromParcels(separate.grid, separate.parcels, 1e-3, reportMany);
    const double survivesA = std::pow(0.9, 7.0);
    EXPECT_NEAR(cOne[0], 1.0 - survivesA, 1e-14);
    EXPECT_NEAR(cOne[0], cMany[0], 1e-14);
    // Not one fiber 7 times as thick (1 - 0.7 survives) nor 7 times one fiber's loss
    EXPECT_GT(std::abs(cOne[0] - 0.7), 0.1);
    EXPECT_GT(std::abs(cOne[0] - 7.0 * (1.0 - std::exp(-0.1))), 0.1);
    EXPECT_NEAR(cOne[2], 1.0 - std::pow(0.9, 2.5), 1e-14);
    // Each physical fiber is granted its share: g_n = R_n / d_n, the same per fiber in both
    EXPECT_NEAR(one.grantedRatio(weighted.nodeA), (1.0 - survivesA) / 0.7, 1e-14);
    EXPECT_NEAR(one.grantedRatio(weighted.nodeA), many.grantedRatio(separate.nodeA), 1e-14);
    // Captured (N times each fiber's grant) = removed (the parcels' loss)
    const double capturedA = 7.0 * 0.1 * s * one.grantedRatio(weighted.nodeA);
    const double capturedC = 2.5 * 0.1 * s * one.grantedRatio(weighted.nodeC);
    EXPECT_NEAR(capturedA + capturedC, (cOne[0] + cOne[2]) * s, 1e-14 * s);
    EXPECT_NEAR(reportOne.massGranted, (cOne[0] + cOne[2]) * s, 1e-14 * s);
}

TEST(WeightedCapture, OneFiberSweepingTheWholeNodeSaturatesItWhateverItsWeight)
{
    ThreeNodes nodes;
    CaptureLimit limit;
    limit.addDemand(nodes.nodeB, 1.2 * nodes.s, 0.0, 1e5);
    CaptureLimitReport report = limit.limit(nodes.grid);
    EXPECT_TRUE(std::isinf(limit.opticalDepth(nodes.nodeB)));
    EXPECT_EQ(report.nodesLimited, 1);
    EXPECT_NEAR(report.excessDemanded, (1.2e5 - 1.0) * nodes.s, 1e-10 * nodes.s);
    const std::vector<double> c = limit.removeFromParcels(nodes.grid, nodes.parcels, 1e-3, report);
    EXPECT_EQ(c[1], 1.0);
    // The node gives what it holds, s, to 1e5 fibers asking 1.2 s each
    EXPECT_NEAR(limit.grantedRatio(nodes.nodeB), 1.0 / (1e5 * 1.2), 1e-20);
    EXPECT_NEAR(report.massGranted, nodes.s, 1e-15 * nodes.s);
}

TEST(WeightedCapture, BadInterceptorsAreRefused)
{
    CaptureLimit limit;
    EXPECT_THROW(limit.addDemand(3, 1.0, 0.0, 0.0), std::invalid_argument);
    EXPECT_THROW(limit.addDemand(3, 1.0, 0.0, -2.0), std::invalid_argument);
    EXPECT_THROW(limit.addDemand(3, 1.0, 0.0, std::nan("")), std::invalid_argument);
}

TEST(WeightedCapture, RealisedHitsOfAWeightedFiberAreRemovedNTimes)
{
    // Discrete hits (P41): each of the N fibers realises the computed fiber's hits, so the
    // node loses N times them: a sample of weight 4 realising half its grant is the same
    // removal as 4 samples of weight 1 each realising half.
    ThreeNodes weighted, separate;
    const double s = weighted.s;
    CaptureLimit one, many;
    SampleCapture sample;
    sample.count = 1;
    sample.node[0] = weighted.nodeA;
    sample.mass[0] = 0.05 * s;
    one.addDemand(sample, 4.0);
    for (int k = 0; k < 4; ++k)
    {
        many.addDemand(sample);
    }
    CaptureLimitReport r1 = one.limit(weighted.grid), r4 = many.limit(separate.grid);
    ParcelReaches reaches1, reaches4;
    one.removeFromParcels(weighted.grid, weighted.parcels, 1e-3, r1, &reaches1);
    many.removeFromParcels(separate.grid, separate.parcels, 1e-3, r4, &reaches4);
    const double granted = one.grantedMass(sample); // one physical fiber's
    ASSERT_GT(granted, 0.0);
    const RealisedRemoval w = realiseCapture(one, reaches1, {s, s, s}, {sample}, {0.5 * granted}, {4.0});
    const RealisedRemoval u = realiseCapture(many, reaches4, {s, s, s}, {sample, sample, sample, sample},
                                             {0.5 * granted, 0.5 * granted, 0.5 * granted, 0.5 * granted});
    EXPECT_NEAR(w.fraction[0], u.fraction[0], 1e-14);
    // The parcel loses 4 x half a fiber's grant: half of what it lost in expectation
    EXPECT_NEAR(w.fraction[0] * s, 4.0 * 0.5 * granted, 1e-14 * s);
    EXPECT_NEAR(w.sampleMass[0], 0.5 * granted, 1e-20);
}
