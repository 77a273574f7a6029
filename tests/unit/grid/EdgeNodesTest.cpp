// A uniform spray filling the grid box reads its true density at every node, faces, edges
// and corners included (docs/model.md sec. 4, edge nodes: dual-cell volumes and folded
// kernels), for cloud-in-cell and kernel deposits, stationary and moving parcels, 2D and
// 3D (the spray: FillingSpray.hpp; eq. 9 near a wall: CollisionNearWallTest).
#include "FillingSpray.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace dropletFiber;
using namespace dropletFiber::test;

namespace
{

// Every node within `tolerance` of the true density, the means the parcels' own, the mass
// on the grid the mass deposited.
void expectUniform(const DensityGrid& grid, const Spray& spray, double tolerance, const std::string& what)
{
    const GridSpec& spec = grid.spec();
    const double rho = spray.trueDensity();
    const Eigen::Vector3d v = spray.velocity();
    double worst = 0.0;
    for (int k = 0; k < spec.nodes[2]; ++k)
        for (int j = 0; j < spec.nodes[1]; ++j)
            for (int i = 0; i < spec.nodes[0]; ++i)
            {
                const DropletFieldValue f = grid.nodeValue(i, j, k);
                worst = std::max(worst, std::abs(f.rho / rho - 1.0));
                ASSERT_NEAR(f.rho, rho, tolerance * rho) << what << " node " << i << " " << j << " " << k;
                ASSERT_NEAR(f.rMeanMass, dropletRadius, 1e-12 * dropletRadius) << what;
                ASSERT_NEAR(f.rMeanNumber, dropletRadius, 1e-12 * dropletRadius) << what;
                ASSERT_LE((f.velocity - v).norm(), 1e-12 * (v.norm() + 1.0)) << what;
            }
    const StepStatistics& stats = grid.lastStepStatistics();
    // Summed over ~1e5 parcels: round-off of the sums (per parcel: MassOnTheGridIsTheMassInside).
    EXPECT_NEAR(grid.windowMassPerStep(), stats.massDeposited, 1e-10 * stats.massDeposited) << what;
    // The paths' time inside the box is that of a lattice filling the box exactly.
    const double boxVolume = (spec.upper - spec.lower).prod();
    EXPECT_NEAR(stats.massDeposited / boxVolume, rho, 1e-9 * rho) << what;
    std::printf("%-40s worst node deviation %.2e\n", what.c_str(), worst);
}

} // namespace

// Moving parcels: paths of about 0.9 spacings per step, diagonal (the cloud-in-cell path
// points and the clipped paths' normalisation are what differs from stationary parcels);
// a finer lattice than for stationary parcels, whose nodes are exact by symmetry (the
// lattice is mirror-symmetric at the faces), so that the lattice's own quadrature error
// stays below 1e-3.
TEST(EdgeNodes, UniformSprayFillingA2DBoxReadsTrueDensityAtEveryNode)
{
    for (const Deposit& deposit : deposits)
    {
        for (const bool moving : {false, true})
        {
            Spray spray;
            spray.nParticle = deposit.nParticle;
            spray.perCell = moving ? 8 : 4;
            spray.steps = moving ? Eigen::Vector3d(6, -4, 0) : Eigen::Vector3d::Zero(); // (0.75, -0.5) h
            const DensityGrid grid
                = depositSpray(spray, kernelWithReach(deposit.reach, deposit.cloudInCellBelow));
            expectUniform(grid, spray, 0.01,
                          std::string("2D ") + deposit.name + (moving ? " moving" : " stationary"));
        }
    }
}

TEST(EdgeNodes, UniformSprayFillingA3DBoxReadsTrueDensityAtEveryNode)
{
    for (const Deposit& deposit : deposits)
    {
        for (const bool moving : {false, true})
        {
            Spray spray;
            spray.dimensions = 3;
            spray.cells = 4;
            // Cloud-in-cell weights are piecewise linear: a finer lattice for their quadrature.
            const int perCell = deposit.cloudInCellBelow > 0.0 ? 12 : 6;
            spray.perCell = moving ? perCell : 3;
            spray.steps = Eigen::Vector3d(4, -2, 2) * (moving ? perCell / 6 : 0); // (0.67, -0.33, 0.33) h
            spray.nParticle = deposit.nParticle3D;
            // Reach within 4 spacings.
            const double reach = std::min(deposit.reach, 4e-3);
            const DensityGrid grid = depositSpray(spray, kernelWithReach(reach, deposit.cloudInCellBelow));
            expectUniform(grid, spray, 0.01,
                          std::string("3D ") + deposit.name + (moving ? " moving" : " stationary"));
        }
    }
}

