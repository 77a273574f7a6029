/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Depletion (entry collision.depletion; docs/model.md sec. 7, P12-P14,
    P19): the mass the fibers capture in a step is taken from the parcels
    that carried it. After the collision samples (collide()):
      - each sample's mass m_s (eq. 9) is attributed to the corners of its
        cell in proportion to their part of the interpolated density (P12),
        by the corners' owners (gridBlocks::grantCapture), and gives the
        nodes their optical depth for the step (P13);
      - each parcel crosses the depths of the nodes its deposit reached and
        loses c_p = 1 - (1 - A_p) exp(-X_p) of its droplets (P14), its loss
        attributed to those nodes (P19; gridBlocks::removeCaptured);
      - each segment is given what its samples' nodes lost, its momentum
        that times the samples' droplet velocity;
      - written back by the spray (sprayParcels::writeBack): nParticle is
        reduced, a parcel with c_p = 1 is removed from its cloud.
    Mass captured = mass removed, to round-off (closeRemoval sums both).

\*---------------------------------------------------------------------------*/

#include "fiberCapture.H"
#include "PstreamReduceOps.H"
#include "depletion/SelfShadow.hpp"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::vector<double>
Foam::dropletFiber::fiberCapture::limitCapture
(
    const heldFibers& held,
    couplingGrid& grid,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const std::vector<::dropletFiber::DropletFieldValue>& fields,
    const std::vector<Eigen::Vector3d>& points,
    const std::vector<double>& massSums,
    const std::vector<double>& sampleMasses,
    const std::vector<int>& samplesPerSegment,
    const scalar dt,
    ::dropletFiber::CaptureSources& capture,
    parallelStatistics& statistics
)
{
    // m_s / Sigma per sample: its owners attribute it to their corners
    std::vector<double> shares(points.size(), 0.0);
    scalar demanded = 0;
    for (std::size_t s = 0; s < points.size(); ++s)
    {
        demanded += sampleMasses[s];
        if (sampleMasses[s] > 0 && massSums[s] > 0)
        {
            shares[s] = sampleMasses[s]/massSums[s];
        }
    }
    // Weighted fibers: each sample asked by the N physical fibers its fiber
    // stands for (P40); eq. 9's demand N times one fiber's
    std::vector<double> interceptors;
    if (held.weighted)
    {
        interceptors = samplesInterceptors(held, samplesPerSegment);
        demanded = 0;
        for (std::size_t s = 0; s < points.size(); ++s)
        {
            demanded += interceptors[s]*sampleMasses[s];
        }
    }
    // Spread populations (sec. 12): the lines ask as one fiber each, the
    // populations on their levels
    const bool spread = spreads(held);
    spreadStep_ = spreadStep();
    const std::vector<Eigen::Vector3d> strips =
        stripsAcrossFlow(held, fields, samplesPerSegment);
    if (spread)
    {
        spreadDemand
        (
            held, grid, points, fields, sampleMasses, strips,
            samplesPerSegment, statistics
        );
    }
    ::dropletFiber::CaptureLimitReport report;
    std::vector<double> granted =
        grid.grantCapture
        (
            points, shares, held.weighted && !spread ? &interceptors : nullptr,
            strips, parcels, dt, report, capturedFraction_, statistics,
            spread ? &spreadStep_ : nullptr
        );
    if (spread)
    {
        granted = spreadGranted(granted, strips);
    }
    step_ = depletionSummary();
    step_.demanded = demanded;
    step_.nodesLimited = label(report.nodesLimited);
    // The core's CaptureLimit::granted, segment by segment
    std::size_t next = 0;
    std::size_t segment = 0;
    for (auto& fiberCapture : capture)
    {
        for (auto& segmentCapture : fiberCapture)
        {
            segmentCapture.mass = 0;
            segmentCapture.momentum.setZero();
            for (int s = 0; s < samplesPerSegment[segment]; ++s, ++next)
            {
                segmentCapture.mass += granted[next];
                segmentCapture.momentum += granted[next]*fields[next].velocity;
            }
            ++segment;
        }
    }
    // What eq. 9 asked beyond the mean step's mass at the nodes where the
    // limit bound
    step_.limitedDemand = report.excessDemanded;
    return granted;
}


std::vector<double> Foam::dropletFiber::fiberCapture::samplesInterceptors
(
    const heldFibers& held,
    const std::vector<int>& samplesPerSegment
)
{
    std::vector<double> interceptors;
    std::size_t segment = 0;
    for (const ::dropletFiber::Fiber& fiber : held.fibers)
    {
        for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
        {
            interceptors.insert
            (
                interceptors.end(), std::size_t(samplesPerSegment[segment++]),
                fiber.represents()
            );
        }
    }
    return interceptors;
}


