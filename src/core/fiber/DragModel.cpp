#include "fiber/DragModel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dropletFiber
{

namespace
{
constexpr double eulerGamma = 0.57721566490153286;
// ln(L/r) below 1 means a fiber shorter than ~3 radii: slender-body theory does not
// apply at all; hold the logarithm there rather than let the coefficient blow up.
constexpr double minimumLogarithm = 1.0;

double slenderBodyLogarithmOfFiber(DragModelType model, double airDensity, double airViscosity,
                                   double fiberRadius, double fiberLogarithm, double normalRelativeSpeed)
{
    double lambda = fiberLogarithm;
    if (model == DragModelType::slenderBodyOseen)
    {
        const double reynolds = airDensity * 2.0 * fiberRadius * normalRelativeSpeed / airViscosity;
        if (reynolds > 0.0)
        {
            // Lamb's logarithm, held at its Re_n = 1 value beyond its range.
            const double lamb = std::log(8.0 / std::min(reynolds, 1.0)) + 0.5 - eulerGamma;
            lambda = std::min(lambda, lamb);
        }
    }
    return lambda;
}

} // namespace

double fiberLogarithm(double fiberRadius, double fiberLength)
{
    return std::max(std::log(fiberLength / fiberRadius), minimumLogarithm);
}

double slenderBodyLogarithm(DragModelType model, double airDensity, double airViscosity, double fiberRadius,
                            double fiberLength, double normalRelativeSpeed)
{
    return slenderBodyLogarithmOfFiber(model, airDensity, airViscosity, fiberRadius,
                                       fiberLogarithm(fiberRadius, fiberLength), normalRelativeSpeed);
}

DragCoefficients dragCoefficientsOfFiber(const DragSettings& settings, double airDensity, double airViscosity,
                                         double fiberRadius, double fiberLogarithm,
                                         double normalRelativeSpeed)
{
    switch (settings.model)
    {
        case DragModelType::none:
            return {0.0, 0.0};
        case DragModelType::linear:
            return {settings.normalCoefficient, settings.tangentialCoefficient};
        case DragModelType::slenderBodyStokes:
        case DragModelType::slenderBodyOseen:
        {
            const double lambda = slenderBodyLogarithmOfFiber(
                settings.model, airDensity, airViscosity, fiberRadius, fiberLogarithm, normalRelativeSpeed);
            const double normal = 4.0 * M_PI * airViscosity / lambda;
            return {normal, 0.5 * normal};
        }
    }
    return {0.0, 0.0};
}

DragCoefficients dragCoefficients(const DragSettings& settings, double airDensity, double airViscosity,
                                  double fiberRadius, double fiberLength, double normalRelativeSpeed)
{
    const bool slender = settings.model == DragModelType::slenderBodyStokes
        || settings.model == DragModelType::slenderBodyOseen;
    return dragCoefficientsOfFiber(settings, airDensity, airViscosity, fiberRadius,
                                   slender ? fiberLogarithm(fiberRadius, fiberLength) : 0.0,
                                   normalRelativeSpeed);
}

DragModelType dragModelFromName(const std::string& name)
{
    if (name == "none")
        return DragModelType::none;
    if (name == "linear")
        return DragModelType::linear;
    if (name == "slenderBodyStokes")
        return DragModelType::slenderBodyStokes;
    if (name == "slenderBodyOseen")
        return DragModelType::slenderBodyOseen;
    throw std::invalid_argument("unknown fiber drag model '" + name
                                + "' (valid: none linear slenderBodyStokes slenderBodyOseen)");
}

std::string dragModelName(DragModelType model)
{
    switch (model)
    {
        case DragModelType::none:
            return "none";
        case DragModelType::linear:
            return "linear";
        case DragModelType::slenderBodyStokes:
            return "slenderBodyStokes";
        case DragModelType::slenderBodyOseen:
            return "slenderBodyOseen";
    }
    return "unknown";
}

} // namespace dropletFiber
