#include "laydown/LayingZone.hpp"

#include <algorithm>
#include <cmath>

namespace dropletFiber
{

void LayingZone::add(const LaidFiber& fiber, double speed)
{
    if (firstTime < 0.0)
        firstTime = fiber.time;
    const double foot = speed * fiber.time - fiber.along;
    footMin = std::min(footMin, foot);
    footMax = std::max(footMax, foot);
    reach = std::max(reach, 0.5 * fiber.endToEnd * std::abs(fiber.orientation.y()) + fiber.spread);
}

std::pair<long, long> LayingZone::completeRows(double speed, double cell, double steadyFrom,
                                               double time) const
{
    if (firstTime < 0.0 || !(speed > 0.0))
        return {1, 0};
    const double from = speed * std::max(firstTime, steadyFrom) - footMin + reach;
    const double to = speed * time - footMax - reach;
    return {static_cast<long>(std::ceil(from / cell - 1e-9)),
            static_cast<long>(std::floor(to / cell + 1e-9)) - 1};
}

} // namespace dropletFiber
