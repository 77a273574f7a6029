/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The step's drag handed to the air (docs/model.md sec. 10): each point's
    drag impulse over the step, times the physical fibers its fiber stands
    for, over the step, handed to the air reaction (airReaction::addDrag:
    with the opposite sign into the cell its air was sampled in). The moving
    fibers' drag is the solver's (its accepted sub-steps at their converged
    iterates); the immobile fibers' is the drag law's at their air, sampled
    for it when coupled.
\*---------------------------------------------------------------------------*/

#include "fiberMotion.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

// Per drag point its fiber's id, weight and position: the air sample's
// points (immobile false) or every point of the immobile fibers (true)
Foam::dropletFiber::dragPointFibers pointFibers
(
    const std::vector<::dropletFiber::Fiber>& fibers,
    const std::vector<Foam::label>& ids,
    const bool immobile
)
{
    Foam::dropletFiber::dragPointFibers points;
    points.position =
        immobile ? Eigen::Matrix3Xd(3, 0) : ::dropletFiber::airSamplePoints(fibers);
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        const ::dropletFiber::Fiber& fiber = fibers[f];
        const Eigen::Index n =
            immobile
          ? (fiber.immobile() ? fiber.pointCount() : 0)
          : ::dropletFiber::airSamplePointCount(fiber);
        if (immobile && n)
        {
            points.position.conservativeResize(3, points.position.cols() + n);
            points.position.rightCols(n) = fiber.positions();
        }
        points.id.insert(points.id.end(), std::size_t(n), ids[f]);
        points.represents.insert(points.represents.end(), std::size_t(n), fiber.represents());
    }
    return points;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::fiberMotion::handMovingDrag
(
    const heldFibers& held,
    const bool sampled,
    const scalar dt,
    airReaction& reaction,
    parallelStatistics& statistics
) const
{
    if (!sampled)
    {
        return;
    }
    // The solver's reaction is laid out as the air sample: the movable
    // fibers' points in fiber order
    Eigen::Matrix3Xd force = dragReaction_.impulse/dt;
    Eigen::VectorXd coefficient = dragReaction_.coefficientTime/dt;
    const ::dropletFiber::AirSampleLayout layout =
        ::dropletFiber::airSampleLayout(held.fibers);
    for (std::size_t f = 0; f < held.fibers.size(); ++f)
    {
        const ::dropletFiber::Fiber& fiber = held.fibers[f];
        const Eigen::Index n = ::dropletFiber::airSamplePointCount(fiber);
        if (n && fiber.represents() != 1)
        {
            force.middleCols(layout.firstPoint[f], n) *= fiber.represents();
            coefficient.segment(layout.firstPoint[f], n) *= fiber.represents();
        }
    }
    dragPointFibers fibers = pointFibers(held.fibers, held.id, false);
    reaction.addDrag(*air_, force, coefficient, statistics, &fibers);
}


void Foam::dropletFiber::fiberMotion::handImmobileDrag
(
    const heldFibers& held,
    const processorBoxes& boxes,
    airReaction& reaction,
    parallelStatistics& statistics
) const
{
    if (solverSettings_.drag.model == ::dropletFiber::DragModelType::none)
    {
        return;
    }
    Eigen::Index total = 0;
    for (const ::dropletFiber::Fiber& fiber : held.fibers)
    {
        total += fiber.immobile() ? fiber.pointCount() : 0;
    }
    if (returnReduce(label(total), sumOp<label>()) == 0)
    {
        return;
    }
    Eigen::Matrix3Xd points(3, total);
    Eigen::Index first = 0;
    for (const ::dropletFiber::Fiber& fiber : held.fibers)
    {
        if (fiber.immobile())
        {
            points.middleCols(first, fiber.pointCount()) = fiber.positions();
            first += fiber.pointCount();
        }
    }
    const ::dropletFiber::AirSample air =
        immobileAir_->sample(points, boxes, statistics);
    // Over a step of 1 s: the impulse is then the force
    ::dropletFiber::DragReaction drag;
    drag.reset(total);
    first = 0;
    for (const ::dropletFiber::Fiber& fiber : held.fibers)
    {
        if (fiber.immobile())
        {
            ::dropletFiber::addImmobileFiberReaction
            (
                fiber, air, first, solverSettings_.drag, 1.0, drag, first
            );
            drag.impulse.middleCols(first, fiber.pointCount()) *=
                fiber.represents();
            drag.coefficientTime.segment(first, fiber.pointCount()) *=
                fiber.represents();
            first += fiber.pointCount();
        }
    }
    dragPointFibers fibers = pointFibers(held.fibers, held.id, true);
    reaction.addDrag
    (
        *immobileAir_, drag.impulse, drag.coefficientTime, statistics,
        &fibers
    );
}


// ************************************************************************* //
