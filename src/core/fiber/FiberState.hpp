// FiberState: everything that defines a fiber between two steps, as plain data, for
// restart files. Restoring a FiberState and stepping on is bit-for-bit identical to
// never having stopped (the solver keeps no other state).
//
// Mass is stored per segment: the segment's base mass is rho_F pi r_F^2 l_j (from the
// material and the rest length) and segmentCapturedMass_j is the droplet mass it has
// collected. Point masses are lumped: half of each adjacent segment.
#pragma once

#include "fiber/EndCondition.hpp"
#include "fiber/FiberMaterial.hpp"

#include <Eigen/Core>

namespace dropletFiber
{

struct FiberState
{
    Eigen::Matrix3Xd positions;          // x_i [m], n points
    Eigen::Matrix3Xd velocities;         // v_i [m/s]
    Eigen::VectorXd restLengths;         // l_j [m], n-1 segments (held fixed: inextensible)
    Eigen::VectorXd segmentCapturedMass; // [kg] per segment
    Eigen::VectorXd tension;             // T_j [N] per segment (last step's multipliers)
    Eigen::Matrix3Xd externalForce;      // [N] per point, applied every step until changed
    FiberMaterial material;
    EndCondition startEnd; // at point 0
    EndCondition endEnd;   // at point n-1
    bool immobile = false; // fully fixed fiber (filters, validation)
    // The physical fibers this computed fiber stands for, N > 0 (docs/model.md sec. 9):
    // each the same in every respect (path, shape, captured mass per length, hits); the
    // spray loses N times what the fiber captures. The state's masses are one fiber's.
    double represents = 1.0;
    // The half-width [m] of the hat its population (the represents - 1 others) was spread
    // over at the last step its centre was inside the coupling grid (docs/model.md sec.
    // 12): how the population lies on the belt when laid (sec. 11, P59); 0 without one.
    double populationSpread = 0.0;
    // Turbulent velocity fluctuation u' [m/s] per point (TurbulentAir, docs/model.md
    // sec. 8): part of the state so that a restart continues the same realisation;
    // empty (0 columns) without turbulence, or before the first turbulent step.
    Eigen::Matrix3Xd turbulentVelocity;
    // Droplets caught per segment since the fiber was made (collision mode discrete: whole
    // numbers; expected: the expected counts), for the binder distribution output
    // (docs/model.md sec. 3, discrete hits). A state without them (empty) reads as zeros.
    Eigen::VectorXd segmentHits;
    // The mass each segment would have caught in the expected mode on the same path (its
    // samples' granted masses; = segmentCapturedMass in expected mode), so that the binder
    // distribution of both modes can be compared. A state without it (empty) reads as
    // segmentCapturedMass.
    Eigen::VectorXd segmentExpectedMass;
};

} // namespace dropletFiber
