// DragModel: air drag on a slender fiber, per unit length, split into a normal and a
// tangential resistance (the f_air of docs/model.md eq. 2):
//     f = c_n (w - (w.t) t) + c_t (w.t) t,    w = u_air - v_fiber,  t = unit tangent.
// Models:
//   none               f = 0.
//   linear             given c_n, c_t [N s/m^2] (tests, calibrated cases).
//   slenderBodyStokes  leading-order slender-body theory for Stokes flow
//                      (Batchelor 1970, J. Fluid Mech. 44:419; Cox 1970, J. Fluid Mech.
//                      44:791; as resistive-force theory): with Lambda = ln(L/r_F),
//                      c_n = 4 pi mu / Lambda,  c_t = 2 pi mu / Lambda  (c_n = 2 c_t).
//                      Valid when the Reynolds number on the fiber LENGTH is small.
//   slenderBodyOseen   the same with the Oseen cut-off: once the Oseen length
//                      mu/(rho |w_n|) is shorter than the fiber, the logarithm is Lamb's
//                      (1911) Oseen result for a cylinder in cross-flow,
//                      Lambda = min( ln(L/r_F), ln(8/Re_n) + 1/2 - gamma_Euler ),
//                      Re_n = rho 2 r_F |w_n| / mu, c_t = c_n / 2 kept from slender-body
//                      theory. Lamb's formula holds for Re_n <~ 1; above Re_n = 1 the
//                      logarithm is held at its Re_n = 1 value (2.002), so drag is
//                      under-predicted there (an empirical high-Re closure such as
//                      FIDYST's Marheineke-Wegener drag is NOT implemented).
// The coefficients are evaluated once per sub-step from the state at its start
// ("lagged"; they depend on speed only through a logarithm), so the drag force is
// linear in the velocity within a sub-step and its Jacobian is exact.
#pragma once

#include <string>

namespace dropletFiber
{

enum class DragModelType
{
    none,
    linear,
    slenderBodyStokes,
    slenderBodyOseen
};

struct DragSettings
{
    DragModelType model = DragModelType::none;
    double normalCoefficient = 0.0;     // linear model: c_n [N s/m^2]
    double tangentialCoefficient = 0.0; // linear model: c_t [N s/m^2]
};

struct DragCoefficients
{
    double normal = 0.0;     // c_n [N s/m^2]
    double tangential = 0.0; // c_t [N s/m^2]
};

// normalRelativeSpeed = |w_n| [m/s] (used by slenderBodyOseen only).
DragCoefficients dragCoefficients(const DragSettings& settings, double airDensity, double airViscosity,
                                  double fiberRadius, double fiberLength, double normalRelativeSpeed);

// The logarithm Lambda of the slender-body models (exposed for tests / reports).
double slenderBodyLogarithm(DragModelType model, double airDensity, double airViscosity, double fiberRadius,
                            double fiberLength, double normalRelativeSpeed);

// The same two in two parts, for a caller that evaluates every point of one fiber:
// the fiber's own part max(ln(L/r_F), 1), taken once per fiber, then the per-point
// coefficients from it (the same bits as the functions above).
double fiberLogarithm(double fiberRadius, double fiberLength);
DragCoefficients dragCoefficientsOfFiber(const DragSettings& settings, double airDensity, double airViscosity,
                                         double fiberRadius, double fiberLogarithm,
                                         double normalRelativeSpeed);

DragModelType dragModelFromName(const std::string& name); // throws on unknown names
std::string dragModelName(DragModelType model);

} // namespace dropletFiber
