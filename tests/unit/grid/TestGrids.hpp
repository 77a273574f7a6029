// Test helper (not a test file): the small grids several grid tests use, and the
// random parcels they deposit, one definition each. grid2D: 3 x 2 cm, 1 mm spacing, one node layer 1 mm thick (31 x 21 nodes
// unless told otherwise); grid3D: 2 x 1.5 x 1 cm, 1 mm spacing (21 x 16 x 11 nodes).
#pragma once

#include "grid/GridSpec.hpp"
#include "grid/Parcel.hpp"

#include <array>
#include <random>
#include <vector>

namespace dropletFiber
{
namespace test
{

// Lattice coordinates i h, i = lowest..highest, on each axis (ghost indices below 0
// included), as SeparableWeight::prepare takes them: pointers at index 0.
struct TestLattice
{
    std::array<std::vector<double>, 3> coordinate;
    std::array<const double*, 3> atIndexZero;
};

inline TestLattice testLattice(int lowest, int highest, double h)
{
    TestLattice lattice;
    for (std::size_t d = 0; d < 3; ++d)
    {
        for (int i = lowest; i <= highest; ++i)
        {
            lattice.coordinate[d].push_back(i * h);
        }
        lattice.atIndexZero[d] = lattice.coordinate[d].data() - lowest;
    }
    return lattice;
}

inline GridSpec grid2D(int nx = 31, int ny = 21)
{
    GridSpec s;
    s.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
    s.upper = Eigen::Vector3d(0.03, 0.02, 1e-3);
    s.nodes = {{nx, ny, 1}};
    return s;
}

inline GridSpec grid3D()
{
    GridSpec s;
    s.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
    s.upper = Eigen::Vector3d(0.02, 0.015, 0.01);
    s.nodes = {{21, 16, 11}};
    return s;
}

// Grids off the origin whose cell counts 2, 3 and 4 do not all divide (multilinear weights,
// spread levels): 0.4 x 0.3 x 0.7 m with 9 x 7 x 5 nodes; 5 x 7 cm with 11 x 15 nodes, one
// layer 1 mm thick.
inline GridSpec offsetGrid3D()
{
    GridSpec s;
    s.lower = Eigen::Vector3d(-0.1, 0.2, 1.0);
    s.upper = Eigen::Vector3d(0.3, 0.5, 1.7);
    s.nodes = {{9, 7, 5}};
    return s;
}

inline GridSpec offsetGrid2D()
{
    GridSpec s;
    s.lower = Eigen::Vector3d(-0.025, 0.0, 0.0);
    s.upper = Eigen::Vector3d(0.025, 0.07, 0.001);
    s.nodes = {{11, 15, 1}};
    return s;
}

// Parcels anywhere in and a little beyond the box, wide and narrow kernels (the narrow
// ones go to the cell corners or the zero-weight fallback), moving and still.
// A random end position in the box grown by 5 % beyond each face (the middle of the node
// layer in flat directions) and velocity components uniform in +-speed/2 (speed 0: a
// stationary parcel, no draw), axis by axis.
inline void placeRandomly(const GridSpec& spec, double speed, std::mt19937_64& rng, Parcel& p)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int d = 0; d < 3; ++d)
    {
        const double size = spec.upper[d] - spec.lower[d];
        p.position[d] = spec.flat(d) ? 0.5 * (spec.lower[d] + spec.upper[d])
                                     : spec.lower[d] - 0.05 * size + 1.1 * size * unit(rng);
        p.velocity[d] = spec.flat(d) ? 0.0 : (speed == 0.0 ? 0.0 : speed * (unit(rng) - 0.5));
    }
}

inline std::vector<Parcel> randomParcels(const GridSpec& spec, int count, unsigned seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Parcel> parcels;
    for (int n = 0; n < count; ++n)
    {
        Parcel p;
        placeRandomly(spec, n % 5 == 0 ? 0.0 : 4.0, rng, p);
        p.diameter = 2e-5 * (0.5 + unit(rng));
        p.nParticle = n % 3 == 0 ? 2.0 : 20.0 + 200.0 * unit(rng);
        p.rhoDroplet = 1000.0;
        parcels.push_back(p);
    }
    return parcels;
}

} // namespace test
} // namespace dropletFiber
