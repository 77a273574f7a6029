/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The direct route of cloudParcels::append for the kinematic cloud types of
    lagrangian/intermediate (kinematicParcelTypes.H). Their parcels are read
    straight from the cloud: five values per parcel, the same values in the
    same order as their writeObjects gives (particle::position(), KinematicParcel's U,
    d, nParticle, rho).
    The generic route builds ~16 fields per parcel in a scratch registry
    every step: it was a fifth of the function object's time in the
    tutorial.

    The parcel types of the thermo, reacting and spray clouds are read and
    written back the same way (cloudParcelsThermo.C, which needs the
    thermophysical libraries' headers); the members below try them after
    the kinematic types.

\*---------------------------------------------------------------------------*/

#include "cloudParcelsTemplates.H"
#include "kinematicParcelTypes.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

namespace
{
    using kinematicParcels =
        Foam::dropletFiber::directRoute
        <
            Foam::dropletFiber::kinematicParcelTypes
        >;
}


bool Foam::dropletFiber::cloudParcels::appendKinematic(const cloud& c)
{
    return kinematicParcels::append(c, *this) || appendThermo(c);
}


bool Foam::dropletFiber::cloudParcels::readsDirectly(const cloud& c)
{
    return isKinematic(c) || isThermo(c);
}


bool Foam::dropletFiber::cloudParcels::isKinematic(const cloud& c)
{
    return kinematicParcels::holds(c);
}


bool Foam::dropletFiber::cloudParcels::depleteKinematic
(
    cloud& c,
    const scalar* capturedFraction,
    const label count,
    const particle* const* address
)
{
    return
        kinematicParcels::deplete(c, capturedFraction, count, address)
     || depleteThermo(c, capturedFraction, count, address);
}


Foam::label Foam::dropletFiber::cloudParcels::applyRemoval
(
    cloud& c,
    const std::unordered_map<std::int64_t, scalar>& removal
)
{
    label found = kinematicParcels::remove(c, removal);
    if (found < 0)
    {
        found = applyRemovalThermo(c, removal);
    }
    return max(found, label(0));
}

// ************************************************************************* //
