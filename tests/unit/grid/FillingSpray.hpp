// Test helper (not a test file): a uniform spray filling the grid box (EdgeNodesTest,
// CollisionNearWallTest). Parcels on a regular lattice of spacing s = h / perCell, at
// (a + 1/2) s from the box's lower corner, n droplets each. Each lattice cell of volume
// s^d (times the depth of a 2D grid) holds one parcel, so the true density is
// rho = n m_droplet / (s^d depth), whatever the grid does. Moving parcels: the lattice
// extends beyond the box on every side by more than a step's path, and v dt is a whole
// number of lattice spacings per direction; the paths' time inside the box is then
// uniform (every point of the box is crossed by the same number of paths), and the
// parcels wholly outside give nothing.
#pragma once

#include "grid/DensityGrid.hpp"

#include <algorithm>
#include <vector>

namespace dropletFiber
{
namespace test
{

inline constexpr double pi = 3.14159265358979323846;
inline constexpr double spacing = 1e-3; // node spacing h
inline constexpr double depth = 1e-3;   // thickness of the 2D grid
inline constexpr double dropletRadius = 1e-5;
inline constexpr double dt = 1e-4;

struct Spray
{
    int dimensions = 2;
    int cells = 10;                 // grid cells per active direction
    int perCell = 4;                // parcels per cell spacing
    double nParticle = 1000.0;      // droplets per parcel
    Eigen::Vector3d steps{0, 0, 0}; // v dt in lattice spacings (whole numbers)

    double latticeSpacing() const { return spacing / perCell; }
    Eigen::Vector3d velocity() const { return steps * latticeSpacing() / dt; }

    GridSpec grid() const
    {
        GridSpec spec;
        spec.lower = Eigen::Vector3d(-2e-3, 1e-3, 0.0);
        const double side = cells * spacing;
        spec.upper = spec.lower + Eigen::Vector3d(side, side, dimensions == 3 ? side : depth);
        spec.nodes = {{cells + 1, cells + 1, dimensions == 3 ? cells + 1 : 1}};
        return spec;
    }

    double parcelMass() const
    {
        return nParticle * 1000.0 * 4.0 / 3.0 * pi * dropletRadius * dropletRadius * dropletRadius;
    }

    double trueDensity() const
    {
        const double s = latticeSpacing();
        return parcelMass() / (dimensions == 3 ? s * s * s : s * s * depth);
    }

    // The lattice over the box, `extra` spacings beyond it on each side (moving parcels).
    std::vector<Parcel> parcels() const
    {
        const GridSpec spec = grid();
        const double s = latticeSpacing();
        const int extra
            = steps.cwiseAbs().maxCoeff() > 0 ? static_cast<int>(steps.cwiseAbs().maxCoeff()) + 2 : 0;
        const int count = cells * perCell;
        const int countZ = dimensions == 3 ? count : 1;
        const int extraZ = dimensions == 3 ? extra : 0;
        std::vector<Parcel> result;
        for (int c = -extraZ; c < countZ + extraZ; ++c)
            for (int b = -extra; b < count + extra; ++b)
                for (int a = -extra; a < count + extra; ++a)
                {
                    Parcel p;
                    const double z = dimensions == 3 ? spec.lower.z() + (c + 0.5) * s : 0.5 * depth;
                    p.position
                        = Eigen::Vector3d(spec.lower.x() + (a + 0.5) * s, spec.lower.y() + (b + 0.5) * s, z);
                    p.velocity = velocity();
                    p.diameter = 2.0 * dropletRadius;
                    p.nParticle = nParticle;
                    p.rhoDroplet = 1000.0;
                    result.push_back(p);
                }
        return result;
    }
};

inline KernelSettings kernelWithReach(double reach, double cloudInCellBelow)
{
    KernelSettings settings;
    settings.rMaxCap = reach;
    settings.cloudInCellBelow = cloudInCellBelow;
    return settings;
}

// One step of the spray on a grid; returns it committed.
inline DensityGrid depositSpray(const Spray& spray, const KernelSettings& settings)
{
    DensityGrid grid(spray.grid(), settings);
    for (const Parcel& p : spray.parcels())
    {
        grid.deposit(p, dt);
    }
    grid.commitStep();
    return grid;
}

struct Deposit
{
    const char* name;
    double reach;            // rMaxCap
    double cloudInCellBelow; // 0: the kernel
    double nParticle;        // droplets per parcel on 2D grids
    double nParticle3D;      // on 3D grids (the 3D r_min of eq. 15 makes kernels narrower)
};

// Kernel widths (eqs. 16-18, r_p = 10 um, h = 1 mm): narrow 0.57 h (2D, n = 1000) and
// 0.55 h (3D, n = 1700), just above the function object's cloudInCellBelow 0.5; wide 2 h
// (2D, n = 5000) and 1.4 h (3D, n = 5000). Cloud-in-cell: the parcels of the narrow kernel.
inline const Deposit deposits[] = {
    {"cloud-in-cell", 2e-3, 1e9, 1000.0, 1700.0},
    {"narrow kernel", 2e-3, 0.0, 1000.0, 1700.0},
    {"wide kernel", 6e-3, 0.0, 5000.0, 5000.0},
};

} // namespace test
} // namespace dropletFiber
