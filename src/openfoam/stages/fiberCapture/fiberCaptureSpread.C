/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Spread populations (entry collision.spread, docs/model.md sec. 12): a
    weighted fiber's N - 1 other physical fibers act on the spray spread
    over a kernel that reaches k other computed fibers (P52), on the level
    of the coupling grid whose spacing gives it (P53), instead of on the
    computed fiber's own line (P40). The computed fiber's line asks as one
    fiber; each sample's population adds (N - 1) kappa_s of swept volume on
    its level's nodes, which the grid's blocks prolong onto their nodes
    before the limit; the population's grant is its level's restriction of
    the nodes' grants. A sample's capture, one physical fiber's, is its
    line's and its population's together over N (P51). Unweighted fibers
    (represents 1) have no population: the same arithmetic as without.

\*---------------------------------------------------------------------------*/

#include "fiberCapture.H"
#include "PstreamReduceOps.H"

#include <cmath>

namespace
{
// The centre of a fiber's length and its length
std::pair<Eigen::Vector3d, double> centreAndLength(const ::dropletFiber::Fiber& fiber)
{
    const Eigen::Matrix3Xd& x = fiber.positions();
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double length = 0;
    for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
    {
        const double piece = (x.col(j + 1) - x.col(j)).norm();
        centre += 0.5*piece*(x.col(j) + x.col(j + 1));
        length += piece;
    }
    return {length > 0 ? Eigen::Vector3d(centre/length) : Eigen::Vector3d(x.col(0)), length};
}


// The widest strip c = 2 (r_F + <r>) of a fiber's samples (their q_d sum to c), from
// sample `first` and segment `segment` on
double widestStrip
(
    const std::vector<Eigen::Vector3d>& strips,
    std::size_t first,
    const ::dropletFiber::Fiber& fiber,
    const std::vector<int>& samplesPerSegment,
    std::size_t segment
)
{
    double widest = 0;
    for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
    {
        for (int s = 0; s < samplesPerSegment[segment]; ++s)
        {
            widest = std::max(widest, strips[first++].sum());
        }
        ++segment;
    }
    return widest;
}
}

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::dropletFiber::fiberCapture::spreads(const heldFibers& held) const
{
    return held.weighted && depletion_ && spread_.active;
}


::dropletFiber::LevelTable Foam::dropletFiber::fiberCapture::countFibers
(
    const heldFibers& held,
    couplingGrid& grid,
    std::vector<std::pair<Eigen::Vector3d, double>>& shape,
    parallelStatistics& statistics
)
{
    const ::dropletFiber::GridSpec& spec = grid.spec();
    if (!populations_ || !::dropletFiber::sameLattice(populations_->grid(), spec))
    {
        const scalar h = ::dropletFiber::SpreadPopulations::largestSpacing(spec);
        const int maxRatio =
            spread_.maxSpacing > 0 ? max(1, int(std::floor(spread_.maxSpacing/h + 1e-9))) : 0;
        populations_.reset
        (
            new ::dropletFiber::SpreadPopulations
            (
                spec, spread_.neighbours, maxRatio, spread_.maxClustering
            )
        );
    }
    const ::dropletFiber::SpreadPopulations& levels = *populations_;
    // P52: every computed fiber in the box counted once at its centre
    ::dropletFiber::LevelTerms count(2);
    shape.assign(held.size(), {Eigen::Vector3d::Zero(), 0.0});
    for (std::size_t f = 0; f < held.size(); ++f)
    {
        shape[f] = centreAndLength(held.fibers[f]);
        if (::dropletFiber::insideActiveBox(spec, shape[f].first))
        {
            levels.addLength(shape[f].first, shape[f].second, count);
        }
    }
    return grid.sumLevelTable(levels, count.summed(), false, statistics);
}


