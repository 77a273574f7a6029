#include "Experiments.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace dropletFiber
{
namespace validation
{

namespace
{
// Steps the polydisperse grid runs average over: the mean radius at the fiber comes from a
// few parcels of random radius, so several steps are averaged (eq. 26's window).
constexpr int polyWindow = 10;

// Steps the formula's count averages over (steady spray: any number gives the same).
constexpr int formulaSteps = 4;

const Eigen::Vector3d downward(0.0, -1.0, 0.0);

std::string gridColumn(int nodes, const std::string& variant)
{
    return "grid" + std::to_string(nodes) + "_" + variant;
}
} // namespace

SprayDefinition monodisperseSpray(const PaperSetting& setting, int streams, double dropletsPerParcel)
{
    SprayDefinition d;
    d.streams = streams;
    d.injectionHalfWidth = setting.injectionHalfWidth;
    d.yInjection = setting.yMax;
    d.speed = setting.speed;
    d.dt = setting.dt;
    d.injectionInterval = setting.injectionInterval;
    d.injectionPhase = setting.injectionPhase;
    d.zMid = 0.0;
    d.dropletDensity = setting.dropletDensity;
    d.dropletRadius = setting.dropletRadius;
    d.dropletsPerParcel = dropletsPerParcel;
    return d;
}

SprayDefinition polydisperseSpray(const PaperSetting& setting, int streams)
{
    SprayDefinition d = monodisperseSpray(setting, streams, 1.0);
    d.polydisperse = true;
    d.radiusLow = setting.polyRadiusLow;
    d.radiusHigh = setting.polyRadiusHigh;
    d.parcelMass = setting.polyParcelMass();
    return d;
}

FiberCircle fiberOf(const PaperSetting& setting, double radius)
{
    FiberCircle f;
    f.x = setting.fiberX;
    f.y = setting.fiberY;
    f.radius = radius;
    return f;
}

double analyticCollisionMass(const SprayStreams& spray, const FiberCircle& fiber)
{
    const double width = 2.0 * spray.definition().injectionHalfWidth;
    return spray.massPerStep() * 2.0 * (fiber.radius + spray.meanRadiusMass()) / width;
}

GridMethod paperGridMethod(const PaperSetting& setting, int nodes, int window)
{
    GridMethod m;
    m.label = gridColumn(nodes, "paper");
    m.nodes = nodes;
    m.kernel.beta = setting.beta;
    m.window = window;
    m.eq9.sampling = Eq9Sampling::Outline;
    m.eq9.outlineSegments = setting.outlineSegments;
    m.eq9.radiusAverage = RadiusAverage::Mass;
    return m;
}

GridMethod improvedGridMethod(const PaperSetting& setting, int nodes, int window)
{
    GridMethod m = paperGridMethod(setting, nodes, window);
    m.label = gridColumn(nodes, "improved");
    m.cloudInCellBelow = 0.5;
    return m;
}

double formulaFromCount(const PaperSetting& setting, const SprayStreams& spray, const FiberCircle& fiber,
                        RadiusAverage average)
{
    const MeasuredField field = measureField(spray, setting.depth, -setting.injectionHalfWidth,
                                             setting.injectionHalfWidth, 0.01, 0.06, formulaSteps);
    const double meanRadius = average == RadiusAverage::Mass ? field.rMeanMass : field.rMeanNumber;
    return formulaCollisionMass(field.rho, meanRadius, fiber, setting.depth, setting.speed * downward,
                                setting.dt);
}

namespace
{
// The methods every figure shares, appended to `values` in the order of `referenceColumns`.
const std::vector<std::string> referenceColumns{"truth",    "formula", "geometric", "spread",
                                                "spreadSE", "fine",    "fineSE"};

// fineSteps: steps per seed of the fine reference (0: as many as the spread count).
void addReferences(const PaperSetting& setting, const SprayDefinition& spray, const FiberCircle& fiber,
                   std::vector<double>& values, int fineSteps = 0)
{
    const SprayStreams streams(spray);
    values.push_back(analyticCollisionMass(streams, fiber));
    values.push_back(formulaFromCount(setting, streams, fiber, RadiusAverage::Mass));
    values.push_back(
        geometricMass(spray, fiber, DropletPlacement::ParcelPoint, 1, setting.spreadStepsPerSeed).mean);
    const MeanAndError spread = geometricMass(spray, fiber, DropletPlacement::Spread, setting.spreadSeeds,
                                              setting.spreadStepsPerSeed);
    values.push_back(spread.mean);
    values.push_back(spread.standardError);
    SprayDefinition jittered = spray;
    jittered.jitter = true;
    const MeanAndError fine = fineSteps > 0
        ? geometricMass(jittered, fiber, DropletPlacement::Spread, setting.fineSeeds, fineSteps)
        : geometricMass(jittered, fiber, DropletPlacement::Spread, setting.spreadSeeds,
                        setting.spreadStepsPerSeed);
    values.push_back(fine.mean);
    values.push_back(fine.standardError);
}

void addGrids(const PaperSetting& setting, const SprayDefinition& spray, const FiberCircle& fiber,
              const std::vector<GridMethod>& methods, std::vector<double>& values)
{
    for (const GridMethod& m : methods)
    {
        values.push_back(runGridMethod(setting, spray, fiber, m).mass);
    }
}

std::vector<std::string> columnsWith(std::vector<std::string> first, const std::vector<GridMethod>& methods)
{
    for (const std::string& c : referenceColumns)
    {
        first.push_back(c);
    }
    for (const GridMethod& m : methods)
    {
        first.push_back(m.label);
    }
    return first;
}
} // namespace

Table figure7(const PaperSetting& setting)
{
    std::vector<GridMethod> methods;
    for (int nodes : setting.fig7Grids)
    {
        methods.push_back(paperGridMethod(setting, nodes));
    }
    for (int nodes : setting.fig7Grids)
    {
        methods.push_back(improvedGridMethod(setting, nodes));
    }
    methods.push_back(paperGridMethod(setting, 250));
    methods.push_back(improvedGridMethod(setting, 250));
    Table t;
    t.name = "figure7";
    t.columns = columnsWith({"streams", "dropletsPerParcel"}, methods);
    const FiberCircle fiber = fiberOf(setting, setting.fiberRadius);
    for (int streams : setting.fig7Streams)
    {
        const double n = setting.fig7DropletsPerStep / streams;
        const SprayDefinition spray = monodisperseSpray(setting, streams, n);
        std::vector<double> values{static_cast<double>(streams), n};
        addReferences(setting, spray, fiber, values);
        addGrids(setting, spray, fiber, methods, values);
        t.add(std::to_string(streams) + " streams", values);
    }
    return t;
}

Table figure8(const PaperSetting& setting)
{
    const std::vector<GridMethod> methods{paperGridMethod(setting, setting.fig8Grid),
                                          improvedGridMethod(setting, setting.fig8Grid),
                                          paperGridMethod(setting, 250), improvedGridMethod(setting, 250)};
    Table t;
    t.name = "figure8";
    t.columns = columnsWith({"streams", "dropletsPerParcel"}, methods);
    const FiberCircle fiber = fiberOf(setting, setting.fiberRadius);
    for (double n : setting.fig8DropletsPerParcel)
    {
        const SprayDefinition spray = monodisperseSpray(setting, setting.fig8Streams, n);
        std::vector<double> values{static_cast<double>(setting.fig8Streams), n};
        addReferences(setting, spray, fiber, values);
        addGrids(setting, spray, fiber, methods, values);
        t.add(std::to_string(static_cast<int>(n)) + " per parcel", values);
    }
    return t;
}

namespace
{
// fineSteps: steps per seed of the fine reference (thin fibers catch few streams: noisy).
Table fiberRadiusSweep(const PaperSetting& setting, const std::string& name, const std::vector<double>& radii,
                       const std::vector<GridMethod>& methods, bool numberColumns, int fineSteps)
{
    Table t;
    t.name = name;
    std::vector<std::string> first{"fiberRadius"};
    t.columns = columnsWith(first, methods);
    if (numberColumns)
    {
        t.columns.push_back("formulaNumber");
        t.columns.push_back(methods.back().label + "_number");
    }
    const SprayDefinition spray = polydisperseSpray(setting, setting.fig9Streams);
    const SprayStreams streams(spray);
    for (double radius : radii)
    {
        const FiberCircle fiber = fiberOf(setting, radius);
        std::vector<double> values{radius};
        addReferences(setting, spray, fiber, values, fineSteps);
        addGrids(setting, spray, fiber, methods, values);
        if (numberColumns)
        {
            values.push_back(formulaFromCount(setting, streams, fiber, RadiusAverage::Number));
            GridMethod number = methods.back();
            number.eq9.radiusAverage = RadiusAverage::Number;
            values.push_back(runGridMethod(setting, spray, fiber, number).mass);
        }
        char label[32];
        std::snprintf(label, sizeof label, "r_F %.4g mm", radius * 1e3);
        t.add(label, values);
    }
    return t;
}
} // namespace

Table figure9(const PaperSetting& setting)
{
    return fiberRadiusSweep(setting, "figure9", setting.fig9FiberRadii,
                            {paperGridMethod(setting, setting.fig9Grid, polyWindow),
                             improvedGridMethod(setting, setting.fig9Grid, polyWindow)},
                            true, setting.fineSteps / 20);
}

Table figure10(const PaperSetting& setting)
{
    std::vector<GridMethod> methods;
    for (int nodes : setting.fig10Grids)
    {
        methods.push_back(paperGridMethod(setting, nodes, polyWindow));
    }
    for (int nodes : setting.fig10Grids)
    {
        methods.push_back(improvedGridMethod(setting, nodes, polyWindow));
    }
    return fiberRadiusSweep(setting, "figure10", setting.fig10FiberRadii, methods, false, 0);
}

Table radiusStudy(const PaperSetting& setting)
{
    Table t;
    t.name = "radius";
    t.columns = {"fiberRadius", "fine",       "fineSE",    "formulaMass", "formulaNumber",
                 "gridMass",    "gridNumber", "rMeanMass", "rMeanNumber", "fineSteps"};
    const SprayDefinition spray = polydisperseSpray(setting, setting.fig9Streams);
    const SprayStreams streams(spray);
    const double rho = streams.analyticDensity(setting.depth);
    const double rMass = streams.meanRadiusMass(), rNumber = streams.meanRadiusNumber();
    SprayDefinition jittered = spray;
    jittered.jitter = true;
    for (double radius : setting.radiusStudyFiberRadii)
    {
        const FiberCircle fiber = fiberOf(setting, radius);
        // The fine reference: many steps, so that its standard error is small.
        // Thicker fibers catch more streams per step (smaller relative noise per step) and
        // cost more per step: fewer steps for them.
        const int steps = std::max(setting.fineSteps / 20,
                                   static_cast<int>(setting.fineSteps * std::min(1.0, 1e-4 / radius)));
        const MeanAndError fine
            = geometricMass(jittered, fiber, DropletPlacement::Spread, setting.fineSeeds, steps);
        const Eigen::Vector3d velocity = setting.speed * downward;
        GridMethod grid = improvedGridMethod(setting, setting.fig9Grid, polyWindow);
        const double gridMass = runGridMethod(setting, spray, fiber, grid).mass;
        grid.eq9.radiusAverage = RadiusAverage::Number;
        const double gridNumber = runGridMethod(setting, spray, fiber, grid).mass;
        t.add("r_F " + std::to_string(radius * 1e6) + " um",
              {radius, fine.mean, fine.standardError,
               formulaCollisionMass(rho, rMass, fiber, setting.depth, velocity, setting.dt),
               formulaCollisionMass(rho, rNumber, fiber, setting.depth, velocity, setting.dt), gridMass,
               gridNumber, rMass, rNumber, static_cast<double>(steps) * setting.fineSeeds});
    }
    return t;
}

Table geometricSawtooth(const PaperSetting& setting)
{
    Table t;
    t.name = "sawtooth";
    t.columns = {"fiberRadius", "truth", "geometric", "grid100_paper", "grid100_improved"};
    const SprayDefinition spray = monodisperseSpray(setting, setting.fig8Streams, 10.0);
    const SprayStreams streams(spray);
    for (double radius : setting.sawtoothFiberRadii())
    {
        const FiberCircle fiber = fiberOf(setting, radius);
        t.add("r_F " + std::to_string(radius * 1e3) + " mm",
              {radius, analyticCollisionMass(streams, fiber),
               geometricMass(spray, fiber, DropletPlacement::ParcelPoint, 1, setting.spreadStepsPerSeed).mean,
               runGridMethod(setting, spray, fiber, paperGridMethod(setting, 100)).mass,
               runGridMethod(setting, spray, fiber, improvedGridMethod(setting, 100)).mass});
    }
    return t;
}

Table accuracyStudy(const PaperSetting& setting)
{
    Table t;
    t.name = "accuracy";
    t.columns = {"figure", "x", "relativeError"};
    const FiberCircle fiber = fiberOf(setting, setting.fiberRadius);
    const int nodes = 100;

    struct Variant
    {
        std::string label;
        GridMethod method;
    };
    std::vector<Variant> variants;
    auto add = [&](const std::string& label, GridMethod m) { variants.push_back({label, m}); };
    add("paper", paperGridMethod(setting, nodes));
    GridMethod axis = paperGridMethod(setting, nodes);
    axis.eq9.sampling = Eq9Sampling::Axis;
    add("paper, eq. 9 at the axis only", axis);
    for (double beta : {0.1, 0.3, 1.0})
    {
        GridMethod m = paperGridMethod(setting, nodes);
        m.kernel.beta = beta;
        char label[32];
        std::snprintf(label, sizeof label, "beta %.3g", beta);
        add(label, m);
    }
    GridMethod margin = paperGridMethod(setting, nodes);
    margin.margin = 0.005;
    add("paper, grid widened by 5 mm", margin);
    for (double below : {0.25, 0.5, 1.0})
    {
        GridMethod m = paperGridMethod(setting, nodes);
        m.cloudInCellBelow = below;
        char label[64];
        std::snprintf(label, sizeof label, "cloud-in-cell below %.3g h%s", below,
                      below == 0.5 ? " (improved)" : "");
        add(label, m);
    }
    GridMethod improvedAxis = improvedGridMethod(setting, nodes);
    improvedAxis.eq9.sampling = Eq9Sampling::Axis;
    add("improved, eq. 9 at the axis only", improvedAxis);

    for (const Variant& v : variants)
    {
        for (int streams : setting.fig7Streams)
        {
            const SprayDefinition spray
                = monodisperseSpray(setting, streams, setting.fig7DropletsPerStep / streams);
            const double truth = analyticCollisionMass(SprayStreams(spray), fiber);
            t.add(v.label,
                  {7.0, static_cast<double>(streams),
                   runGridMethod(setting, spray, fiber, v.method).mass / truth - 1.0});
        }
        for (double n : setting.fig8DropletsPerParcel)
        {
            const SprayDefinition spray = monodisperseSpray(setting, setting.fig8Streams, n);
            const double truth = analyticCollisionMass(SprayStreams(spray), fiber);
            t.add(v.label, {8.0, n, runGridMethod(setting, spray, fiber, v.method).mass / truth - 1.0});
        }
    }

    // The averaging window: parcels injected every 1.37 steps, so one step's paths leave
    // gaps along each stream that move from step to step; the window averages them out.
    for (int window : {1, 2, 5, 10, 20, 50})
    {
        SprayDefinition spray = monodisperseSpray(setting, setting.fig8Streams, 10.0);
        spray.injectionInterval = 1.37 * setting.dt;
        const double truth = analyticCollisionMass(SprayStreams(spray), fiber);
        const GridMethod m = improvedGridMethod(setting, nodes, window);
        t.add("window, injection every 1.37 steps (improved)",
              {0.0, static_cast<double>(window), runGridMethod(setting, spray, fiber, m).mass / truth - 1.0});
    }
    return t;
}

} // namespace validation
} // namespace dropletFiber
