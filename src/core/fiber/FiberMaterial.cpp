#include "fiber/FiberMaterial.hpp"

#include <cmath>

namespace dropletFiber
{

double FiberMaterial::crossSection() const
{
    return M_PI * radius * radius;
}

double FiberMaterial::baseLineDensity() const
{
    return density * crossSection();
}

double FiberMaterial::bendingStiffness() const
{
    return youngsModulus * M_PI * radius * radius * radius * radius / 4.0;
}

} // namespace dropletFiber