void Foam::dropletFiber::fiberCapture::spreadDemand
(
    const heldFibers& held,
    couplingGrid& grid,
    const std::vector<Eigen::Vector3d>& points,
    const std::vector<::dropletFiber::DropletFieldValue>& fields,
    const std::vector<double>& sampleMasses,
    const std::vector<Eigen::Vector3d>& strips,
    const std::vector<int>& samplesPerSegment,
    parallelStatistics& statistics
)
{
    std::vector<std::pair<Eigen::Vector3d, double>> shape;
    const ::dropletFiber::LevelTable counted =
        countFibers(held, grid, shape, statistics);
    const ::dropletFiber::SpreadPopulations& levels = *populations_;
    // P53, P54: each weighted fiber's level, its samples' terms there
    spreadStep_ = spreadStep();
    spreadStep_.populations = populations_.get();
    fiberLevel_.clear();
    spreadOf_.clear();
    spreadPoints_ = points;
    sampleLevel_.assign(points.size(), 0);
    sampleWhy_.assign(points.size(), ::dropletFiber::LevelChoice::Why::thin);
    sampleVolume_.assign(points.size(), 0.0);
    sampleFibers_.assign(points.size(), 1.0);
    ::dropletFiber::LevelTerms terms(2);
    std::size_t next = 0;
    std::size_t segment = 0;
    for (std::size_t f = 0; f < held.size(); ++f)
    {
        const ::dropletFiber::Fiber& fiber = held.fibers[f];
        const scalar N = fiber.represents();
        const std::size_t first = next;
        const ::dropletFiber::LevelChoice choice =
            N > 1
          ? levels.choose
            (
                shape[f].first, shape[f].second, counted,
                (N - 1)*widestStrip(strips, first, fiber, samplesPerSegment, segment)/4
            )
          : ::dropletFiber::LevelChoice();
        if (N > 1)
        {
            fiberLevel_[held.id[f]] = choice.level;
            if (::dropletFiber::insideActiveBox(grid.spec(), shape[f].first))
            {
                spreadOf_[held.id[f]] = levels.levelSpacing(choice.level);
            }
        }
        for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
        {
            for (int s = 0; s < samplesPerSegment[segment]; ++s, ++next)
            {
                sampleFibers_[next] = N;
                if (!(N > 1) || !(sampleMasses[next] > 0) || !(fields[next].rho > 0))
                {
                    continue;
                }
                // The swept volume kappa_s of eq. 9: its mass over the density read
                sampleLevel_[next] = choice.level;
                sampleWhy_[next] = choice.why;
                sampleVolume_[next] = (N - 1)*sampleMasses[next]/fields[next].rho;
                levels.addDemand
                (
                    points[next], choice.level, sampleVolume_[next],
                    strips[next], N, terms
                );
            }
            ++segment;
        }
    }
    spreadStep_.demand = terms.summed();
}


std::vector<double> Foam::dropletFiber::fiberCapture::spreadGranted
(
    const std::vector<double>& lines,
    const std::vector<Eigen::Vector3d>& strips
)
{
    const ::dropletFiber::SpreadPopulations& levels = *populations_;
    const scalar h = levels.levelSpacing(0);
    std::vector<double> granted(lines.size(), 0.0);
    for (std::size_t s = 0; s < lines.size(); ++s)
    {
        if (sampleVolume_[s] > 0)
        {
            const int level = sampleLevel_[s];
            const scalar population =
                sampleVolume_[s]*levels.readLevel(spreadPoints_[s], level, spreadStep_.grants);
            const scalar G = lines[s] + population;
            granted[s] = G/sampleFibers_[s];
            // P57: weighted by the sample's capture
            const scalar H = levels.levelSpacing(level);
            const scalar sigma = H/std::sqrt(3.0)/h;
            const scalar c = strips[s].sum();
            resolution_.captured += G;
            resolution_.sigma += G*sigma;
            using why = ::dropletFiber::LevelChoice::Why;
            resolution_.capped += sampleWhy_[s] == why::capped ? G : 0;
            resolution_.thin += sampleWhy_[s] == why::thin ? G : 0;
            resolution_.eps += G*(sampleFibers_[s] - 1)*c/(4*H);
            resolution_.sigmaMin = min(resolution_.sigmaMin, sigma);
            resolution_.sigmaMax = max(resolution_.sigmaMax, sigma);
        }
        else
        {
            granted[s] = lines[s];
        }
    }
    return granted;
}


