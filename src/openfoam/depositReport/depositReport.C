/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "depositReport.H"
#include "Pstream.H"
#include "List.H"
#include "ops.H"
#include "messageStream.H"
#include "error.H"
#include "OStringStream.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The largest node spacing of the active directions: the unit of the
//  deposit's widest-kernel figures (DensityGrid's largestSpacing)
Foam::scalar largestSpacing(const ::dropletFiber::GridSpec& spec)
{
    Foam::scalar largest = 0;
    for (int d = 0; d < 3; ++d)
    {
        largest = spec.flat(d) ? largest : Foam::max(largest, spec.spacing(d));
    }
    return largest;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::depositReport::depositReport
(
    const word& owner,
    const ::dropletFiber::GridSpec& spec,
    const ::dropletFiber::KernelSettings& kernel
)
:
    owner_(owner),
    kernel_(kernel),
    activeDimensions_(spec.activeDimensions()),
    spacing_(largestSpacing(spec)),
    since_(),
    untilWarned_(),
    lastStep_(),
    timing_(false),
    warned_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::depositReport::record
(
    const ::dropletFiber::StepStatistics& deposit,
    const scalar depositTime,
    const word& timeName
)
{
    // The wall time of a step: from this call to the next (the same point of
    // every step); the first step is not timed
    const auto now = std::chrono::steady_clock::now();
    const scalar stepTime =
        timing_ ? std::chrono::duration<double>(now - lastStep_).count() : 0;
    add(since_, deposit, stepTime, timing_ ? depositTime : 0);
    if (!warned_)
    {
        add(untilWarned_, deposit, stepTime, timing_ ? depositTime : 0);
    }
    lastStep_ = now;
    timing_ = true;

    // One scalar reduction per step decides for all processors
    if (warned_)
    {
        return;
    }
    const interval& run = untilWarned_;
    const scalar share = run.stepTime > 0 ? run.depositTime/run.stepTime : 0;
    const bool large =
        returnReduce(share, maxOp<scalar>()) > largeShare
     && run.steps >= minSteps
     && run.stepTime >= minWallTime;
    if (!large)
    {
        return;
    }
    warn(timeName);
    warned_ = true;
}


void Foam::dropletFiber::depositReport::warn(const word& timeName) const
{
    const interval all = overProcessors(untilWarned_);
    OStringStream text;
    text.precision(3);
    text<< owner_ << ": the deposit of the parcels takes "
        << label(100*all.depositTime/all.stepTime + 0.5)
        << " % of the wall time (" << all.steps << " steps to time "
        << timeName << "; reported above " << label(100*largeShare)
        << " %)" << nl;
    writeFigures(text, all);
    writeAdvice(text, all);
    text<< "    (warned once; the figures are given again at write times)";
    WarningInFunction << text.str().c_str() << endl;
}


void Foam::dropletFiber::depositReport::reportAtWrite(const word& timeName)
{
    const interval all = overProcessors(since_);
    if (all.steps > 0)
    {
        const scalar share = all.depositTime/all.stepTime;
        OStringStream text;
        text.precision(3);
        text<< owner_ << ": deposit " << label(100*share + 0.5)
            << " % of the wall time over " << all.steps
            << " steps to time " << timeName << nl;
        writeFigures(text, all);
        if (share > largeShare)
        {
            writeAdvice(text, all);
        }
        Info<< text.str().c_str();
    }
    since_ = interval();
}


void Foam::dropletFiber::depositReport::add
(
    interval& to,
    const ::dropletFiber::StepStatistics& deposit,
    const scalar stepTime,
    const scalar depositTime
)
{
    // The first step is not timed (stepTime 0): its counts are kept
    if (stepTime > 0)
    {
        to.stepTime += stepTime;
        to.depositTime += depositTime;
        ++to.steps;
    }
    to.widestWidth = max(to.widestWidth, deposit.widestKernelWidth);
    to.widestReach = max(to.widestReach, deposit.widestKernelReach);
    to.nodesVisited += scalar(deposit.nodesVisited);
    to.parcelsOnGrid +=
        scalar(deposit.parcels - deposit.parcelsEmpty - deposit.parcelsOutside);
}


Foam::dropletFiber::depositReport::interval
Foam::dropletFiber::depositReport::overProcessors(const interval& mine)
{
    List<scalar> sums(2);
    sums[0] = mine.nodesVisited;
    sums[1] = mine.parcelsOnGrid;
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);
    List<scalar> maxima(4);
    maxima[0] = mine.widestWidth;
    maxima[1] = mine.widestReach;
    maxima[2] = mine.stepTime > 0 ? mine.depositTime/mine.stepTime : 0;
    maxima[3] = mine.stepTime;
    Pstream::listCombineGather(maxima, maxEqOp<scalar>());
    Pstream::listCombineScatter(maxima);

    interval all = mine;
    all.nodesVisited = sums[0];
    all.parcelsOnGrid = sums[1];
    all.widestWidth = maxima[0];
    all.widestReach = maxima[1];
    // The largest share of any processor, on the longest step time
    all.stepTime = maxima[3];
    all.depositTime = maxima[2]*maxima[3];
    return all;
}


