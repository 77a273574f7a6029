// DensityGrid with KernelSettings::vectorised on and off: the same random parcels (2D and
// 3D grids, reach 1, 3 and 10 node spacings, moving from 1e-9 to several reaches per step,
// stationary, partly outside the grid, with and without the negligible-weight cut) give
//  - with vectorised = false: bit for bit the per-node deposit written out here from
//    PathWeight::omegaFromOffset and eq. 24 (that is what the portable path is);
//  - with vectorised = true (batched AVX2 + FMA node loop where the CPU has it): the same
//    node values to the batched kernel's accuracy, the same touched boxes, the same step
//    statistics.
#include "grid/DensityGrid.hpp"
#include "grid/PathWeight.hpp"
#include "grid/PathWeightBatch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace dropletFiber;

namespace
{

constexpr double spacing = 5e-4;       // node spacing h, m
constexpr double dropletRadius = 1e-5; // r_p, m
constexpr double dt = 1e-4;            // s

GridSpec gridSpec(int dimension)
{
    GridSpec s;
    s.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
    if (dimension == 2)
    {
        s.upper = Eigen::Vector3d(40 * spacing, 60 * spacing, 2 * spacing);
        s.nodes = {{41, 61, 1}};
    }
    else
    {
        s.upper = Eigen::Vector3d(20 * spacing, 24 * spacing, 20 * spacing);
        s.nodes = {{21, 25, 21}};
    }
    return s;
}

// A parcel whose kernel reaches about `reach` node spacings (r_max = r_p n, eq. 13), at a
// random place of the grid box (inside: its whole path, the kernel may reach beyond the
// grid; otherwise anywhere, also a little outside), moving `pathLength` metres in a random
// direction during dt.
Parcel randomParcel(std::mt19937_64& random, const GridSpec& spec, int dimension, double reach,
                    double pathLength, bool inside)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Parcel p;
    p.diameter = 2.0 * dropletRadius;
    p.nParticle = reach * spacing / dropletRadius * (0.7 + 0.6 * unit(random));
    p.rhoDroplet = 1000.0;
    Eigen::Vector3d direction(unit(random) - 0.5, unit(random) - 0.5,
                              dimension == 3 ? unit(random) - 0.5 : 0.0);
    direction.normalize();
    p.velocity = pathLength / dt * direction;
    const double margin = inside ? 1.05 * pathLength + 0.5 * spacing : -2.0 * spacing;
    for (int d = 0; d < 3; ++d)
    {
        if (d == 2 && dimension == 2)
        {
            p.position[d] = spec.nodeCoordinate(d, 0); // on the node layer: no projection needed
            continue;
        }
        const double span = spec.upper[d] - spec.lower[d] - 2.0 * margin;
        p.position[d] = spec.lower[d] + margin + span * unit(random);
    }
    return p;
}

// Path lengths per step, in reaches: stationary, regime B (1e-9), short to long; at most
// 0.4 of the grid's smallest extent (so that a parcel's whole path fits inside).
double randomPathLength(std::mt19937_64& random, const GridSpec& spec, int dimension, double reach, int p)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int kind = p % 8;
    const double reachMetres = reach * spacing;
    double extent = spec.upper.x() - spec.lower.x();
    for (int d = 1; d < dimension; ++d)
    {
        extent = std::min(extent, spec.upper[d] - spec.lower[d]);
    }
    const double length = reachMetres * 3.0 * std::pow(1e-3, unit(random));
    return kind == 0 ? 0.0 : kind == 1 ? 1e-9 * reachMetres : std::min(length, 0.4 * extent);
}

void expectSameStatistics(const StepStatistics& a, const StepStatistics& b)
{
    EXPECT_EQ(a.parcels, b.parcels);
    EXPECT_EQ(a.parcelsEmpty, b.parcelsEmpty);
    EXPECT_EQ(a.parcelsOutside, b.parcelsOutside);
    EXPECT_EQ(a.parcelsPartlyOutside, b.parcelsPartlyOutside);
    EXPECT_EQ(a.parcelsCapped, b.parcelsCapped);
    EXPECT_EQ(a.parcelsFallback, b.parcelsFallback);
    EXPECT_EQ(a.parcelsCloudInCell, b.parcelsCloudInCell);
    EXPECT_EQ(a.nodesVisited, b.nodesVisited);
    EXPECT_EQ(a.nodesWeighted, b.nodesWeighted);
    EXPECT_EQ(a.massIn, b.massIn);
    EXPECT_EQ(a.massDeposited, b.massDeposited);
    EXPECT_EQ(a.massOutside, b.massOutside);
}

} // namespace

TEST(DensityGridVectorised, SettingChoosesTheKernel)
{
    KernelSettings settings;
    EXPECT_TRUE(settings.vectorised); // default: batched where the CPU has it
    EXPECT_EQ(DensityGrid(gridSpec(2), settings).batchedKernel(), PathWeightBatch::cpuSupported());
    settings.vectorised = false;
    EXPECT_FALSE(DensityGrid(gridSpec(2), settings).batchedKernel());
    EXPECT_FALSE(DensityGrid(gridSpec(3), settings).batchedKernel());
}

