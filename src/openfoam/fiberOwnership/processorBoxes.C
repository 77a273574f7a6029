/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "processorBoxes.H"
#include "Pstream.H"
#include "UOPstream.H"
#include "ops.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::processorBoxes::processorBoxes(const polyMesh& mesh)
:
    mesh_(mesh),
    boxes_(Pstream::nProcs())
{
    update();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::processorBoxes::update()
{
    // This processor's own points (mesh_.bounds() is the whole mesh's box
    // in parallel)
    boxes_[Pstream::myProcNo()] = boundBox(mesh_.points(), false);
    Pstream::gatherList(boxes_);
    Pstream::scatterList(boxes_);
}


bool Foam::dropletFiber::processorBoxes::holds(const point& p) const
{
    return myBox().contains(p) && mesh_.findCell(p) >= 0;
}


Foam::labelList Foam::dropletFiber::processorBoxes::candidates
(
    const point& p
) const
{
    labelList result;
    forAll(boxes_, proci)
    {
        if (proci != Pstream::myProcNo() && boxes_[proci].contains(p))
        {
            result.append(proci);
        }
    }
    return result;
}


Foam::labelList Foam::dropletFiber::processorBoxes::lowestHolders
(
    const List<point>& points,
    const label fallback
) const
{
    // One reduction of the points' processors (nProcs: not held here)
    labelList holder(points.size(), Pstream::nProcs());
    forAll(points, i)
    {
        if (holds(points[i]))
        {
            holder[i] = Pstream::myProcNo();
        }
    }
    Pstream::listCombineGather(holder, minEqOp<label>());
    Pstream::listCombineScatter(holder);
    for (label& proci : holder)
    {
        if (proci == Pstream::nProcs())
        {
            proci = fallback;
        }
    }
    return holder;
}

Foam::labelList Foam::dropletFiber::askProcessors
(
    const List<DynamicList<point>>& pointsTo,
    PstreamBuffers& questions,
    parallelStatistics& statistics
)
{
    forAll(pointsTo, proci)
    {
        if (pointsTo[proci].size())
        {
            UOPstream os(proci, questions);
            os << pointsTo[proci];
            statistics.countSent
            (
                pointsTo[proci].byteSize(), parallelStatistics::traffic::fibers
            );
        }
    }
    labelList recvSizes;
    questions.finishedSends(recvSizes);
    return recvSizes;
}


// ************************************************************************* //
