// Test helper (not a test file): a steady, uniform spray through a 2D box, parcels in
// parallel streams moving in -y, one parcel per stream and step, spaced so that the
// parcels of a stream move exactly one spacing per step (their paths tile the stream
// line without gaps or overlaps). The analytic droplet mass density is then
//     rho = parcel mass / (stream spacing * parcel spacing * depth)
// = flow rate / (velocity * cross-section).
#pragma once

#include "grid/DensityGrid.hpp"

#include <vector>

namespace dropletFiber
{
namespace test
{

struct UniformStream
{
    // Box 20 mm x 30 mm, depth 1 mm, nodes every 0.5 mm.
    double width = 0.02, height = 0.03, depth = 1e-3, spacing = 5e-4;
    // Parcels: 1000 droplets of 10 um radius, water, 5 m/s down, dt = 1e-4 s.
    double nParticle = 1000.0, dropletRadius = 1e-5, rhoDroplet = 1000.0;
    double speed = 5.0, dt = 1e-4;
    double streamSpacing = 2.5e-4; // across the flow
    double phase = 0.3;            // position of the parcels within their spacing

    GridSpec grid() const
    {
        GridSpec s;
        s.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
        s.upper = Eigen::Vector3d(width, height, depth);
        s.nodes = {
            {static_cast<int>(width / spacing + 0.5) + 1, static_cast<int>(height / spacing + 0.5) + 1, 1}};
        return s;
    }

    double parcelSpacing() const { return speed * dt; }

    double parcelMassAnalytic() const
    {
        return nParticle * rhoDroplet * 4.0 / 3.0 * 3.14159265358979323846 * dropletRadius * dropletRadius
            * dropletRadius;
    }

    double rhoAnalytic() const { return parcelMassAnalytic() / (streamSpacing * parcelSpacing() * depth); }

    // Parcels at the end of any step: streams at x = (i + 1/2) streamSpacing inside the
    // box; along y every parcelSpacing, from below the box to above it. Each parcel moves
    // one spacing per step and its upstream neighbour takes its place, so the set at the
    // end of every step is the same: the flow is steady.
    std::vector<Parcel> parcels() const
    {
        std::vector<Parcel> result;
        const int streams = static_cast<int>(width / streamSpacing + 0.5);
        const double dy = parcelSpacing();
        const int rows = static_cast<int>(height / dy + 0.5) + 2;
        for (int i = 0; i < streams; ++i)
        {
            for (int m = -1; m < rows; ++m)
            {
                Parcel p;
                const double y = (m + phase) * dy;
                p.position = Eigen::Vector3d((i + 0.5) * streamSpacing, y, 0.5 * depth);
                p.velocity = Eigen::Vector3d(0.0, -speed, 0.0);
                p.diameter = 2.0 * dropletRadius;
                p.nParticle = nParticle;
                p.rhoDroplet = rhoDroplet;
                result.push_back(p);
            }
        }
        return result;
    }
};

} // namespace test
} // namespace dropletFiber
