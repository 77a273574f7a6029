#include "grid/Parcel.hpp"

namespace dropletFiber
{

double dropletMass(double diameter, double rhoDroplet)
{
    constexpr double pi = 3.14159265358979323846;
    const double radius = 0.5 * diameter;
    return rhoDroplet * (4.0 / 3.0) * pi * radius * radius * radius;
}

double parcelMass(const Parcel& parcel)
{
    return parcel.nParticle * dropletMass(parcel.diameter, parcel.rhoDroplet);
}

} // namespace dropletFiber
