// Depletion's pieces (docs/model.md sec. 7): the deposit's weights re-evaluated
// (DensityGrid::depositedShare) against what deposit() put on the nodes, the attribution of
// a sample's mass to its corners (P12) against a hand calculation, the limit (P13) at
// nodes with too little mass, and the removal split over grid blocks adding up to the
// whole grid's.
#include "depletion/CaptureLimit.hpp"

#include "grid/GridPartition.hpp"

#include "../grid/TestGrids.hpp"

#include "DepositedBlocks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

using namespace dropletFiber;
using test::randomParcels;

namespace
{

std::array<int, 3> indices(const GridSpec& spec, std::size_t node)
{
    const auto nx = static_cast<std::size_t>(spec.nodes[0]);
    const auto ny = static_cast<std::size_t>(spec.nodes[1]);
    return {{static_cast<int>(node % nx), static_cast<int>((node / nx) % ny),
             static_cast<int>(node / (nx * ny))}};
}

// Per parcel: deposit() alone on a grid, the mass it put on each node read back after the
// commit; depositedShare with a random fraction per node must give sum m_n f_n / m_p, and
// depositBox must hold every node that got mass.
void checkSharesAgainstDeposit(const GridSpec& spec, const KernelSettings& settings, unsigned seed)
{
    const double dt = 1e-3;
    DensityGrid grid(spec, settings, 1);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> fraction(spec.nodeCount());
    for (double& f : fraction)
    {
        f = unit(rng);
    }
    const DensityGrid::NodeFraction fractionAt = [&](std::size_t node) { return fraction[node]; };
    const DensityGrid::NodeBoxTest askAll = [](const IndexBox&) { return true; };
    const DensityGrid::NodeBoxTest askNone = [](const IndexBox&) { return false; };
    int withMass = 0;
    for (const Parcel& parcel : randomParcels(spec, 300, seed))
    {
        grid.deposit(parcel, dt);
        grid.commitStep();
        const IndexBox box = grid.depositBox(parcel, dt);
        double expected = 0.0;
        for (std::size_t node = 0; node < spec.nodeCount(); ++node)
        {
            const double mass = grid.lastStepValue(node, quantityMass);
            expected += mass * fraction[node];
            const std::array<int, 3> n = indices(spec, node);
            ASSERT_TRUE(mass == 0.0 || box.holds(n[0], n[1], n[2]))
                << "node " << node << " outside depositBox";
        }
        const double parcelTotal = parcelMass(parcel);
        expected /= parcelTotal;
        withMass += expected > 0.0 ? 1 : 0;
        EXPECT_NEAR(grid.depositedShare(parcel, dt, askAll, fractionAt, spec.fullBox()), expected, 1e-13);
        // A test that turns down every box gives 0 (nothing weighed).
        EXPECT_EQ(grid.depositedShare(parcel, dt, askNone, fractionAt, spec.fullBox()), 0.0);
    }
    EXPECT_GT(withMass, 200);
    EXPECT_GT(grid.lastStepStatistics().parcels, 0);
}

} // namespace

TEST(DepositedShare, EqualsTheDepositsWeightsKernelFoldedAndFallback2D)
{
    checkSharesAgainstDeposit(test::grid2D(), KernelSettings{}, 3);
}

TEST(DepositedShare, EqualsTheDepositsWeightsCloudInCell3D)
{
    KernelSettings settings;
    settings.cloudInCellBelow = 0.5;
    checkSharesAgainstDeposit(test::grid3D(), settings, 4);
}

TEST(DepositedShare, LeavesTheStepAndItsStatisticsAlone)
{
    const GridSpec spec = test::grid2D();
    DensityGrid grid(spec, KernelSettings{}, 1);
    const std::vector<Parcel> parcels = randomParcels(spec, 20, 5);
    grid.deposit(parcels[1], 1e-3);
    const NodeValueArray before = grid.stepValues();
    const std::int64_t parcelsBefore = grid.stepStatistics().parcels;
    const DensityGrid::NodeFraction one = [](std::size_t) { return 1.0; };
    const DensityGrid::NodeBoxTest askAll = [](const IndexBox&) { return true; };
    for (const Parcel& parcel : parcels)
    {
        grid.depositedShare(parcel, 1e-3, askAll, one, spec.fullBox());
    }
    EXPECT_EQ(grid.stepValues(), before);
    EXPECT_EQ(grid.stepStatistics().parcels, parcelsBefore);
}