void Foam::dropletFiber::depositReport::writeFigures
(
    Ostream& os,
    const interval& all
) const
{
    const scalar perParcel =
        all.parcelsOnGrid > 0 ? all.nodesVisited/all.parcelsOnGrid : 0;
    const scalar parcelsPerStep = all.parcelsOnGrid/max(all.steps, label(1));
    if (all.widestWidth > 0)
    {
        os  << "    widest kernel: width " << all.widestWidth
            << " node spacings (eq. 16), reach " << all.widestReach
            << " spacings (node spacing " << spacing_ << " m); ";
    }
    else
    {
        os  << "    every parcel with cloud-in-cell weights (cloudInCellBelow); ";
    }
    os  << label(perParcel + 0.5) << " nodes visited per parcel on the grid ("
        << label(parcelsPerStep + 0.5) << " parcels per step)" << nl;
}


void Foam::dropletFiber::depositReport::writeAdvice
(
    Ostream& os,
    const interval& all
) const
{
    // Nodes per parcel ~ (2 reach / h)^D: what each setting does to them
    const scalar D = scalar(activeDimensions_);
    if (!(all.widestWidth > 0))
    {
        // Cloud-in-cell: 2^D corners per point of a parcel's path, whatever
        // the kernel entries; only fewer parcels or points cost less
        os  << "    every parcel was deposited cloud-in-cell (its kernel"
            << " narrower than grid.cloudInCellBelow " << kernel_.cloudInCellBelow
            << " node spacings): " << std::pow(2.0, D) << " corners per point"
            << " of its path; the kernel entries (rMaxCap, negligibleWeight,"
            << " cloudInCellBelow) cannot lower that cost, and a coarser"
            << " grid.spacing only shortens the paths in node spacings. The"
            << " cost follows the number of parcels (the clouds' injection)."
            << nl;
        return;
    }
    os  << "    settings that would help (docs/model.md sec. 4, cost of wide"
        << " kernels):" << nl
        << "      grid.spacing " << 2*spacing_ << " (twice the present): about "
        << std::pow(2.0, D) << "x fewer nodes per kernel-deposited parcel; a"
        << " coarser density field for the collision" << nl;
    const scalar epsilon = kernel_.negligibleWeight;
    if (epsilon > 0 && epsilon < 1e-8)
    {
        // The cut reach grows as sqrt(-ln negligibleWeight) (P10)
        const scalar shorter = std::sqrt(std::log(1e8)/(-std::log(epsilon)));
        os  << "      grid.negligibleWeight 1e-8 (now " << epsilon
            << "): reach about " << shorter << " of the present where the cut"
            << " binds, about " << std::pow(1/shorter, D)
            << "x fewer nodes; node weights below 1e-8 of a parcel's largest"
            << " left out (mass kept)" << nl;
    }
    writeCapAndCloudInCellAdvice(os, all);
}


void Foam::dropletFiber::depositReport::writeCapAndCloudInCellAdvice
(
    Ostream& os,
    const interval& all
) const
{
    const scalar D = scalar(activeDimensions_);
    const scalar capReach = 3*all.widestWidth;
    if (!(kernel_.rMaxCap > 0) && all.widestReach > capReach)
    {
        os  << "      grid.rMaxCap " << capReach*spacing_
            << " (3 widths of the widest kernel): about "
            << std::pow(all.widestReach/capReach, D)
            << "x fewer nodes for it; but it cuts the kernel's support and"
            << " moves its mass inwards: density +10 % at the centre, a fiber"
            << " passing at 3 widths captures 58-95 % less (docs/model.md"
            << " sec. 4)" << nl;
    }
    if (all.widestWidth < 2 && all.widestWidth >= kernel_.cloudInCellBelow)
    {
        // cloudInCellBelow c: kernels narrower than c spacings go to their
        // cell corners; 0 keeps the paper's kernel for every parcel
        const scalar above = 1.01*all.widestWidth;
        os  << "      grid.cloudInCellBelow " << above << " (now "
            << kernel_.cloudInCellBelow << "; 0 = the paper's kernel for"
            << " every parcel): the parcels whose kernel is narrower than "
            << above << " node spacings, the widest of this run included,"
            << " go to their cell corners (2^D nodes per point of the path);"
            << " kernels of that width are then not resolved" << nl;
    }
}


// ************************************************************************* //
