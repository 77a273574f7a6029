#include "grid/Parcel.hpp"

#include <algorithm>

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

void writeParcelValues(const Parcel& parcel, double* values)
{
    const double flat[parcelValueCount]
        = {parcel.position[0], parcel.position[1], parcel.position[2], parcel.velocity[0], parcel.velocity[1],
           parcel.velocity[2], parcel.diameter,    parcel.nParticle,   parcel.rhoDroplet};
    std::copy(flat, flat + parcelValueCount, values);
}

Parcel parcelFromValues(const double* values)
{
    Parcel parcel;
    parcel.position = Eigen::Vector3d(values[0], values[1], values[2]);
    parcel.velocity = Eigen::Vector3d(values[3], values[4], values[5]);
    parcel.diameter = values[6];
    parcel.nParticle = values[7];
    parcel.rhoDroplet = values[8];
    return parcel;
}

} // namespace dropletFiber
