// Test helper (not a test file): the small grids several grid tests deposit on, one
// definition each. grid2D: 3 x 2 cm, 1 mm spacing, one node layer 1 mm thick (31 x 21 nodes
// unless told otherwise); grid3D: 2 x 1.5 x 1 cm, 1 mm spacing (21 x 16 x 11 nodes).
#pragma once

#include "grid/GridSpec.hpp"

namespace dropletFiber
{
namespace test
{

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

} // namespace test
} // namespace dropletFiber