TEST(DensityGridVectorised, PortablePathIsThePerNodeDeposit)
{
    // Reference: eq. 24 written out for each parcel, every node of the lattice in storage order
    // (i fastest), omega from PathWeight::omegaFromOffset, ghost nodes beyond the faces folded
    // onto their mirror images; exact tails (negligibleWeight 0),
    // so that every node within reach counts. Parcels inside the grid (no clipping), several
    // per step, so that the step's sums are compared too.
    std::mt19937_64 random(20260611);
    long parcels = 0, weightedNodes = 0;
    for (int dimension : {2, 3})
    {
        const GridSpec spec = gridSpec(dimension);
        KernelSettings settings;
        settings.negligibleWeight = 0.0;
        settings.vectorised = false;
        settings.method = DepositMethod::Exact; // the per-node code (SeparableWeightTest: the other)
        DensityGrid grid(spec, settings);
        ASSERT_FALSE(grid.batchedKernel());
        for (double reach : {1.0, 3.0, 10.0})
        {
            if (dimension == 3 && reach == 10.0)
            {
                continue; // the whole 3D grid per parcel: slow, and reaches 1, 3 cover it
            }
            std::vector<double> reference(spec.nodeCount() * nQuantities, 0.0);
            std::vector<double> omega(spec.nodeCount());
            for (int p = 0; p < 60; ++p, ++parcels)
            {
                const Parcel parcel = randomParcel(random, spec, dimension, reach,
                                                   randomPathLength(random, spec, dimension, reach, p), true);
                grid.deposit(parcel, dt);

                const double radius = 0.5 * parcel.diameter;
                const ParcelKernel kernel(radius, parcel.nParticle, settings, dimension);
                const Eigen::Vector3d displacement = parcel.velocity * dt;
                const Eigen::Vector3d start = parcel.position - displacement;
                const PathWeight path(kernel, start, displacement);
                // Every node of the unbounded lattice lower + i h within one grid length of
                // the box (ghost nodes beyond the faces), in storage order; a ghost node's
                // omega goes to its mirror image (folded kernel, docs/model.md sec. 4).
                std::fill(omega.begin(), omega.end(), 0.0);
                double sum = 0.0;
                std::array<int, 3> ghosts{};
                for (int d = 0; d < 3; ++d)
                {
                    ghosts[d] = spec.flat(d) ? 0 : spec.nodes[d] - 1;
                }
                auto latticeCoordinate = [&](int d, int i) {
                    return i >= 0 && i < spec.nodes[d] ? spec.nodeCoordinate(d, i)
                                                       : spec.lower[d] + i * spec.spacing(d);
                };
                for (int k = -ghosts[2]; k < spec.nodes[2] + ghosts[2]; ++k)
                    for (int j = -ghosts[1]; j < spec.nodes[1] + ghosts[1]; ++j)
                        for (int i = -ghosts[0]; i < spec.nodes[0] + ghosts[0]; ++i)
                        {
                            const Eigen::Vector3d offset(latticeCoordinate(0, i) - start.x(),
                                                         latticeCoordinate(1, j) - start.y(),
                                                         latticeCoordinate(2, k) - start.z());
                            const double w = path.omegaFromOffset(offset);
                            if (w > 0.0)
                            {
                                sum += w;
                                omega[spec.flatIndex(spec.mirrorIndex(0, i), spec.mirrorIndex(1, j),
                                                     spec.mirrorIndex(2, k))]
                                    += w;
                            }
                        }
                for (std::size_t n = 0; n < spec.nodeCount(); ++n)
                {
                    weightedNodes += omega[n] > 0.0 ? 1 : 0;
                }
                ASSERT_GT(sum, 0.0);
                const double mass = parcelMass(parcel);
                const double totals[nQuantities] = {mass,
                                                    parcel.nParticle,
                                                    parcel.nParticle * radius,
                                                    mass * radius,
                                                    mass * parcel.velocity.x(),
                                                    mass * parcel.velocity.y(),
                                                    mass * parcel.velocity.z()};
                const double inverseSum = 1.0 / sum;
                for (std::size_t n = 0; n < spec.nodeCount(); ++n)
                {
                    if (omega[n] > 0.0)
                    {
                        for (int q = 0; q < nQuantities; ++q)
                        {
                            reference[n * nQuantities + static_cast<std::size_t>(q)]
                                += omega[n] * inverseSum * totals[q];
                        }
                    }
                }
            }
            ASSERT_EQ(grid.stepStatistics().parcelsPartlyOutside, 0);
            const NodeValueArray& values = grid.stepValues();
            for (std::size_t v = 0; v < values.size(); ++v)
            {
                ASSERT_EQ(values[v], reference[v])
                    << "dimension " << dimension << " reach " << reach << " value " << v;
            }
            grid.commitStep();
        }
    }
    EXPECT_GT(weightedNodes, 10000);
    std::printf("%ld parcels, %ld weighted nodes: bit for bit\n", parcels, weightedNodes);
}

