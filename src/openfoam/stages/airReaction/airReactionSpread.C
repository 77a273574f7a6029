/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The spread populations' drag on the air (docs/model.md sec. 12, P56): a
    weighted fiber's N points stand for its own line and N - 1 fibers spread
    as its capture is. The line's 1 / N of each point's drag stays in the
    point's cell; the population's (N - 1) / N goes onto its level's nodes
    with the point's multilinear weights, is summed over the processors at
    each level node's owner and sent to the processors whose cells the
    node's hat reaches, and each node gives it to those cells in proportion
    to hat x volume, normalised over all of them (a second sum): the air
    gets exactly what the fibers lose. A level node whose hat holds no cell
    centre gives its part back to the points' cells. Populations on the
    grid's own level stay at their points (the hats are no wider than the
    cells the drag sees). The coefficient of the implicit part likewise.

\*---------------------------------------------------------------------------*/

#include "airReaction.H"
#include "levelSums.H"
#include "PstreamReduceOps.H"
#include "grid/MultilinearWeights.hpp"

#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::airReaction::binCells()
{
    const ::dropletFiber::GridSpec& g = populations_->grid();
    binnedFor_ = g;
    cellsBinned_ = true;
    cellBins_.clear();
    const vectorField& centres = mesh_.C();
    forAll(centres, celli)
    {
        const Eigen::Vector3d x(centres[celli].x(), centres[celli].y(), centres[celli].z());
        if (::dropletFiber::insideActiveBox(g, x))
        {
            const std::array<int, 3> lower =
                ::dropletFiber::multilinearWeights(g, x).lowerCorner;
            cellBins_.emplace_back(g.flatIndex(lower[0], lower[1], lower[2]), celli);
        }
    }
    std::sort(cellBins_.begin(), cellBins_.end());
    // Every processor's cell centres' box, for the level nodes' receivers
    boundBox mine(boundBox::invertedBox);
    for (const auto& bin : cellBins_)
    {
        mine.add(centres[bin.second]);
    }
    cellBoxes_.setSize(Pstream::nProcs());
    cellBoxes_[Pstream::myProcNo()] = mine;
    Pstream::gatherList(cellBoxes_);
    Pstream::scatterList(cellBoxes_);
}


Foam::boundBox Foam::dropletFiber::airReaction::hatBox
(
    const ::dropletFiber::LevelKey key
) const
{
    const ::dropletFiber::SpreadLevel& level =
        populations_->level(::dropletFiber::levelOfKey(key));
    const ::dropletFiber::GridSpec& g = populations_->grid();
    const std::array<int, 3> c =
        ::dropletFiber::nodeIndicesOfFlat
        (
            level.spec().nodes, ::dropletFiber::nodeOfKey(key)
        );
    point lo, hi;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar H = level.spec().spacing(d);
        const scalar at = g.lower[d] + c[d]*H;
        lo[d] = g.flat(d) ? g.lower[d] : at - H;
        hi[d] = g.flat(d) ? g.upper[d] : at + H;
    }
    return boundBox(lo, hi);
}


template<class F>
void Foam::dropletFiber::airReaction::forEachCellInHat
(
    const ::dropletFiber::LevelKey key,
    F&& f
) const
{
    const ::dropletFiber::SpreadLevel& level =
        populations_->level(::dropletFiber::levelOfKey(key));
    const ::dropletFiber::GridSpec& g = populations_->grid();
    const int r = level.ratio();
    const std::array<int, 3> c =
        ::dropletFiber::nodeIndicesOfFlat
        (
            level.spec().nodes, ::dropletFiber::nodeOfKey(key)
        );
    // The grid's cells (by their lower node) that may hold centres in the hat
    std::array<int, 3> lo{}, hi{};
    for (int d = 0; d < 3; ++d)
    {
        lo[d] = g.flat(d) ? 0 : std::max(0, r*(c[d] - 1));
        hi[d] = g.flat(d) ? 0 : std::min(g.nodes[d] - 2, r*(c[d] + 1) - 1);
    }
    const vectorField& centres = mesh_.C();
    const scalarField& V = mesh_.V();
    for (int k = lo[2]; k <= hi[2]; ++k)
    {
        for (int j = lo[1]; j <= hi[1]; ++j)
        {
            const auto first = std::lower_bound
            (
                cellBins_.begin(), cellBins_.end(),
                std::make_pair(g.flatIndex(lo[0], j, k), label(-1))
            );
            const std::size_t last = g.flatIndex(hi[0], j, k);
            for (auto bin = first; bin != cellBins_.end() && bin->first <= last; ++bin)
            {
                const point& x = centres[bin->second];
                scalar hat = 1;
                for (int d = 0; d < 3 && hat > 0; ++d)
                {
                    if (!g.flat(d))
                    {
                        const scalar H = level.spec().spacing(d);
                        hat *= max(0.0, 1 - mag(x[d] - (g.lower[d] + c[d]*H))/H);
                    }
                }
                if (hat > 0)
                {
                    f(bin->second, hat*V[bin->second]);
                }
            }
        }
    }
}


