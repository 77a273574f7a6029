// FiberMaterial: the solid properties of one fiber (radius, density, Young's modulus)
// and the line quantities the dynamics needs from them (docs/model.md sec. 1):
// base line density rho_F pi r_F^2 and bending stiffness S_b = E pi r_F^4 / 4.
#pragma once

namespace dropletFiber
{

struct FiberMaterial
{
    double radius = 0.0;        // r_F [m]
    double density = 0.0;       // rho_F [kg/m^3]
    double youngsModulus = 0.0; // E [Pa]; 0 gives a limp chain (S_b = 0)

    double crossSection() const;     // A = pi r_F^2 [m^2]
    double baseLineDensity() const;  // rho_F A [kg/m], before any captured droplets
    double bendingStiffness() const; // S_b = E I, I = pi r_F^4 / 4 [N m^2]
};

} // namespace dropletFiber
