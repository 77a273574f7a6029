/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "cloudParcels.H"
#include "cloud.H"
#include "IOField.H"
#include "objectRegistry.H"
#include "dictionary.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The field of the cloud's parcels called fieldName, or a FatalIOError
//  naming the cloud and the field
template<class Type>
const Foam::IOField<Type>& parcelField
(
    const Foam::objectRegistry& fields,
    const Foam::word& fieldName,
    const Foam::cloud& c,
    const Foam::dictionary& context
)
{
    const auto* ptr = fields.findObject<Foam::IOField<Type>>(fieldName);
    if (!ptr)
    {
        FatalIOErrorInFunction(context)
            << "Cloud '" << c.name() << "' (type " << c.type()
            << ") has no parcel field '" << fieldName << "' of type "
            << Foam::IOField<Type>::typeName << "." << Foam::nl
            << "    dropletFiber needs the parcel fields position, U, d, "
            << "nParticle and rho, as written by kinematic clouds and the "
            << "clouds derived from them." << Foam::nl
            << "    Fields this cloud has: " << fields.sortedToc()
            << Foam::exit(Foam::FatalIOError);
    }
    return *ptr;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::dropletFiber::cloudParcels::clear()
{
    position.clear();
    U.clear();
    d.clear();
    nParticle.clear();
    rho.clear();
    origProc.clear();
    origId.clear();
    address.clear();
}


Foam::scalar Foam::dropletFiber::cloudParcels::nDroplets() const
{
    scalar sum = 0;
    for (const scalar n : nParticle)
    {
        sum += n;
    }
    return sum;
}


void Foam::dropletFiber::cloudParcels::append
(
    const cloud& c,
    const dictionary& context,
    const bool generic
)
{
    if (!generic && appendKinematic(c))
    {
        return;
    }

    // Any other cloud writes its parcel fields into a scratch registry,
    // whatever its parcel type (the generic route of vtkCloud).
    objectRegistry fields
    (
        IOobject
        (
            "dropletFiber::cloudParcels::" + c.name(),
            c.db().time().constant(),
            c.db(),
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    c.writeObjects(fields);

    const auto* positionPtr = cloud::findIOPosition(fields);
    if (!positionPtr)
    {
        FatalIOErrorInFunction(context)
            << "Cloud '" << c.name() << "' (type " << c.type()
            << ") does not give parcel positions." << nl
            << "    Fields this cloud has: " << fields.sortedToc()
            << exit(FatalIOError);
    }
    const auto& cloudU = parcelField<vector>(fields, "U", c, context);
    const auto& cloudD = parcelField<scalar>(fields, "d", c, context);
    const auto& cloudN = parcelField<scalar>(fields, "nParticle", c, context);
    const auto& cloudRho = parcelField<scalar>(fields, "rho", c, context);

    position.append(*positionPtr);
    U.append(cloudU);
    d.append(cloudD);
    nParticle.append(cloudN);
    rho.append(cloudRho);
    // Not written back (depleteKinematic): no identity needed
    origProc.append(labelList(cloudRho.size(), -1));
    origId.append(labelList(cloudRho.size(), -1));
    for (label i = 0; i < cloudRho.size(); ++i)
    {
        address.append(nullptr);
    }
}


Foam::wordList Foam::dropletFiber::cloudParcels::cloudNames
(
    const objectRegistry& obr
)
{
    return obr.sortedNames<cloud>();
}

// ************************************************************************* //
