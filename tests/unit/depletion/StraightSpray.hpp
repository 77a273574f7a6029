// Test helper (not a test file): a monodisperse spray crossing a 2D box in +y at constant
// velocity (straight paths), through fixed fibers along z (across the flow, one segment of
// the box's depth each), with the step of the function object in core terms:
//     move -> inject -> deposit -> commit -> eq. 9 per fiber -> depths -> remove droplets -> grant
// Streams: four per node spacing across x, at x = (j/4 + 1/8) h, one parcel per stream and
// step injected at the lower face: the pattern repeats every spacing and is symmetric about
// every node column, so an x-uniform set of fibers sees an x-uniform spray. Parcels are
// deposited cloud-in-cell (narrow kernels), so a node row receives exactly the incoming
// density (the hat functions sampled every half spacing sum to a constant).
// Bookkeeping: sprayed = airborne + left + captured (the binder balance).
#pragma once

#include "depletion/CaptureLimit.hpp"

#include <cmath>
#include <vector>

namespace dropletFiber
{
namespace test
{

struct StraightSpray
{
    // Box: columns x rows node spacings of h, depth h; nodes on the bounds.
    double h = 1e-3;
    int columns = 8;
    int rows = 56;
    double speed = 1.0, dt = 5e-4; // a path of half a spacing per step
    double dropletRadius = 1e-5, nParticle = 100.0, rhoDroplet = 1000.0;
    double fiberRadius = 1.5e-5;
    bool depletion = true;

    std::vector<Eigen::Vector2d> fibers; // (x, y) of each fiber, spanning the depth
    std::vector<double> fiberCaptured;   // per fiber, summed over the measured steps

    double sprayed = 0.0, left = 0.0, captured = 0.0;
    double injectedMeasured = 0.0; // sprayed during the measured steps
    std::vector<Parcel> parcels;
    CaptureLimitReport limits; // summed over all steps

    GridSpec grid() const
    {
        GridSpec s;
        s.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
        s.upper = Eigen::Vector3d(columns * h, rows * h, h);
        s.nodes = {{columns + 1, rows + 1, 1}};
        return s;
    }

    double airborne() const
    {
        double mass = 0.0;
        for (const Parcel& p : parcels)
        {
            mass += parcelMass(p);
        }
        return mass;
    }

    // Runs warmUp steps, then `measured` steps in which fiberCaptured and injectedMeasured add up.
    void run(int warmUp, int measured)
    {
        KernelSettings settings;
        settings.cloudInCellBelow = 0.5;
        const GridSpec spec = grid();
        DensityGrid density(spec, settings, 1);
        fiberCaptured.assign(fibers.size(), 0.0);
        for (int step = 0; step < warmUp + measured; ++step)
        {
            const bool measuring = step >= warmUp;
            moveAndInject(spec, measuring);
            for (const Parcel& p : parcels)
            {
                density.deposit(p, dt);
            }
            density.commitStep();
            collideAndDeplete(density, measuring);
        }
    }

private:
    void moveAndInject(const GridSpec& spec, bool measuring)
    {
        std::vector<Parcel> kept;
        for (Parcel p : parcels)
        {
            p.position += p.velocity * dt;
            if (p.position.y() - speed * dt >= spec.upper.y())
            {
                left += parcelMass(p); // the whole step's path beyond the box
                continue;
            }
            kept.push_back(p);
        }
        parcels.swap(kept);
        for (int j = 0; j < 4 * columns; ++j)
        {
            Parcel p;
            p.position = Eigen::Vector3d((0.25 * j + 0.125) * h, 0.5 * speed * dt, 0.5 * h);
            p.velocity = Eigen::Vector3d(0.0, speed, 0.0);
            p.diameter = 2.0 * dropletRadius;
            p.nParticle = nParticle;
            p.rhoDroplet = rhoDroplet;
            sprayed += parcelMass(p);
            injectedMeasured += measuring ? parcelMass(p) : 0.0;
            parcels.push_back(p);
        }
    }

    void collideAndDeplete(DensityGrid& density, bool measuring)
    {
        CaptureLimit limit;
        std::vector<SegmentCapture> segments;
        for (const Eigen::Vector2d& fiber : fibers)
        {
            const Eigen::Vector3d a(fiber.x(), fiber.y(), 0.0), b(fiber.x(), fiber.y(), h);
            segments.push_back(segmentCapture(density, a, b, fiberRadius, Eigen::Vector3d::Zero(), dt));
            limit.addDemand(segments.back());
        }
        CaptureLimitReport report = limit.limit(density);
        // P14: the same parcels and dt as deposited this step; the fibers granted what left them.
        std::vector<double> fraction(parcels.size(), 0.0);
        if (depletion)
        {
            fraction = limit.removeFromParcels(density, parcels, dt, report);
        }
        limits += report;
        for (std::size_t f = 0; f < fibers.size(); ++f)
        {
            const double mass = depletion ? limit.granted(segments[f]).mass : segments[f].collision.mass;
            captured += mass;
            fiberCaptured[f] += measuring ? mass : 0.0;
        }
        for (std::size_t p = 0; p < parcels.size(); ++p)
        {
            parcels[p].nParticle *= 1.0 - fraction[p];
        }
    }
};

} // namespace test
} // namespace dropletFiber
