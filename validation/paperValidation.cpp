// paperValidation: runs the validation experiments (Experiments.hpp) and writes one CSV per
// experiment, plus setting.csv (the physical values used), into the output directory.
//
//     paperValidation [--reduced] [--out DIR] [--only figure7,figure8,...]
//
// --reduced: fewer sweep points and seeds (PaperSetting::reduced), for a quick look.
// Experiments: figure7 figure8 figure9 figure10 radius sawtooth accuracy (default: all).
#include "Experiments.hpp"

#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <sys/stat.h>

using namespace dropletFiber::validation;

namespace
{
void usage()
{
    std::cerr << "usage: paperValidation [--reduced] [--out DIR] [--only "
                 "figure7,figure8,figure9,figure10,radius,sawtooth,accuracy]\n";
}

Table settingTable(const PaperSetting& s, bool reduced)
{
    Table t;
    t.name = "setting";
    t.columns = {"value"};
    auto add = [&](const std::string& name, double v) { t.add(name, {v}); };
    add("reduced", reduced ? 1.0 : 0.0);
    add("xMin_m", s.xMin);
    add("xMax_m", s.xMax);
    add("yMin_m", s.yMin);
    add("yMax_m", s.yMax);
    add("injectionHalfWidth_m", s.injectionHalfWidth);
    add("fiberX_m", s.fiberX);
    add("fiberY_m", s.fiberY);
    add("fiberRadius_m", s.fiberRadius);
    add("depth_m", s.depth);
    add("dropletRadius_m", s.dropletRadius);
    add("dropletDensity_kg_m3", s.dropletDensity);
    add("speed_m_s", s.speed);
    add("dt_s", s.dt);
    add("injectionInterval_s", s.injectionInterval);
    add("injectionPhase", s.injectionPhase);
    add("outlineSegments", s.outlineSegments);
    add("beta", s.beta);
    add("fig7DropletsPerStep", s.fig7DropletsPerStep);
    add("fig8Streams", s.fig8Streams);
    add("fig9Streams", s.fig9Streams);
    add("polyRadiusLow_m", s.polyRadiusLow);
    add("polyRadiusHigh_m", s.polyRadiusHigh);
    add("polyParcelMass_kg", s.polyParcelMass());
    add("spreadSeeds", s.spreadSeeds);
    add("spreadStepsPerSeed", s.spreadStepsPerSeed);
    add("fineSeeds", s.fineSeeds);
    add("fineSteps", s.fineSteps);
    return t;
}
} // namespace

int main(int argc, char** argv)
{
    bool reduced = false;
    std::string out = "validation-output";
    std::set<std::string> only;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--reduced")
        {
            reduced = true;
        }
        else if (arg == "--out" && i + 1 < argc)
        {
            out = argv[++i];
        }
        else if (arg == "--only" && i + 1 < argc)
        {
            std::stringstream list(argv[++i]);
            std::string item;
            while (std::getline(list, item, ','))
            {
                only.insert(item);
            }
        }
        else
        {
            usage();
            return 2;
        }
    }
    mkdir(out.c_str(), 0755);
    const PaperSetting setting = reduced ? PaperSetting::reduced() : PaperSetting{};
    settingTable(setting, reduced).write(out);

    const std::vector<std::pair<std::string, std::function<Table(const PaperSetting&)>>> experiments{
        {"figure7", figure7},       {"figure8", figure8},    {"figure9", figure9},
        {"figure10", figure10},     {"radius", radiusStudy}, {"sawtooth", geometricSawtooth},
        {"accuracy", accuracyStudy}};
    try
    {
        for (const auto& [name, run] : experiments)
        {
            if (!only.empty() && only.count(name) == 0)
            {
                continue;
            }
            const auto start = std::chrono::steady_clock::now();
            const Table table = run(setting);
            table.write(out);
            const double seconds
                = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            std::printf("%-10s %3zu rows  %7.1f s  -> %s/%s.csv\n", name.c_str(), table.rows.size(), seconds,
                        out.c_str(), table.name.c_str());
            std::fflush(stdout);
        }
    }
    catch (const std::exception& e)
    {
        std::cerr << "paperValidation: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
