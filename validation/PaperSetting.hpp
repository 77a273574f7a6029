// PaperSetting: every physical and numerical value of the validation against section 6 of
// Schröder et al. 2011 (docs/model.md sec. 5), in one place. Values the paper states are marked
// "paper"; the others are our choice, the reason given beside each.
//
// Geometry of the paper's 2D test (its figure 6): droplets fly in the x-y plane; the
// fiber is a cylinder normal to that plane, so the plane shows its cross-section, the
// circle of radius r_F around (0, 3 cm). The 2D plane is a slab of depth `depth` in z
// (the density grid's flat direction); eq. 9 for the fiber is a segment along z of length
// `depth`, so all masses are per slab and the depth cancels from every comparison.
#pragma once

#include <cmath>
#include <vector>

namespace dropletFiber
{
namespace validation
{

constexpr double pi = 3.14159265358979323846;

struct PaperSetting
{
    // --- domain and fiber (paper, sec. 6 and figure 6) -----------------------------------
    double xMin = -0.025, xMax = 0.025; // box, m
    double yMin = 0.0, yMax = 0.07;
    double injectionHalfWidth = 0.0249; // streams injected over [-2.49, 2.49] cm at y = yMax
    double fiberX = 0.0, fiberY = 0.03; // circle centre
    double fiberRadius = 0.01;          // r_F = 1 cm unless varied
    // Choice: any depth works (masses are per slab); 1 cm keeps rho in ordinary units.
    double depth = 0.01;

    // --- droplets (paper: r_p = 1e-5 m in its figure 4; the rest is our choice) -----------
    double dropletRadius = 1e-5;    // paper, figure 4
    double dropletDensity = 1000.0; // water
    // Speed and step: 1 m/s and 1 ms give 1 mm of flight per step, between the node
    // spacings of the 50x50 (1.4 mm) and 250x250 (0.28 mm) grids in y.
    double speed = 1.0; // m/s, straight down (-y), constant (paper)
    double dt = 1e-3;   // s
    // One parcel per stream per step: the parcels' paths tile each stream line exactly,
    // so the spray is steady from step to step (the paper's constant flow rate).
    double injectionInterval = 1e-3; // s
    double injectionPhase = 0.37;    // parcels' offset within a step (avoids ties)

    // --- evaluation -----------------------------------------------------------------------
    int outlineSegments = 256; // closed polyline approximating the circle (at least)
    double beta = 0.025;       // paper, eq. 18

    // --- figure 7: fixed total flow rate, 50-500 streams ---------------------------------
    // Choice: 500 droplets per step in total (2.09e-9 kg per ms), so 50 streams carry 10
    // droplets per parcel and 500 streams 1 (the paper's "1-10 particles per parcel").
    double fig7DropletsPerStep = 500.0;
    std::vector<int> fig7Streams{50, 100, 150, 200, 250, 300, 350, 400, 450, 500};
    std::vector<int> fig7Grids{50, 100};

    // --- figure 8: 100 streams, 100x100, 1-1000 droplets per parcel (paper) ---------------
    int fig8Streams = 100;
    std::vector<double> fig8DropletsPerParcel{1,   2,   5,   10,  20,  50,  100, 200,
                                              300, 400, 500, 600, 700, 800, 900, 1000};
    int fig8Grid = 100;

    // --- figure 9: polydisperse, 200 streams, 6-100 droplets per parcel (paper) -----------
    // Choice: every parcel carries the same mass (as OpenFOAM injectors do) and its droplet
    // radius is drawn uniformly from [polyRadiusLow, polyRadiusHigh]; n = parcel mass / m(r).
    // With parcel mass = 100 m(6 um), n runs from 100 (r = 6 um) to 6 (r = 15.3 um).
    int fig9Streams = 200;
    double polyRadiusLow = 6e-6;
    double polyRadiusHigh = 6e-6 * std::cbrt(100.0 / 6.0);
    double polyParcelDroplets = 100.0; // droplets of radius polyRadiusLow per parcel mass
    std::vector<double> fig9FiberRadii{2e-4,   3e-4,   4e-4,   5e-4,   6e-4,   7e-4,   8e-4,
                                       9e-4,   1e-3,   1.1e-3, 1.2e-3, 1.3e-3, 1.4e-3, 1.5e-3,
                                       1.6e-3, 1.7e-3, 1.8e-3, 1.9e-3, 2e-3};
    int fig9Grid = 100;

    // --- figure 10: grid 100x100 vs 250x250, fiber radius up to 14 mm (paper) -------------
    // The spray of figure 9.
    std::vector<double> fig10FiberRadii{1e-3, 2e-3, 3e-3, 4e-3,   5e-3,   6e-3,   7e-3,
                                        8e-3, 9e-3, 1e-2, 1.1e-2, 1.2e-2, 1.3e-2, 1.4e-2};
    std::vector<int> fig10Grids{100, 250};

    // --- radius question (docs/model.md note under eq. 10) -------------------------------------
    // Fiber radii down to the droplet size, where the mean radius matters most.
    std::vector<double> radiusStudyFiberRadii{2e-5, 5e-5, 1e-4, 2e-4, 5e-4, 1e-3, 2e-3};

    // --- statistics of the geometric references -------------------------------------------
    int spreadSeeds = 16;       // droplets spread within r_min: seeds...
    int spreadStepsPerSeed = 8; // ...times steps counted per seed
    // Fine reference (jittered injection, spread droplets): radius question, up to fineSteps
    // steps per seed (fewer for thick fibers); figure 9, fineSteps / 20 per seed.
    int fineSteps = 100000;
    int fineSeeds = 10;

    // Geometric staircase: fiber radii 9-11 mm in steps of 0.05 mm (100 streams).
    double sawtoothStep = 5e-5;
    std::vector<double> sawtoothFiberRadii() const
    {
        std::vector<double> radii;
        for (double r = 9e-3; r <= 11e-3 + 1e-12; r += sawtoothStep)
        {
            radii.push_back(r);
        }
        return radii;
    }

    double dropletMass(double radius) const
    {
        return dropletDensity * 4.0 / 3.0 * pi * radius * radius * radius;
    }
    double injectionWidth() const { return 2.0 * injectionHalfWidth; }
    double polyParcelMass() const { return polyParcelDroplets * dropletMass(polyRadiusLow); }

    // A reduced setting for the CTest run: fewer sweep points and seeds, same physics.
    static PaperSetting reduced()
    {
        PaperSetting s;
        s.fig7Streams = {50, 200, 500};
        s.fig8DropletsPerParcel = {1, 10, 100, 1000};
        s.fig9FiberRadii = {2e-4, 1e-3, 2e-3};
        s.fig10FiberRadii = {4e-3, 1e-2};
        s.radiusStudyFiberRadii = {5e-5, 5e-4};
        s.spreadSeeds = 6;
        s.spreadStepsPerSeed = 4;
        s.fineSteps = 40000;
        s.sawtoothStep = 5e-4;
        s.fineSeeds = 6;
        return s;
    }
};

} // namespace validation
} // namespace dropletFiber