void Foam::dropletFiber::airReaction::spreadPopulationDrag
(
    const dragPointFibers& fibers,
    Eigen::Matrix3Xd& force,
    Eigen::VectorXd& coefficient,
    parallelStatistics& statistics
)
{
    if (!cellsBinned_ || !::dropletFiber::sameLattice(binnedFor_, populations_->grid()))
    {
        binCells();
    }
    // The populations' parts onto their levels' nodes
    std::vector<populationPart> parts;
    ::dropletFiber::LevelTerms terms(4);
    for (Eigen::Index i = 0; i < force.cols(); ++i)
    {
        const auto found = populationLevel_.find(fibers.id[i]);
        const scalar N = fibers.represents[i];
        if (found == populationLevel_.end() || found->second <= 0 || !(N > 1))
        {
            continue;
        }
        populationPart p;
        p.point = i;
        p.level = found->second;
        p.part << (N - 1)/N*force.col(i), (N - 1)/N*coefficient(i);
        force.col(i) -= p.part.head<3>();
        coefficient(i) -= p.part(3);
        const ::dropletFiber::CornerWeights w =
            populations_->level(p.level).weightsAt(fibers.position.col(i));
        for (int c = 0; c < w.count; ++c)
        {
            const Eigen::Vector4d v = w.weight[c]*p.part;
            terms.add(::dropletFiber::levelKey(p.level, w.node[c]), v.data());
        }
        parts.push_back(p);
    }
    spreadOverCells(terms.summed(), parts, fibers, force, coefficient, statistics);
}


void Foam::dropletFiber::airReaction::spreadOverCells
(
    const ::dropletFiber::LevelTable& local,
    const std::vector<populationPart>& parts,
    const dragPointFibers& fibers,
    Eigen::Matrix3Xd& force,
    Eigen::VectorXd& coefficient,
    parallelStatistics& statistics
)
{
    const auto what = parallelStatistics::traffic::fibers;
    const label nProcs = Pstream::nProcs();
    const auto owner = [&](const ::dropletFiber::LevelKey key)
    {
        return label(key % ::dropletFiber::LevelKey(nProcs));
    };
    const auto reached = [&](const ::dropletFiber::LevelKey key, std::vector<int>& to)
    {
        to.clear();
        const boundBox hat = hatBox(key);
        forAll(cellBoxes_, proci)
        {
            if (cellBoxes_[proci].valid() && cellBoxes_[proci].overlaps(hat))
            {
                to.push_back(int(proci));
            }
        }
    };
    const ::dropletFiber::LevelTable sums =
        sumOverProcessors(local, owner, reached, statistics, what);
    // Each node's hat x volume over every processor's cells (the givers
    // ask with a zero term: a node that reaches no cell they keep)
    ::dropletFiber::LevelTerms partial(1);
    for (const ::dropletFiber::LevelKey key : sums.keys)
    {
        scalar sum = 0;
        forEachCellInHat(key, [&](label, scalar w) { sum += w; });
        partial.add(key, sum);
    }
    for (const ::dropletFiber::LevelKey key : local.keys)
    {
        partial.add(key, 0.0);
    }
    const ::dropletFiber::LevelTable norms =
        sumOverProcessors(partial.summed(), owner, nullptr, statistics, what);
    for (std::size_t i = 0; i < sums.keys.size(); ++i)
    {
        const scalar norm = norms.value(sums.keys[i], 0);
        const double* v = sums.values.data() + 4*i;
        if (norm > 0)
        {
            forEachCellInHat
            (
                sums.keys[i],
                [&](const label celli, const scalar w)
                {
                    cellForce_[celli] += vector(v[0], v[1], v[2])*(w/norm);
                    cellCoefficient_[celli] += v[3]*(w/norm);
                }
            );
            spreadOnAir_ += vector(v[0], v[1], v[2]);
        }
    }
    // Parts on nodes that reach no cell: back to their points
    for (const populationPart& p : parts)
    {
        const ::dropletFiber::CornerWeights w =
            populations_->level(p.level).weightsAt(fibers.position.col(p.point));
        for (int c = 0; c < w.count; ++c)
        {
            if (!(norms.value(::dropletFiber::levelKey(p.level, w.node[c]), 0) > 0))
            {
                force.col(p.point) += w.weight[c]*p.part.head<3>();
                coefficient(p.point) += w.weight[c]*p.part(3);
                const Eigen::Vector3d back = w.weight[c]*p.part.head<3>();
                spreadReturned_ += vector(back.x(), back.y(), back.z());
            }
        }
    }
}


void Foam::dropletFiber::airReaction::reportSpreadDrag() const
{
    const vector spread = returnReduce(spreadOnAir_, sumOp<vector>());
    const vector returned = returnReduce(spreadReturned_, sumOp<vector>());
    if (mag(spread) > 0 || mag(returned) > 0)
    {
        Info<< "    of which spread with the weighted fibers' populations"
            << " over their kernels' cells " << spread << " N (docs/model.md"
            << " sec. 12, P56; at the points, their kernels reaching no cell, "
            << returned << " N)" << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::airReaction::spreadLike
(
    const ::dropletFiber::SpreadPopulations* populations,
    const std::unordered_map<label, int>& levels
)
{
    populations_ = populations;
    populationLevel_ = levels;
}


// ************************************************************************* //
