// Parcel: one O'Rourke computational particle as the density grid sees it, and its mass.
//
// Convention (shared with the OpenFOAM layer and the dropletGrid tool): `position` is the
// parcel's position at the END of the time step, as OpenFOAM reports it after the move.
// The path during the step is the straight segment
//     from  position - velocity * dt   to  position,
// i.e. eq. 19's p is position - velocity * dt and v dt is velocity * dt.
#pragma once

#include <Eigen/Core>

namespace dropletFiber
{

struct Parcel
{
    Eigen::Vector3d position{0.0, 0.0, 0.0}; // end of the step, m
    Eigen::Vector3d velocity{0.0, 0.0, 0.0}; // droplet velocity, m/s
    double diameter = 0.0;                   // droplet diameter 2 r_p, m
    double nParticle = 0.0;                  // droplets in the parcel, n (may be fractional)
    double rhoDroplet = 0.0;                 // droplet material density rho_p, kg/m^3
};

// m(r_p) = rho_p 4/3 pi r_p^3, one droplet.
double dropletMass(double diameter, double rhoDroplet);
// n m(r_p), the whole parcel.
double parcelMass(const Parcel& parcel);

// A parcel as flat numbers, the layout of every message, log and file that carries parcels
// (the blocks' exchange, the deposit log, dropletGrid's input): position x y z, velocity
// x y z, diameter, nParticle, rhoDroplet.
constexpr int parcelValueCount = 9;
void writeParcelValues(const Parcel& parcel, double* values);
Parcel parcelFromValues(const double* values);

} // namespace dropletFiber