TEST(EdgeNodes, MassOnTheGridIsTheMassInside)
{
    // Single parcels near faces, edges and corners (kernels folded, cloud-in-cell), moving
    // (also across the faces) and stationary: the grid holds the mass deposited.
    std::mt19937_64 random(21);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int parcels = 0;
    for (const int dimensions : {2, 3})
    {
        Spray spray;
        spray.dimensions = dimensions;
        spray.cells = 6;
        const GridSpec spec = spray.grid();
        for (const Deposit& deposit : deposits)
        {
            for (int p = 0; p < 50; ++p, ++parcels)
            {
                DensityGrid grid(spec, kernelWithReach(deposit.reach, deposit.cloudInCellBelow));
                Parcel parcel = spray.parcels().front();
                parcel.nParticle = dimensions == 3 ? deposit.nParticle3D : deposit.nParticle;
                for (int d = 0; d < dimensions; ++d)
                {
                    // Within 1.5 spacings of a face, mostly, a few slightly outside.
                    const double fromFace = (1.6 * unit(random) - 0.1) * spacing;
                    parcel.position[d]
                        = unit(random) < 0.5 ? spec.lower[d] + fromFace : spec.upper[d] - fromFace;
                }
                parcel.velocity = p % 5 == 0 ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                                             : Eigen::Vector3d(unit(random) - 0.5, unit(random) - 0.5,
                                                               dimensions == 3 ? unit(random) - 0.5 : 0.0)
                        * (2.0 * spacing / dt);
                grid.deposit(parcel, dt);
                const double deposited = grid.stepStatistics().massDeposited;
                double onGrid = 0.0;
                for (std::size_t n = 0; n < spec.nodeCount(); ++n)
                {
                    onGrid += grid.stepValues()[n * nQuantities + quantityMass];
                }
                ASSERT_NEAR(onGrid, deposited, 1e-12 * spray.parcelMass()) << deposit.name << " parcel " << p;
            }
        }
    }
    EXPECT_EQ(parcels, 300);
}

TEST(EdgeNodes, KernelWiderThanTheGridConservesMass)
{
    // Reach beyond the ghost layers (one grid length beyond each face): the kernel is
    // folded as far as it is evaluated, the mass stays on the grid.
    Spray spray;
    spray.cells = 3;
    spray.nParticle = 50000.0;
    spray.steps = Eigen::Vector3d(1, 1, 0);
    const DensityGrid grid = depositSpray(spray, kernelWithReach(0.05, 0.0));
    const StepStatistics& stats = grid.lastStepStatistics();
    EXPECT_GT(stats.massDeposited, 0.0);
    EXPECT_NEAR(grid.windowMassPerStep(), stats.massDeposited, 1e-12 * stats.massDeposited);
}

TEST(EdgeNodes, SampleBetweenFaceNodeAndNeighbourIsUniform)
{
    Spray spray;
    const DensityGrid grid = depositSpray(spray, kernelWithReach(6e-3, 0.0));
    const GridSpec& spec = grid.spec();
    const double rho = spray.trueDensity();
    for (const double fraction : {0.0, 0.25, 0.5, 0.75})
    {
        // Between the corner node and its neighbours, and along the lower face.
        const Eigen::Vector3d corner(spec.lower.x() + fraction * spacing, spec.lower.y() + 0.3 * spacing,
                                     0.0);
        const Eigen::Vector3d face(spec.lower.x() + 4.5 * spacing, spec.lower.y() + fraction * spacing, 0.0);
        EXPECT_NEAR(grid.sample(corner).rho, rho, 0.01 * rho) << fraction;
        EXPECT_NEAR(grid.sample(face).rho, rho, 0.01 * rho) << fraction;
        EXPECT_NEAR(grid.sample(face).rMeanMass, dropletRadius, 1e-12 * dropletRadius);
    }
}

TEST(EdgeNodes, DualVolumesTileTheBox)
{
    for (const GridSpec& spec : {Spray{}.grid(),
                                 []
                                 {
                                     Spray s;
                                     s.dimensions = 3;
                                     s.cells = 1; // two nodes per direction: every node a corner
                                     return s.grid();
                                 }()})
    {
        double total = 0.0;
        for (int k = 0; k < spec.nodes[2]; ++k)
            for (int j = 0; j < spec.nodes[1]; ++j)
                for (int i = 0; i < spec.nodes[0]; ++i)
                {
                    total += spec.dualVolume(i, j, k);
                }
        const double box = (spec.upper - spec.lower).prod();
        EXPECT_NEAR(total, box, 1e-12 * box);
    }
    // A flat direction is not a face: its factor stays 1.
    const GridSpec flat = Spray{}.grid();
    EXPECT_EQ(flat.boundaryDirections(0, 0, 0), 2);
    EXPECT_EQ(flat.boundaryDirections(3, 0, 0), 1);
    EXPECT_EQ(flat.boundaryDirections(3, 4, 0), 0);
    // Mirror images of lattice indices, repeatedly reflected (nodes 0..10, period 20).
    EXPECT_EQ(flat.mirrorIndex(0, -1), 1);
    EXPECT_EQ(flat.mirrorIndex(0, 11), 9);
    EXPECT_EQ(flat.mirrorIndex(0, -12), 8);
    EXPECT_EQ(flat.mirrorIndex(0, 21), 1);
    EXPECT_EQ(flat.mirrorIndex(2, 5), 0);
}
