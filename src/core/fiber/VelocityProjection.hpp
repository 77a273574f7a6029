// VelocityProjection: make point velocities consistent with inextensibility,
// e_j . (v_{j+1} - v_j) = 0 for every segment, by the smallest mass-weighted change
//     v <- v - M^{-1} G^T mu,   (G M^{-1} G^T) mu = G v.
// This is the impulsive tension response of an inextensible fiber (mu_j = tension
// impulse); it conserves momentum (the impulses are internal) except at held points,
// whose prescribed velocity it leaves untouched (infinite mass). G M^{-1} G^T is
// tridiagonal and SPD: solved by the Thomas algorithm in O(n).
#pragma once

#include "fiber/Fiber.hpp"

namespace dropletFiber
{

// Sets held points to their prescribed velocity, then projects the rest.
void projectVelocities(Fiber& fiber);

} // namespace dropletFiber
