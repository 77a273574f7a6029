// A steady uniform spray through the grid (UniformStream.hpp): the grid's rho equals the
// analytic mass density flow rate / (velocity * cross-section) within 0.5 % away from
// the edges, and the mean radius and velocity are the parcels' own.
#include "UniformStream.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dropletFiber;

TEST(DensityGridStream, UniformSprayGivesAnalyticDensity)
{
    const test::UniformStream stream;
    KernelSettings settings;
    settings.rMaxCap = 3e-3; // r_max = 1 cm; the Gaussian (inflection at 0.57 mm) is ~1e-6 at 3 mm
    DensityGrid grid(stream.grid(), settings, 3);
    const std::vector<Parcel> parcels = stream.parcels();
    for (int step = 0; step < 3; ++step)
    {
        for (const Parcel& p : parcels)
        {
            grid.deposit(p, stream.dt);
        }
        grid.commitStep();
        // Every parcel that reaches the box has r_max = 1 cm > cap.
        const StepStatistics& stats = grid.lastStepStatistics();
        EXPECT_EQ(stats.parcelsCapped, stats.parcels - stats.parcelsOutside);
        EXPECT_GT(stats.parcelsCapped, 4000);
    }
    const double rho = stream.rhoAnalytic();
    const GridSpec spec = grid.spec();
    int checked = 0;
    double worst = 0.0;
    for (int j = 0; j < spec.nodes[1]; ++j)
    {
        for (int i = 0; i < spec.nodes[0]; ++i)
        {
            const Eigen::Vector3d g = spec.nodePosition(i, j, 0);
            // Away from the edges: more than reach + 1 mm from the box boundary.
            const double margin = 4e-3;
            if (g.x() < margin || g.x() > stream.width - margin || g.y() < margin
                || g.y() > stream.height - margin)
            {
                continue;
            }
            const DropletFieldValue f = grid.nodeValue(i, j, 0);
            EXPECT_NEAR(f.rho, rho, 0.005 * rho) << i << " " << j;
            worst = std::max(worst, std::abs(f.rho / rho - 1.0));
            EXPECT_NEAR(f.rMeanNumber, stream.dropletRadius, 1e-12 * stream.dropletRadius);
            EXPECT_NEAR(f.rMeanMass, stream.dropletRadius, 1e-12 * stream.dropletRadius);
            EXPECT_NEAR(f.velocity.y(), -stream.speed, 1e-12 * stream.speed);
            EXPECT_EQ(f.velocity.x(), 0.0);
            ++checked;
        }
    }
    EXPECT_GT(checked, 200);
    char worstText[32];
    std::snprintf(worstText, sizeof worstText, "%.3e", worst);
    RecordProperty("worstRelativeDeviation", worstText);
    // Interpolated between nodes as well.
    const DropletFieldValue mid = grid.sample(Eigen::Vector3d(0.01012, 0.01537, 0.0));
    EXPECT_NEAR(mid.rho, rho, 0.005 * rho);
}