std::vector<Eigen::Vector3d>
Foam::dropletFiber::fiberCapture::stripsAcrossFlow
(
    const heldFibers& held,
    const std::vector<::dropletFiber::DropletFieldValue>& fields,
    const std::vector<int>& samplesPerSegment
) const
{
    // Per sample, in collisionMasses' order: the strip 2 (r_F + r_p) of eq. 9,
    // r_p its mean radius, across the segment and the relative velocity
    std::vector<Eigen::Vector3d> strips(fields.size(), Eigen::Vector3d::Zero());
    std::size_t next = 0;
    std::size_t segment = 0;
    for (const ::dropletFiber::Fiber& fiber : held.fibers)
    {
        const Eigen::Matrix3Xd& x = fiber.positions();
        const Eigen::Matrix3Xd& v = fiber.velocities();
        for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
        {
            const Eigen::Vector3d segmentVelocity = 0.5*(v.col(j) + v.col(j + 1));
            const Eigen::Vector3d piece = x.col(j + 1) - x.col(j);
            for (int s = 0; s < samplesPerSegment[segment]; ++s, ++next)
            {
                const ::dropletFiber::DropletFieldValue& field = fields[next];
                if (!field.inside || !(field.rho > 0))
                {
                    continue;
                }
                const scalar meanRadius =
                    collision_.radiusAverage
                 == ::dropletFiber::RadiusAverage::Mass
                  ? field.rMeanMass
                  : field.rMeanNumber;
                strips[next] =
                    ::dropletFiber::stripAcrossFlow
                    (
                        2*(fiber.material().radius + meanRadius), piece,
                        field.velocity - segmentVelocity
                    );
            }
            ++segment;
        }
    }
    return strips;
}


void Foam::dropletFiber::fiberCapture::logLimitOnce()
{
    if (loggedLimit_ || step_.nodesLimited == 0)
    {
        return;
    }
    loggedLimit_ = true;
    Info<< type() << " " << name() << ": at time " << time_.timeName()
        << " the fibers asked more droplet mass of "
        << step_.nodesLimited << " grid nodes than the parcels bring there"
        << " in a step (eq. 9 asked " << step_.limitedDemand
        << " kg more than the window's mean step holds there): their capture"
        << " is limited to what the nodes hold (docs/model.md sec. 7; a large"
        << " time step, a thin spray, fibers thicker than the grid spacing or"
        << " fibers each standing for many). Logged once." << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberCapture::closeRemoval
(
    const parcelRemoval& removal
)
{
    // What left the parcels written back, and what flies on, with the
    // step's demand: one reduction
    List<scalar> sums(6, Zero);
    sums[0] = removal.removed;
    sums[1] = removal.airborne;
    sums[2] = step_.demanded;
    sums[3] = scalar(step_.nodesLimited);
    sums[4] = step_.limitedDemand;
    sums[5] = removal.kept;
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);
    step_.removed = sums[0];
    step_.airborne = sums[1];
    step_.demanded = sums[2];
    step_.nodesLimited = label(sums[3]);
    step_.limitedDemand = sums[4];
    step_.kept = sums[5];
    logLimitOnce();
}


void Foam::dropletFiber::fiberCapture::reportBinderBalance() const
{
    if (!depletion_)
    {
        return;
    }
    // Captured = removed + kept in clouds that cannot be written back
    const depletionSummary& d = step_;
    const scalar scale = max(mag(d.captured), mag(d.removed + d.kept));
    Info<< type() << " " << name() << " binder balance at time "
        << time_.timeName() << ":" << nl
        << "    this step: captured " << d.captured << " kg, removed from"
        << " the parcels " << d.removed << " kg";
    if (d.kept > 0)
    {
        Info<< ", left in the parcels of clouds read through"
            << " cloud::writeObjects " << d.kept << " kg (they cannot be"
            << " written back)";
    }
    Info<< " (relative difference "
        << (scale > 0 ? (d.captured - d.removed - d.kept)/scale : scalar(0))
        << "), eq. 9 before the limit " << d.demanded << " kg" << nl
        << "    airborne parcel mass after the removal " << d.airborne
        << " kg; captured in total " << captured_ << " kg" << nl
        << "    since this run started: eq. 9 asked " << run_.demanded
        << " kg, the fibers captured " << run_.captured
        << " kg and the parcels lost " << run_.removed
        << " kg; the limit bound in " << limitedSteps_ << " of "
        << depletionSteps_ << " steps" << nl << endl;
}


// ************************************************************************* //
