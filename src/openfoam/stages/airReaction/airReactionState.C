/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The fields' part of the restart state: written with the time folders,
    read at the start, and checked against the state restarted from.
\*---------------------------------------------------------------------------*/

#include "airReaction.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::airReaction::startWithoutState()
{
    if (!readAtStart_)
    {
        return;
    }
    *force_ == dimensionedVector(force_->dimensions(), Zero);
    *coefficient_ == dimensionedScalar(coefficient_->dimensions(), Zero);
    readAtStart_ = false;
    Info<< type() << " " << name() << ": the fields " << forceName << " and "
        << coefficientName << " of time " << time_.timeName() << " are not"
        << " used (no restart state read: the fibers start afresh)" << nl;
}


void Foam::dropletFiber::airReaction::writeState
(
    const fileName&,
    dictionary& state,
    dictionary&
)
{
    if (!coupled_)
    {
        return;
    }
    // OpenFOAM fields in the time folder: the next step's source, which
    // decomposePar and reconstructPar carry with the flow
    force_->write();
    coefficient_->write();
    state.add("coupledDrag", true);
}


void Foam::dropletFiber::airReaction::readState
(
    const dictionary& state,
    const fileName& path
)
{
    const bool stateCoupled = state.lookupOrDefault<bool>("coupledDrag", false);
    if (coupled_ && stateCoupled && !readAtStart_)
    {
        FatalIOErrorInFunction(state)
            << "The restart state " << path << " was written with the"
            << " fibers' drag on the air (fibers.coupled true), but the"
            << " fields " << forceName << " and " << coefficientName
            << " of time " << time_.timeName() << " are missing: the next"
            << " step's air would lose the fibers' drag." << nl
            << "    Restore them (decomposePar and reconstructPar carry"
            << " them with the flow), or set 'restart fresh;'."
            << exit(FatalIOError);
    }
    if (coupled_ && !stateCoupled)
    {
        Info<< type() << " " << name() << ": the state restarted from was"
            << " one-way: the first step's air feels no fiber drag" << nl;
    }
}


// ************************************************************************* //
