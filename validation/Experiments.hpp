// Experiments: the paper's evaluations (sec. 6, figures 7-10), the radius question (which
// mean radius eq. 9 needs for a polydisperse spray) and the accuracy study of the grid
// method. Each returns a Table of masses hitting the fiber per step (kg), one column per
// method:
//   truth         expected mass from the flow rate alone (analyticCollisionMass)
//   formula       eq. 9 with the droplet density and mean radius counted in the domain
//   geometric     count of droplets entering the fiber, all droplets at the parcel's position
//   spread        the same with each parcel's droplets spread within r_min (mean +- SE over seeds)
//   fine          spread and jittered injection: samples the uniform spray the streams
//                 stand for (mean +- SE over seeds)
//   grid<N>_paper     density grid N x N, the paper's deposit (kernel of eqs. 12-18, beta 0.025)
//   grid<N>_improved  the same with cloud-in-cell deposit for kernels the grid cannot
//                     resolve (GridMethod::cloudInCellBelow = 0.5, see accuracyStudy)
// plot.py and report.py turn the tables into the figures and docs/validation.md.
#pragma once

#include "GeometricCount.hpp"
#include "GridMethod.hpp"
#include "PaperSetting.hpp"
#include "SprayStreams.hpp"
#include "Table.hpp"

namespace dropletFiber
{
namespace validation
{

SprayDefinition monodisperseSpray(const PaperSetting& setting, int streams, double dropletsPerParcel);
SprayDefinition polydisperseSpray(const PaperSetting& setting, int streams);
FiberCircle fiberOf(const PaperSetting& setting, double radius);

// Expected mass per step from the flow rate alone: the streams stand for a spray spread
// uniformly over the injection width W; a droplet of radius r hits when its centre passes
// within r_F + r of the fiber's axis, so the fiber catches the fraction 2 (r_F + r) / W of
// the mass of that radius: mass per step * 2 (r_F + r_mass) / W, r_mass the mass-weighted
// mean radius (uniform in r for our equal-mass parcels, so exact).
double analyticCollisionMass(const SprayStreams& spray, const FiberCircle& fiber);

// The paper's grid method and ours (the setting that brings the error below 1 %).
GridMethod paperGridMethod(const PaperSetting& setting, int nodes, int window = 1);
GridMethod improvedGridMethod(const PaperSetting& setting, int nodes, int window = 1);

// Eq. 9 with the field counted in the control area (injection width x [1, 6] cm).
double formulaFromCount(const PaperSetting& setting, const SprayStreams& spray, const FiberCircle& fiber,
                        RadiusAverage average);

Table figure7(const PaperSetting& setting);  // x: streams (fixed flow rate)
Table figure8(const PaperSetting& setting);  // x: droplets per parcel
Table figure9(const PaperSetting& setting);  // x: fiber radius, polydisperse
Table figure10(const PaperSetting& setting); // x: fiber radius up to 14 mm, grids 100 and 250
Table radiusStudy(const PaperSetting& setting);
// The geometric count against the flow-rate expectation as the fiber radius sweeps across
// the stream lattice (100 streams, r_F 9-11 mm): the staircase behind the geometric error.
Table geometricSawtooth(const PaperSetting& setting);
// Relative error of grid variants (beta, sampling, edge margin, deposit rule, window) over
// the sweeps of figures 7 and 8 at 100x100; rows: variant label, figure, x, error.
Table accuracyStudy(const PaperSetting& setting);

} // namespace validation
} // namespace dropletFiber
