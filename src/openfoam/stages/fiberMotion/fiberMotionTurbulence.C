/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The fibers' turbulent air (docs/model.md sec. 8): the fluctuation u' of
    the held fibers' points advanced each step before the fiber step, keyed
    by (seed, fiber id, point, time index) so that the realisation does not
    depend on the decomposition or on restarts (the time index continues
    over a restart and u' is part of each fiber's restart state); the log
    line saying whether it is on and why.

\*---------------------------------------------------------------------------*/

#include "fiberMotion.H"
#include "PstreamReduceOps.H"

#include <cmath>
#include <cstdint>
#include <vector>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::fiberMotion::advanceTurbulence
(
    heldFibers& held,
    const scalar dt,
    const ::dropletFiber::TurbulenceSample& turbulence
)
{
    // A model without k (Spalart-Allmaras, or k not yet developed) gives
    // k = 0: no fluctuation, which the log line would not tell
    // (collective: every processor calls this, with its points or none)
    const label points =
        returnReduce(label(turbulence.pointCount()), sumOp<label>());
    const scalar kMax = returnReduce
    (
        turbulence.pointCount() ? turbulence.kineticEnergy.maxCoeff() : 0.0,
        maxOp<scalar>()
    );
    if (points > 0 && kMax <= 0 && !warnedZeroK_)
    {
        WarningInFunction
            << type() << " " << name() << ": fibers.turbulence is "
            << ::dropletFiber::turbulenceModelName(turbulence_.settings.model).c_str()
            << " but the case's turbulence model gives k = 0 at every fiber"
            << " point at time " << time_.timeName() << " (a model without k,"
            << " such as Spalart-Allmaras?): the fibers see the mean air only"
            << " (said once)." << endl;
        warnedZeroK_ = true;
    }
    if (turbulence.pointCount() == 0)
    {
        return;   // no air sampled here (no movable fiber, or no drag)
    }
    const std::vector<std::uint64_t> ids(held.id.begin(), held.id.end());
    ::dropletFiber::advanceTurbulentVelocities
    (
        held.fibers,
        ids,
        turbulence,
        turbulence_.settings,
        std::uint64_t(time_.timeIndex()),
        dt
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberMotion::reportTurbulence(Ostream& os) const
{
    const auto& s = turbulence_.settings;
    os  << "    fibers.turbulence: "
        << ::dropletFiber::turbulenceModelName(s.model).c_str() << " ("
        << turbulence_.reason.c_str() << ")";
    if (s.model != ::dropletFiber::TurbulenceModelType::none)
    {
        os  << ": u' with variance 2k/3, T_L = " << s.timeScaleCoeff
            << " k/epsilon, L = " << s.lengthScaleCoeff
            << " k^1.5/epsilon along the fibers, seed " << label(s.seed);
    }
    else
    {
        os  << ": the fibers see the mean air only";
    }
    if
    (
        s.model != ::dropletFiber::TurbulenceModelType::none
     && solverSettings_.drag.model == ::dropletFiber::DragModelType::none
    )
    {
        os  << " (no effect: fibers.drag is none)";
    }
    os  << nl;
}


// ************************************************************************* //
