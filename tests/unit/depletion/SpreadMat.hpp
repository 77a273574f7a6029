// Test helper (not a test file): one steady step of a uniform spray crossing a random mat of
// M fixed fibers of weight N (docs/model.md sec. 12, the validation case), on a 2D grid:
// fibers along z (the flat direction, length T), straight across a spray in +y; lanes of
// parcels at x = (j / 4 + 1 / 8) h, one parcel every half spacing along y, deposited
// cloud-in-cell, a window of one step. A node's optical depth is the fibers' swept volume
// over its volume (P13), whatever the spray's density, so one step gives the steady
// penetration: each lane keeps prod_k (1 - c_pk) of its parcels' droplets over the mat.
// With spread populations (SpreadPopulations.hpp) the computed fiber's line asks as one
// fiber and its N - 1 as a population on its level; without, P40's N interceptors.
#pragma once

#include "depletion/CaptureLimit.hpp"
#include "depletion/SelfShadow.hpp"
#include "depletion/SpreadPopulations.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace dropletFiber
{
namespace test
{

struct SpreadMatResult
{
    double penetration = 0.0; // mean over the lanes of prod (1 - c_p)
    double theory = 0.0;      // exp(-S), S = M N c / W
    double captured = 0.0;    // the fibers' granted mass (lines and populations), kg
    double removed = 0.0;     // sum c_p m_p, kg
    double meanRatio = 0.0;   // the populations' mean H / h (0 without)
    int capped = 0;           // populations that reached no level's k
};

struct SpreadMat
{
    double width = 0.75, height = 1.0;      // the box, m
    double slabLow = 0.25, slabHigh = 0.75; // the mat's extent in y, m
    double h = 1.0 / 32.0;
    double strip = 1e-4; // c = 2 (r_F + r_p), m
    double dropletRadius = 1e-5;
    double S = 1.0;
    double weight = 10.0; // N
    bool spread = true;
    double neighbours = 8.0;
    double maxClustering = 0.05;

    GridSpec grid() const
    {
        GridSpec s;
        s.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
        s.upper = Eigen::Vector3d(width, height, h);
        s.nodes = {
            {static_cast<int>(std::lround(width / h)) + 1, static_cast<int>(std::lround(height / h)) + 1, 1}};
        return s;
    }

    int fiberCount() const { return static_cast<int>(std::lround(S * width / (weight * strip))); }

    SpreadMatResult run(unsigned seed) const
    {
        const GridSpec spec = grid();
        const double speed = 1.0, dt = 0.5 * h / speed, thickness = h;
        const double fiberRadius = 0.5 * strip - dropletRadius;
        KernelSettings settings;
        settings.cloudInCellBelow = 0.5;
        DensityGrid density(spec, settings, 1);
        std::vector<Parcel> parcels;
        const int lanes = 4 * static_cast<int>(std::lround(width / h));
        const int perLane = static_cast<int>(std::lround(height / (speed * dt)));
        for (int j = 0; j < lanes; ++j)
        {
            for (int k = 0; k < perLane; ++k)
            {
                Parcel p;
                p.position = Eigen::Vector3d((0.25 * j + 0.125) * h, (k + 0.5) * speed * dt, 0.5 * h);
                p.velocity = Eigen::Vector3d(0.0, speed, 0.0);
                p.diameter = 2.0 * dropletRadius;
                p.nParticle = 100.0;
                p.rhoDroplet = 1000.0;
                parcels.push_back(p);
                density.deposit(p, dt);
            }
        }
        density.commitStep();

        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::vector<Eigen::Vector3d> centres;
        for (int f = 0; f < fiberCount(); ++f)
        {
            centres.emplace_back(width * unit(rng), slabLow + (slabHigh - slabLow) * unit(rng),
                                 0.5 * thickness);
        }
        CaptureLimit limit;
        std::vector<SegmentCapture> lines;
        const bool populations = spread && weight > 1.0;
        for (const Eigen::Vector3d& c : centres)
        {
            const Eigen::Vector3d a(c.x(), c.y(), 0.0), b(c.x(), c.y(), thickness);
            lines.push_back(segmentCapture(density, a, b, fiberRadius, Eigen::Vector3d::Zero(), dt));
            limit.addDemand(lines.back(), populations ? 1.0 : weight);
        }
        SpreadMatResult result;
        const SpreadPopulations spreads(spec, neighbours, 0, maxClustering);
        LevelTable demand;
        std::vector<LevelChoice> choices;
        // The swept volume of one fiber over the step, its strip across the flow
        const double kappa = strip * thickness * speed * dt;
        const Eigen::Vector3d q
            = stripAcrossFlow(strip, Eigen::Vector3d(0.0, 0.0, thickness), Eigen::Vector3d(0.0, speed, 0.0));
        if (populations)
        {
            LevelTerms count(2), terms(2);
            for (const Eigen::Vector3d& c : centres)
            {
                spreads.addLength(c, thickness, count);
            }
            const LevelTable counted = count.summed();
            for (const Eigen::Vector3d& c : centres)
            {
                choices.push_back(spreads.choose(c, thickness, counted, (weight - 1.0) * strip / 4.0));
                spreads.addDemand(c, choices.back().level, (weight - 1.0) * kappa, q, weight, terms);
                result.meanRatio += spreads.level(choices.back().level).ratio() / double(centres.size());
                result.capped += choices.back().why == LevelChoice::Why::capped ? 1 : 0;
            }
            demand = terms.summed();
            std::vector<double> share, depth;
            spreads.prolongOnto(demand, wholeBox(spec.nodes), share, depth);
            for (std::size_t n = 0; n < share.size(); ++n)
            {
                if (share[n] > 0.0)
                {
                    limit.addSpread(n, share[n], depth[n]);
                }
            }
        }
        limit.limit(density);
        CaptureLimitReport report;
        const std::vector<double> fraction = limit.removeFromParcels(density, parcels, dt, report);
        // Penetration per lane
        for (int j = 0; j < lanes; ++j)
        {
            double kept = 1.0;
            for (int k = 0; k < perLane; ++k)
            {
                kept *= 1.0 - fraction[static_cast<std::size_t>(j * perLane + k)];
            }
            result.penetration += kept / lanes;
        }
        for (std::size_t p = 0; p < parcels.size(); ++p)
        {
            result.removed += fraction[p] * parcelMass(parcels[p]);
        }
        // The fibers' grants: lines (N each without populations), populations on their level
        std::vector<double> supplies;
        limit.grantedSupplies(wholeBox(spec.nodes), false, supplies);
        const LevelTable grants = spreads.restrictFrom(demand, wholeBox(spec.nodes), supplies);
        for (std::size_t f = 0; f < lines.size(); ++f)
        {
            result.captured += (populations ? 1.0 : weight) * limit.granted(lines[f]).mass;
            if (populations)
            {
                result.captured
                    += (weight - 1.0) * kappa * spreads.readLevel(centres[f], choices[f].level, grants);
            }
        }
        result.theory = std::exp(-fiberCount() * weight * strip / width);
        return result;
    }
};

} // namespace test
} // namespace dropletFiber
