// FiberInjector: a stream of straight fibers entering the domain, as in glass-wool
// production where fibers leave a spinner (the fiber source of the paper's figure 11).
//
// Fiber k of a stream is born at t_k = startTime + k / rate, for every k with
// t_k < endTime. It is laid straight from `position` along `direction` (unit), with
// all points moving at `velocity`, and - because it is only handed to the solver at
// the end of the CFD step in which it is born - it is moved on by velocity*(t - t_k),
// so that a stream looks the same whatever the CFD step.
//
// The only state is the number of fibers injected so far, which makes a restart
// exact: save injectedCount(), restore it with setInjectedCount().
#pragma once

#include "fiber/Fiber.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace dropletFiber
{

struct FiberInjectorSpec
{
    std::string name;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();   // first point of a new fiber [m]
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX(); // along the fiber (normalised)
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();   // of every point [m/s]
    double length = 0.0;                                  // [m]
    int points = 21;                                      // points per fiber (>= 2)
    double rate = 0.0;                                    // fibers per second
    double startTime = 0.0;                               // [s]
    double endTime = 0.0;                                 // [s], no fiber born at or after
    FiberMaterial material;
    // The physical fibers each computed fiber stands for (Fiber::represents), N > 0
    double represents = 1.0;

    // The glass mass flow the stream stands for [kg/s]: rate x N x one fiber's mass.
    double massFlow() const;

    // Throws std::invalid_argument naming the offending entry.
    void validate() const;
};

// The N (FiberInjectorSpec::represents) that makes a stream of `rate` computed fibers per
// second of this length and material carry the physical glass mass flow massFlow [kg/s]:
// N = massFlow / (rate rho_F pi r_F^2 length). Throws std::invalid_argument unless every
// input is finite and > 0.
double representsForMassFlow(double massFlow, double rate, double length, const FiberMaterial& material);

class FiberInjector
{
public:
    explicit FiberInjector(FiberInjectorSpec spec);

    const FiberInjectorSpec& spec() const { return spec_; }

    // Births counted exactly: 2^53, the largest count a double holds to the unit.
    static constexpr double maxBirths = 9007199254740992.0;

    // Number of fibers born at or before time t (and before endTime): any rate, also
    // with no endTime (a huge one). Throws std::overflow_error naming `rate` beyond
    // maxBirths (a count no run could hold in memory anyway).
    long bornBy(double t) const;

    // The fibers born in (.., t] not injected yet, placed as they are at time t.
    std::vector<Fiber> inject(double t);

    long injectedCount() const { return injected_; }
    void setInjectedCount(long count) { injected_ = count; }

private:
    FiberInjectorSpec spec_;
    long injected_ = 0;
};

} // namespace dropletFiber