TEST(DensityGridVectorised, BatchedAgreesWithPortable)
{
    if (!PathWeightBatch::cpuSupported())
    {
        GTEST_SKIP() << "this CPU has no AVX2 + FMA (or this build no batched kernel): both settings run the "
                        "per-node code";
    }
    // One parcel per step, so that each parcel's node values are compared with a bound of
    // their own. The batched node weights omega' agree with the per-node ones to
    // |omega' - omega| <= epsilon omega_max (PathWeightBatchTest: 2.9e-15 where the parcel's
    // largest weight is not tiny; conditioning of exp(-E) at large exponents E adds
    // ~E 1.1e-16, see PathWeightBatch.hpp). Normalised (eq. 24), w = omega / sum omega with
    // N weighted nodes:
    //   |w'_n - w_n| <= epsilon omega_max / sum + w_n N epsilon omega_max / sum
    //               <= epsilon w_max (1 + N w_n) <= epsilon w_max (1 + N w_max),
    // and every quantity of a node is w times the parcel's total: relative to the parcel's
    // largest node value the bound is epsilon (1 + N w_max). epsilon = 1e-14 (the measured
    // 2.9e-15 with room for exponents E up to ~60).
    constexpr double epsilon = 1e-14;
    std::mt19937_64 random(20260612);
    long parcels = 0, movingParcels = 0;
    long differentParcels = 0; // not bit-identical: the batched loop ran
    double worstRatio = 0.0;   // |difference| / bound
    for (int dimension : {2, 3})
    {
        const GridSpec spec = gridSpec(dimension);
        for (double negligibleWeight : {1e-17, 0.0})
        {
            KernelSettings vectorisedSettings;
            vectorisedSettings.negligibleWeight = negligibleWeight;
            vectorisedSettings.method = DepositMethod::Exact;
            KernelSettings portableSettings = vectorisedSettings;
            portableSettings.vectorised = false;
            DensityGrid batched(spec, vectorisedSettings, 2);
            DensityGrid portable(spec, portableSettings, 2);
            ASSERT_TRUE(batched.batchedKernel());
            ASSERT_FALSE(portable.batchedKernel());
            for (double reach : {1.0, 3.0, 10.0})
            {
                const int count = dimension == 3 && reach == 10.0 ? 16 : 120;
                for (int p = 0; p < count; ++p, ++parcels)
                {
                    const double length = randomPathLength(random, spec, dimension, reach, p);
                    const Parcel parcel = randomParcel(random, spec, dimension, reach, length, p % 5 != 4);
                    batched.deposit(parcel, dt);
                    portable.deposit(parcel, dt);
                    movingParcels += length > 1e-12 * reach * spacing ? 1 : 0;

                    const StepStatistics& stats = portable.stepStatistics();
                    expectSameStatistics(batched.stepStatistics(), stats);
                    ASSERT_TRUE(batched.stepBox() == portable.stepBox());
                    const IndexBox box = portable.stepBox();
                    double largest[nQuantities] = {};
                    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
                        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
                            for (int i = box.lo[0]; i <= box.hi[0]; ++i)
                                for (int q = 0; q < nQuantities; ++q)
                                {
                                    const double value
                                        = portable.stepValues()[spec.flatIndex(i, j, k) * nQuantities
                                                                + static_cast<std::size_t>(q)];
                                    largest[q] = std::max(largest[q], std::abs(value));
                                }
                    const double largestWeight
                        = stats.massDeposited > 0.0 ? largest[quantityMass] / stats.massDeposited : 0.0;
                    const double relativeBound
                        = epsilon * (1.0 + static_cast<double>(stats.nodesWeighted) * largestWeight);
                    differentParcels += batched.stepValues() != portable.stepValues() ? 1 : 0;
                    for (std::size_t v = 0; v < portable.stepValues().size(); ++v)
                    {
                        const int q = static_cast<int>(v % nQuantities);
                        const double difference
                            = std::abs(batched.stepValues()[v] - portable.stepValues()[v]);
                        const double bound = relativeBound * largest[q];
                        if (bound > 0.0)
                        {
                            worstRatio = std::max(worstRatio, difference / bound);
                        }
                        ASSERT_LE(difference, bound)
                            << "dimension " << dimension << " reach " << reach << " parcel " << p << " value "
                            << v << ": batched " << batched.stepValues()[v] << " portable "
                            << portable.stepValues()[v];
                    }
                    batched.commitStep();
                    portable.commitStep();
                    expectSameStatistics(batched.lastStepStatistics(), portable.lastStepStatistics());
                }
            }
        }
    }
    EXPECT_GT(movingParcels, 1000);
    EXPECT_GT(differentParcels, 500); // round-off differences show that the batched loop ran
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", worstRatio);
    RecordProperty("worstDifferenceOverBound", text);
    std::printf("%ld parcels (%ld moving, %ld not bit-identical): worst |batched - portable| / bound = %s\n",
                parcels, movingParcels, differentParcels, text);
}