TEST(CaptureAttribution, SplitsTheSampleMassByCornerWeightTimesDensity)
{
    // 2D grid, 1 mm spacing. Masses put on four nodes by still parcels of two droplets
    // sitting exactly on them (cloud-in-cell: the whole parcel on the node). Node (0, 0)
    // is a corner of the box (a quarter cell), node (0, 1) on a face (half a cell): their
    // densities are mass * 4 / cell volume and mass * 2 / cell volume.
    const GridSpec spec = test::grid2D();
    KernelSettings settings;
    settings.cloudInCellBelow = 0.5;
    DensityGrid grid(spec, settings, 1);
    const double rhoP = 1000.0, d = 2e-5;
    const std::array<double, 4> nParticle{{2.0, 3.0, 5.0, 7.0}};
    const std::array<std::array<int, 2>, 4> at{{{{0, 0}}, {{1, 0}}, {{0, 1}}, {{1, 1}}}};
    for (int c = 0; c < 4; ++c)
    {
        Parcel p;
        p.position = spec.nodePosition(at[c][0], at[c][1], 0);
        p.diameter = d;
        p.nParticle = nParticle[c];
        p.rhoDroplet = rhoP;
        grid.deposit(p, 1e-3);
    }
    grid.commitStep();
    // rho per corner relative to a droplet's mass per cell volume: corner 2*4, face 3*2 and 5*2, inside 7.
    const std::array<double, 4> rho{{8.0, 6.0, 10.0, 7.0}};
    // A point at 0.25 and 0.6 of the cell: weights (1-a)(1-b), a(1-b), (1-a)b, ab.
    const double a = 0.25, b = 0.6;
    const std::array<double, 4> w{{(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b}};
    double norm = 0.0;
    for (int c = 0; c < 4; ++c)
    {
        norm += w[c] * rho[c];
    }
    const Eigen::Vector3d point = spec.nodePosition(0, 0, 0) + Eigen::Vector3d(a * 1e-3, b * 1e-3, 0.0);
    const CornerWeights corners = multilinearWeights(spec, point);
    std::array<double, 4 * nQuantities> totals{};
    for (int c = 0; c < 4; ++c)
    {
        grid.windowTotal(corners.node[c], totals.data() + c * nQuantities);
    }
    const double sampleMass = 3.7e-9;
    const SampleCapture capture
        = attributeSample(grid, corners, totals.data(), sampleMass, Eigen::Vector3d::Zero());
    ASSERT_EQ(capture.count, 4);
    double sum = 0.0;
    for (int c = 0; c < 4; ++c)
    {
        const std::size_t node = spec.flatIndex(at[c][0], at[c][1], 0);
        ASSERT_EQ(capture.node[c], node);
        EXPECT_NEAR(capture.mass[c], sampleMass * w[c] * rho[c] / norm, 1e-14 * sampleMass) << "corner " << c;
        sum += capture.mass[c];
    }
    EXPECT_NEAR(sum, sampleMass, 1e-15 * sampleMass);
}

TEST(CaptureLimit, ParcelsCrossTheNodesDepthsAndTheFibersGetWhatTheyLost)
{
    const GridSpec spec = test::grid2D();
    KernelSettings settings;
    settings.cloudInCellBelow = 0.5;
    DensityGrid grid(spec, settings, 3);
    Parcel p;
    p.diameter = 2e-5;
    p.nParticle = 4.0;
    p.rhoDroplet = 1000.0;
    const std::size_t nodeA = spec.flatIndex(5, 5, 0), nodeB = spec.flatIndex(9, 5, 0);
    const std::size_t nodeC = spec.flatIndex(12, 5, 0); // demand, no parcel this step
    // An older step in the window at node C: the window has mass there, the step none.
    p.position = spec.nodePosition(12, 5, 0);
    grid.deposit(p, 1e-3);
    grid.commitStep();
    std::vector<Parcel> parcels;
    for (const int i : {5, 9})
    {
        p.position = spec.nodePosition(i, 5, 0);
        grid.deposit(p, 1e-3);
        parcels.push_back(p);
    }
    p.position = spec.nodePosition(22, 12, 0); // far from the fibers
    grid.deposit(p, 1e-3);
    parcels.push_back(p);
    grid.commitStep();
    const double s = parcelMass(p);
    CaptureLimit limit;
    SampleCapture sample;
    sample.count = 3;
    sample.node = {{nodeA, nodeB, nodeC}};
    sample.mass = {{3.0 * s, 0.25 * s, 0.2 * s}};
    limit.addDemand(sample);
    CaptureLimitReport report = limit.limit(grid);
    // Two steps in the window: eq. 9 read s_n = s / 2 per step at A, B and C. One
    // interceptor per node: A asks 6 s_n (saturated), B x = -ln(1 - 1/2) = ln 2, C
    // x = -ln(1 - 0.4).
    EXPECT_TRUE(std::isinf(limit.opticalDepth(nodeA)));
    EXPECT_NEAR(limit.opticalDepth(nodeB), std::log(2.0), 1e-15);
    EXPECT_NEAR(limit.opticalDepth(nodeC), -std::log(0.6), 1e-15);
    EXPECT_EQ(limit.opticalDepth(spec.flatIndex(1, 1, 0)), 0.0);
    EXPECT_EQ(report.nodesDemanded, 3);
    EXPECT_EQ(report.nodesLimited, 1); // A: 3 s > s / 2
    EXPECT_NEAR(report.massDemanded, 3.45 * s, 1e-14 * s);
    // The parcel on A loses all its droplets, the one on B 1 - exp(-ln 2) = 1/2, the far
    // one none; nothing reaches C. Granted what left them: A s (g = 1/3), B s / 2 (g = 2:
    // this step holds twice the window's mean), C nothing.
    const std::vector<double> fraction = limit.removeFromParcels(grid, parcels, 1e-3, report);
    EXPECT_EQ(fraction[0], 1.0);
    EXPECT_NEAR(fraction[1], 0.5, 1e-15);
    EXPECT_EQ(fraction[2], 0.0);
    EXPECT_NEAR(report.massGranted, 1.5 * s, 1e-14 * s);
    EXPECT_NEAR(limit.grantedRatio(nodeA), 1.0 / 3.0, 1e-15);
    EXPECT_NEAR(limit.grantedRatio(nodeB), 2.0, 1e-15);
    EXPECT_EQ(limit.grantedRatio(nodeC), 0.0);
    EXPECT_NEAR(limit.grantedMass(sample), 1.5 * s, 1e-14 * s);
    // Only boxes near A, B and C may take (bricks of 4 nodes).
    IndexBox nearA, far;
    nearA.lo = {{4, 4, 0}};
    nearA.hi = {{5, 5, 0}};
    far.lo = {{20, 10, 0}};
    far.hi = {{25, 15, 0}};
    EXPECT_TRUE(limit.mayTake(nearA));
    EXPECT_FALSE(limit.mayTake(far));
    EXPECT_THROW(limit.grantedRatio(spec.flatIndex(1, 1, 0)), std::out_of_range);
    EXPECT_THROW(limit.addDemand(nodeA, -1.0), std::invalid_argument);
}

TEST(CaptureLimit, AParcelKeepsTheExponentialOfItsMeanDepth)
{
    // A parcel half on node D (x = 0.2) and half on E (x = 1.4): it crosses the depth
    // X = 0.8 and keeps exp(-0.8) (a rule per node would keep (e^-0.2 + e^-1.4) / 2, 3.1 %
    // more: the mat faces' error). Its loss goes to D and E as 0.1 : 0.7.
    const GridSpec spec = test::grid2D();
    KernelSettings settings;
    settings.cloudInCellBelow = 0.5;
    DensityGrid grid(spec, settings, 1);
    Parcel p;
    p.diameter = 2e-5;
    p.nParticle = 4.0;
    p.rhoDroplet = 1000.0;
    p.position = 0.5 * (spec.nodePosition(5, 5, 0) + spec.nodePosition(6, 5, 0));
    grid.deposit(p, 1e-3);
    grid.commitStep();
    const double m = parcelMass(p);
    const std::size_t nodeD = spec.flatIndex(5, 5, 0), nodeE = spec.flatIndex(6, 5, 0);
    CaptureLimit limit;
    const double dD = 0.5 * m * -std::expm1(-0.2), dE = 0.5 * m * -std::expm1(-1.4);
    limit.addDemand(nodeD, dD);
    limit.addDemand(nodeE, dE);
    CaptureLimitReport report = limit.limit(grid);
    const std::vector<double> fraction = limit.removeFromParcels(grid, {p}, 1e-3, report);
    const double c = -std::expm1(-0.8);
    EXPECT_NEAR(fraction[0], c, 1e-14);
    EXPECT_NEAR(limit.grantedRatio(nodeD) * dD, m * c * 0.1 / 0.8, 1e-14 * m);
    EXPECT_NEAR(limit.grantedRatio(nodeE) * dE, m * c * 0.7 / 0.8, 1e-14 * m);
    EXPECT_NEAR(report.massGranted, m * c, 1e-14 * m);
    // The discrete hits' factor: the fibers at E realised half of what they were granted,
    // so the parcel loses D's share and half of E's.
    ParcelReaches reaches;
    limit.reach(grid, p, 1e-3, reaches);
    EXPECT_NEAR(limit.removedFraction(reaches, 0, 0.0, 0.8), c, 1e-14);
    limit.scaleRemoval(nodeE, 0.5);
    EXPECT_NEAR(limit.removedFraction(reaches, 0, 0.0, 0.8), c * (0.1 + 0.5 * 0.7) / 0.8, 1e-14);
    EXPECT_THROW(limit.scaleRemoval(spec.flatIndex(1, 1, 0), 1.0), std::invalid_argument);
}

TEST(CaptureLimit, IndependentInterceptorsMultiplyTheirSurvivals)
{
    // P13: each part d_sn intercepts d_sn / s_n of the node's droplets, independently:
    // x_n = -ln prod (1 - d_sn / s_n). One step in the window: s_n = h_n = s.
    const GridSpec spec = test::grid2D();
    KernelSettings settings;
    settings.cloudInCellBelow = 0.5;
    DensityGrid grid(spec, settings, 1);
    Parcel p;
    p.diameter = 2e-5;
    p.nParticle = 4.0;
    p.rhoDroplet = 1000.0;
    const std::size_t nodeA = spec.flatIndex(5, 5, 0), nodeB = spec.flatIndex(9, 5, 0);
    const std::size_t nodeC = spec.flatIndex(13, 5, 0);
    std::vector<Parcel> parcels;
    for (const int i : {5, 9, 13})
    {
        p.position = spec.nodePosition(i, 5, 0);
        grid.deposit(p, 1e-3);
        parcels.push_back(p);
    }
    grid.commitStep();
    const double s = parcelMass(p);
    CaptureLimit limit;
    // A: two halves, (1 - 1/2)^2 = 1/4 survive (linear: all taken). B: 1000 parts of
    // 1/1000, (1 - 1e-3)^1000 = exp(-1) to 5e-4 (the Poisson limit of thin fibers).
    // C: a part of 0.3 s and one of 1.5 s (a sample sweeping more than the node holds).
    limit.addDemand(nodeA, 0.5 * s);
    limit.addDemand(nodeA, 0.5 * s);
    for (int k = 0; k < 1000; ++k)
    {
        limit.addDemand(nodeB, 1e-3 * s);
    }
    limit.addDemand(nodeC, 0.3 * s);
    limit.addDemand(nodeC, 1.5 * s);
    CaptureLimitReport report = limit.limit(grid);
    EXPECT_NEAR(limit.opticalDepth(nodeA), 2.0 * std::log(2.0), 1e-15);
    EXPECT_NEAR(limit.opticalDepth(nodeB), -1000.0 * std::log1p(-1e-3), 1e-12);
    EXPECT_TRUE(std::isinf(limit.opticalDepth(nodeC)));
    const std::vector<double> fraction = limit.removeFromParcels(grid, parcels, 1e-3, report);
    EXPECT_NEAR(fraction[0], 0.75, 1e-15);
    EXPECT_NEAR(fraction[1], 1.0 - std::pow(1.0 - 1e-3, 1000), 1e-13);
    EXPECT_NEAR(fraction[1], 1.0 - std::exp(-1.0), 5e-4);
    EXPECT_EQ(fraction[2], 1.0);
    EXPECT_NEAR(report.massDemanded, (1.0 + 1.0 + 1.8) * s, 1e-14 * s);
    EXPECT_NEAR(report.massGranted, (0.75 + 1.0 - std::pow(1.0 - 1e-3, 1000) + 1.0) * s, 1e-13 * s);
    EXPECT_NEAR(limit.grantedRatio(nodeA), 0.75, 1e-15);
    EXPECT_NEAR(limit.grantedRatio(nodeC), 1.0 / 1.8, 1e-15);
    EXPECT_EQ(report.nodesLimited, 1);                      // C: 1.8 s > s
    EXPECT_NEAR(report.excessDemanded, 0.8 * s, 1e-15 * s); // what C asked beyond s
    // A block that sends the parts to the owner (takeForeignDemand) keeps them apart.
    CaptureLimit sender, owner;
    sender.addDemand(nodeA, 0.5 * s);
    sender.addDemand(nodeA, 0.5 * s);
    const IndexBox elsewhere{{{0, 0, 0}}, {{2, 2, 0}}};
    DensityGrid other(spec, settings, 1, GridBlock{elsewhere, elsewhere});
    const std::vector<NodeMass> sent = sender.takeForeignDemand(other);
    ASSERT_EQ(sent.size(), 2u);
    for (const NodeMass& part : sent)
    {
        owner.addDemand(part.node, part.mass, part.shadow);
    }
    owner.limit(grid);
    EXPECT_EQ(owner.opticalDepth(nodeA), limit.opticalDepth(nodeA));
}

TEST(CaptureLimit, BlocksGivePartsThatAddUpToTheWholeGrids)
{
    const GridSpec spec = test::grid2D();
    const double dt = 1e-3;
    const std::vector<Parcel> parcels = randomParcels(spec, 200, 8);
    DensityGrid whole(spec, KernelSettings{}, 1);
    const GridPartition partition = GridPartition::bisection(spec, 4);
    std::vector<std::unique_ptr<DensityGrid>> blocks
        = test::depositedBlocks(spec, partition, parcels, dt, whole);
    // Demand at random nodes, some above the supply.
    std::mt19937_64 rng(2);
    std::uniform_int_distribution<std::size_t> anyNode(0, spec.nodeCount() - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    CaptureLimit wholeLimit;
    std::vector<CaptureLimit> blockLimits(blocks.size());
    for (int n = 0; n < 150; ++n)
    {
        const std::size_t node = anyNode(rng);
        const double demand = 2.0 * unit(rng) * (whole.lastStepValue(node, quantityMass) + 1e-12);
        wholeLimit.addDemand(node, demand);
        blockLimits[0].addDemand(node, demand); // as if a fiber on block 0 asked
    }
    const std::vector<NodeMass> foreign = blockLimits[0].takeForeignDemand(*blocks[0]);
    for (const NodeMass& entry : foreign)
    {
        for (std::size_t b = 1; b < blocks.size(); ++b)
        {
            if (blocks[b]->owns(entry.node))
            {
                blockLimits[b].addDemand(entry.node, entry.mass, entry.shadow);
            }
        }
    }
    CaptureLimitReport wholeReport = wholeLimit.limit(whole);
    const std::vector<double> wholeFraction = wholeLimit.removeFromParcels(whole, parcels, dt, wholeReport);
    // The blocks: the parts of A_p and X_p added up, c_p from the sums, each block's removal
    CaptureLimitReport blockReport;
    std::vector<ParcelReaches> reaches(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        blockReport += blockLimits[b].limit(*blocks[b]);
        for (const Parcel& parcel : parcels)
        {
            blockLimits[b].reach(*blocks[b], parcel, dt, reaches[b]);
        }
    }
    EXPECT_EQ(blockReport.nodesLimited, wholeReport.nodesLimited);
    EXPECT_GT(wholeReport.nodesLimited, 10);
    double removed = 0.0;
    for (std::size_t p = 0; p < parcels.size(); ++p)
    {
        double saturated = 0.0, depth = 0.0;
        for (std::size_t b = 0; b < blocks.size(); ++b)
        {
            saturated += reaches[b].parcels[p].saturated;
            depth += reaches[b].parcels[p].depth;
        }
        const double fraction = CaptureLimit::capturedFraction(saturated, depth);
        EXPECT_NEAR(fraction, wholeFraction[p], 1e-14);
        for (std::size_t b = 0; b < blocks.size(); ++b)
        {
            blockLimits[b].remove(reaches[b], p, parcelMass(parcels[p]), saturated, depth);
        }
        removed += fraction * parcelMass(parcels[p]);
    }
    CaptureLimitReport granted;
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        CaptureLimitReport part;
        blockLimits[b].grant(part);
        granted += part;
    }
    EXPECT_GT(removed, 0.0);
    EXPECT_NEAR(granted.massGranted, wholeReport.massGranted, 1e-13 * wholeReport.massGranted);
    // Removed from the parcels = granted to the fibers (P14).
    EXPECT_NEAR(removed, wholeReport.massGranted, 1e-12 * wholeReport.massGranted);
    for (const NodeMass& entry : foreign)
    {
        for (std::size_t b = 1; b < blocks.size(); ++b)
        {
            if (blocks[b]->owns(entry.node))
            {
                EXPECT_NEAR(blockLimits[b].grantedRatio(entry.node), wholeLimit.grantedRatio(entry.node),
                            1e-12);
            }
        }
    }
}

TEST(CaptureAttribution, OwnedCornersOfTheBlocksAddUpToTheWholeSample)
{
    // The parallel route of P12: each block attributes m_s / Sigma times its corners' parts
    // (Sigma from the blocks' addOwnedCornerSums); per node that must be attributeSample's
    // share on the whole grid, and the whole grid's own corners all of it.
    const GridSpec spec = test::grid2D();
    const double dt = 1e-3;
    const std::vector<Parcel> parcels = randomParcels(spec, 200, 11);
    DensityGrid whole(spec, KernelSettings{}, 1);
    const GridPartition partition = GridPartition::bisection(spec, 4);
    std::vector<std::unique_ptr<DensityGrid>> blocks
        = test::depositedBlocks(spec, partition, parcels, dt, whole);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int compared = 0;
    for (int s = 0; s < 200; ++s)
    {
        const Eigen::Vector3d point(spec.lower.x() + unit(rng) * (spec.upper.x() - spec.lower.x()),
                                    spec.lower.y() + unit(rng) * (spec.upper.y() - spec.lower.y()),
                                    0.5 * (spec.lower.z() + spec.upper.z()));
        const CornerWeights corners = multilinearWeights(spec, point);
        std::array<double, 8 * nQuantities> totals{};
        for (int c = 0; c < corners.count; ++c)
        {
            whole.windowTotal(corners.node[c], totals.data() + c * nQuantities);
        }
        const double sampleMass = 1e-9 * (0.5 + unit(rng));
        const SampleCapture expected
            = attributeSample(whole, corners, totals.data(), sampleMass, Eigen::Vector3d::Zero());
        if (expected.count == 0)
        {
            continue;
        }
        std::array<double, nQuantities> sums{};
        for (const auto& block : blocks)
        {
            block->addOwnedCornerSums(corners, sums);
        }
        const double share = sampleMass / sums[quantityMass];
        std::unordered_map<std::size_t, double> fromBlocks;
        for (const auto& block : blocks)
        {
            const SampleCapture part = attributeOwnedCorners(*block, corners, share, Eigen::Vector3d::Zero());
            for (int c = 0; c < part.count; ++c)
            {
                EXPECT_TRUE(block->owns(part.node[c]));
                fromBlocks[part.node[c]] += part.mass[c];
            }
        }
        const SampleCapture wholeOwned
            = attributeOwnedCorners(whole, corners, share, Eigen::Vector3d::Zero());
        ASSERT_EQ(wholeOwned.count, expected.count);
        ASSERT_EQ(fromBlocks.size(), static_cast<std::size_t>(expected.count));
        double sum = 0.0;
        for (int c = 0; c < expected.count; ++c)
        {
            EXPECT_EQ(wholeOwned.node[c], expected.node[c]);
            EXPECT_NEAR(wholeOwned.mass[c], expected.mass[c], 1e-14 * sampleMass);
            EXPECT_NEAR(fromBlocks[expected.node[c]], expected.mass[c], 1e-14 * sampleMass);
            sum += wholeOwned.mass[c];
        }
        EXPECT_NEAR(sum, sampleMass, 1e-14 * sampleMass);
        ++compared;
    }
    EXPECT_GT(compared, 50);
}
