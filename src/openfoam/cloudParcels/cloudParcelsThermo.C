/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The direct route of cloudParcels for the parcel types of the evaporating,
    reacting and spray clouds the stock v1912 solvers create
    (thermoParcelTypes.H).
    All derive from KinematicParcel<particle>: the five values read (position,
    U, d, nParticle, rho) and the depletion's write-back (nParticle reduced,
    emptied parcels deleted) are the kinematic parcels' (cloudParcelsTemplates.H).
    A parcel's mass is nParticle rho pi d^3/6, as the cloud's own mass
    (KinematicParcel::mass); its composition (Y) and temperature are left as
    they are: the captured droplets are taken whole.

\*---------------------------------------------------------------------------*/

#include "cloudParcelsTemplates.H"
#include "thermoParcelTypes.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

namespace
{
    using thermoParcels =
        Foam::dropletFiber::directRoute
        <
            Foam::dropletFiber::thermoParcelTypes
        >;
}


bool Foam::dropletFiber::cloudParcels::isThermo(const cloud& c)
{
    return thermoParcels::holds(c);
}


bool Foam::dropletFiber::cloudParcels::appendThermo(const cloud& c)
{
    return thermoParcels::append(c, *this);
}


bool Foam::dropletFiber::cloudParcels::depleteThermo
(
    cloud& c,
    const scalar* capturedFraction,
    const label count,
    const particle* const* address
)
{
    return thermoParcels::deplete(c, capturedFraction, count, address);
}


Foam::label Foam::dropletFiber::cloudParcels::applyRemovalThermo
(
    cloud& c,
    const std::unordered_map<std::int64_t, scalar>& removal
)
{
    return thermoParcels::remove(c, removal);
}

// ************************************************************************* //
