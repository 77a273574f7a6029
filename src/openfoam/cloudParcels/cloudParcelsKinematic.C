/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The direct route of cloudParcels::append for the kinematic cloud types of
    lagrangian/intermediate: clouds of basicKinematicParcel,
    basicKinematicCollidingParcel (icoUncoupledKinematicCloud,
    icoUncoupledKinematicParcelFoam, kinematicParcelFoam) and
    basicKinematicMPPICParcel (MPPICFoam). Their parcels are read straight
    from the cloud: five values per parcel, the same values in the same order
    as their writeObjects gives (particle::position(), KinematicParcel's U,
    d, nParticle, rho).
    The generic route builds ~16 fields per parcel in a scratch registry
    every step: it was a fifth of the function object's time in the
    tutorial.

    Thermo, reacting and spray clouds keep the generic route: their parcel
    headers need the thermophysical libraries' headers, which the library
    does not otherwise depend on.

\*---------------------------------------------------------------------------*/

#include "cloudParcels.H"
#include "Cloud.H"
#include "basicKinematicParcel.H"
#include "basicKinematicCollidingParcel.H"
#include "basicKinematicMPPICParcel.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- Append the parcels of c when it is a Cloud<ParcelType>; false otherwise
template<class ParcelType>
bool appendIfCloudOf
(
    const Foam::cloud& c,
    Foam::dropletFiber::cloudParcels& parcels
)
{
    const auto* typed = dynamic_cast<const Foam::Cloud<ParcelType>*>(&c);
    if (!typed)
    {
        return false;
    }
    const Foam::label n = parcels.size() + typed->size();
    parcels.position.reserve(n);
    parcels.U.reserve(n);
    parcels.d.reserve(n);
    parcels.nParticle.reserve(n);
    parcels.rho.reserve(n);
    parcels.origProc.reserve(n);
    parcels.origId.reserve(n);
    parcels.address.reserve(n);
    for (const ParcelType& p : *typed)
    {
        parcels.address.append(&p);
        parcels.origProc.append(p.origProc());
        parcels.origId.append(p.origId());
        const Foam::KinematicParcel<Foam::particle>& k = p;
        parcels.position.append(k.position());
        parcels.U.append(k.U());
        parcels.d.append(k.d());
        parcels.nParticle.append(k.nParticle());
        parcels.rho.append(k.rho());
    }
    return true;
}


//- Depletion of c when it is a Cloud<ParcelType>; false otherwise
template<class ParcelType>
bool depleteIfCloudOf
(
    Foam::cloud& c,
    const Foam::scalar* capturedFraction,
    const Foam::label count,
    const Foam::particle* const* address
)
{
    auto* typed = dynamic_cast<Foam::Cloud<ParcelType>*>(&c);
    if (!typed)
    {
        return false;
    }
    if (typed->size() != count)
    {
        FatalErrorInFunction
            << "Cloud '" << c.name() << "' holds " << typed->size()
            << " parcels, but " << count << " were gathered from it this"
            << " step: the captured droplets cannot be matched to its"
            << " parcels." << Foam::exit(Foam::FatalError);
    }
    bool addressed = address != nullptr;
    for (Foam::label i = 0; i < count && addressed; ++i)
    {
        addressed = address[i] != nullptr;
    }
    Foam::DynamicList<ParcelType*> emptied;
    // The parcel of the i-th fraction, in the cloud's order either way
    const auto deplete = [&](ParcelType& p, const Foam::scalar f)
    {
        Foam::KinematicParcel<Foam::particle>& k = p;
        if (f >= 1)
        {
            emptied.append(&p); // every droplet captured
        }
        else if (f > 0)
        {
            k.nParticle() *= 1 - f;
        }
    };
    if (addressed)
    {
        // Only the parcels that lost droplets (gathered this step from
        // this cloud, which has not changed since: its type is ParcelType)
        for (Foam::label i = 0; i < count; ++i)
        {
            if (capturedFraction[i] > 0)
            {
                deplete
                (
                    *static_cast<ParcelType*>
                    (
                        const_cast<Foam::particle*>(address[i])
                    ),
                    capturedFraction[i]
                );
            }
        }
    }
    else
    {
        Foam::label i = 0;
        for (ParcelType& p : *typed)
        {
            deplete(p, capturedFraction[i++]);
        }
    }
    for (ParcelType* p : emptied)
    {
        typed->deleteParticle(*p);
    }
    return true;
}


//- applyRemoval for c when it is a Cloud<ParcelType>; -1 otherwise
template<class ParcelType>
Foam::label removeIfCloudOf
(
    Foam::cloud& c,
    const std::unordered_map<std::int64_t, Foam::scalar>& removal
)
{
    auto* typed = dynamic_cast<Foam::Cloud<ParcelType>*>(&c);
    if (!typed)
    {
        return -1;
    }
    Foam::DynamicList<ParcelType*> emptied;
    Foam::label found = 0;
    for (ParcelType& p : *typed)
    {
        const auto entry =
            removal.find
            (
                Foam::dropletFiber::cloudParcels::removalKey
                (
                    p.origProc(), p.origId()
                )
            );
        if (entry == removal.end())
        {
            continue;
        }
        ++found;
        Foam::KinematicParcel<Foam::particle>& k = p;
        if (entry->second >= 1)
        {
            emptied.append(&p);
        }
        else
        {
            k.nParticle() *= 1 - entry->second;
        }
    }
    for (ParcelType* p : emptied)
    {
        typed->deleteParticle(*p);
    }
    return found;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::dropletFiber::cloudParcels::appendKinematic(const cloud& c)
{
    return
        appendIfCloudOf<basicKinematicCollidingParcel>(c, *this)
     || appendIfCloudOf<basicKinematicParcel>(c, *this)
     || appendIfCloudOf<basicKinematicMPPICParcel>(c, *this);
}


bool Foam::dropletFiber::cloudParcels::isKinematic(const cloud& c)
{
    return
        isA<Cloud<basicKinematicCollidingParcel>>(c)
     || isA<Cloud<basicKinematicParcel>>(c)
     || isA<Cloud<basicKinematicMPPICParcel>>(c);
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
        depleteIfCloudOf<basicKinematicCollidingParcel>
        (
            c, capturedFraction, count, address
        )
     || depleteIfCloudOf<basicKinematicParcel>
        (
            c, capturedFraction, count, address
        )
     || depleteIfCloudOf<basicKinematicMPPICParcel>
        (
            c, capturedFraction, count, address
        );
}

Foam::label Foam::dropletFiber::cloudParcels::applyRemoval
(
    cloud& c,
    const std::unordered_map<std::int64_t, scalar>& removal
)
{
    label found = removeIfCloudOf<basicKinematicCollidingParcel>(c, removal);
    if (found < 0)
    {
        found = removeIfCloudOf<basicKinematicParcel>(c, removal);
    }
    if (found < 0)
    {
        found = removeIfCloudOf<basicKinematicMPPICParcel>(c, removal);
    }
    return max(found, label(0));
}

// ************************************************************************* //