void Foam::dropletFiber::fiberCapture::spreadRealised
(
    const std::vector<double>& ratios
)
{
    if (!spreadStep_.populations)
    {
        return;
    }
    ::dropletFiber::LevelTerms terms(1);
    for (std::size_t s = 0; s < ratios.size(); ++s)
    {
        if (sampleVolume_[s] > 0 && ratios[s] > 0)
        {
            populations_->addAtLevel
            (
                spreadPoints_[s], sampleLevel_[s], ratios[s]*sampleVolume_[s],
                terms
            );
        }
    }
    spreadStep_.realised = terms.summed();
}


void Foam::dropletFiber::fiberCapture::spreadCut
(
    const std::vector<double>& ratios,
    std::vector<double>& cut
) const
{
    if (cut.empty() || !spreadStep_.populations)
    {
        return;
    }
    for (std::size_t s = 0; s < cut.size(); ++s)
    {
        scalar population = 0;
        if (sampleVolume_[s] > 0 && !spreadStep_.cut.keys.empty())
        {
            population =
                ratios[s]*sampleVolume_[s]
               *populations_->readLevel
                (
                    spreadPoints_[s], sampleLevel_[s], spreadStep_.cut
                );
        }
        cut[s] = (cut[s] + population)/sampleFibers_[s];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberCapture::handPopulations
(
    airReaction& reaction
) const
{
    if (spreadStep_.populations)
    {
        reaction.spreadLike(populations_.get(), fiberLevel_);
        return;
    }
    reaction.spreadLike(nullptr, {});
}


void Foam::dropletFiber::fiberCapture::reportSpread()
{
    List<scalar> sums(5, Zero);
    sums[0] = resolution_.captured;
    sums[1] = resolution_.sigma;
    sums[2] = resolution_.capped;
    sums[3] = resolution_.thin;
    sums[4] = resolution_.eps;
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);
    const scalar sigmaMin = returnReduce(resolution_.sigmaMin, minOp<scalar>());
    const scalar sigmaMax = returnReduce(resolution_.sigmaMax, maxOp<scalar>());
    resolution_ = spreadResolution();
    if (!(sums[0] > 0))
    {
        return;
    }
    const scalar capped = sums[2]/sums[0];
    const scalar eps = sums[4]/sums[0];
    const scalar thin = sums[3]/sums[0];
    Info<< type() << " " << name() << " spread populations at time "
        << time_.timeName() << " (docs/model.md sec. 12, P57; shares of"
        << " their capture since the last write):" << nl
        << "    kernel sigma / h " << sums[1]/sums[0] << " (" << sigmaMin
        << " to " << sigmaMax << "); thin on their level " << thin
        << ", reaching " << spread_.neighbours << " other computed fibers "
        << 1 - thin - capped << ", capped " << capped << "; clustering eps "
        << eps << nl << endl;
    if (capped > 0.05 && !warnedHoles_)
    {
        warnedHoles_ = true;
        WarningInFunction
            << type() << " " << name() << ": at time " << time_.timeName()
            << " " << capped << " of the weighted fibers' capture comes from"
            << " populations whose kernel reached fewer than "
            << spread_.neighbours << " other computed fibers on the coarsest"
            << " level: the capture is set by holes in the veil. More computed"
            << " fibers per second, or a larger collision.spread.maxSpacing"
            << " (warned once; the write times' lines give the share)." << endl;
    }
    if (eps > 0.25 && !warnedOpaque_)
    {
        warnedOpaque_ = true;
        WarningInFunction
            << type() << " " << name() << ": at time " << time_.timeName()
            << " the populations are opaque on their levels (clustering eps "
            << eps << " > 0.25): the capture may be low by up to eps where"
            << " the veil is thin (docs/model.md sec. 12, P55; warned once)."
            << endl;
    }
}


// ************************************************************************* //
