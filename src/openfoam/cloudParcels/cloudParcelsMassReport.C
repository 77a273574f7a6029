/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The clouds' own mass figures for the binder balance (sprayed =
    airborne + evaporated + escaped + captured) and the captured mass per
    liquid species, for the parcel types read directly: every such cloud
    reports its injectors' mass and the escaped mass (its kinematic level,
    KinematicCloud<Cloud<parcel>>); the reacting, reacting multiphase,
    heterogeneous reacting and spray clouds also the phase change mass and
    their composition (their reacting level,
    ReactingCloud<ThermoCloud<KinematicCloud<Cloud<parcel>>>>).
    Devolatilisation and surface reaction of reacting multiphase (coal)
    clouds are not among the terms.

\*---------------------------------------------------------------------------*/

#include "cloudMassReportTemplates.H"
#include "cloudParcelsTemplates.H"
#include "kinematicParcelTypes.H"
#include "thermoParcelTypes.H"
#include "ThermoCloud.H"
#include "ReactingCloud.H"
#include "PhaseChangeModel.H"
#include "CompositionModel.H"

#include <type_traits>
#include <utility>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The reacting level of the clouds of ParcelType
template<class ParcelType>
using reactingCloudOf =
    ReactingCloud<ThermoCloud<KinematicCloud<Cloud<ParcelType>>>>;


//- The phase change mass as PhaseChangeModel::info prints it
template<class CloudType>
struct phaseChangeMassOf
:
    public PhaseChangeModel<CloudType>
{
    static scalar total(const PhaseChangeModel<CloudType>& model)
    {
        const scalar thisRun = model.*(&phaseChangeMassOf::dMass_);
        return
            model.template getBaseProperty<scalar>("mass")
          + returnReduce(thisRun, sumOp<scalar>());
    }
};


//- Whether ParcelType has the member that Member names (the detection
//  idiom)
template<class ParcelType, template<class> class Member, class = void>
struct hasMember : std::false_type {};

template<class ParcelType, template<class> class Member>
struct hasMember<ParcelType, Member, std::void_t<Member<ParcelType>>>
: std::true_type {};

//- A composition, ReactingParcel's Y(): the parcel's cloud has a reacting
//  level
template<class ParcelType>
using compositionOf = decltype(std::declval<const ParcelType&>().Y());

//- Phases, ReactingMultiphaseParcel's YLiquid(): Y() holds the phases'
//  fractions, YLiquid() the liquid's composition
template<class ParcelType>
using liquidPhaseOf = decltype(std::declval<const ParcelType&>().YLiquid());


//- Adds m Y_liquid,i of parcel p to captured (idLiquid: the liquid phase)
template<class ParcelType>
void addLiquidMass
(
    const ParcelType& p,
    const label idLiquid,
    const scalar m,
    scalarList& captured
)
{
    if constexpr (hasMember<ParcelType, liquidPhaseOf>::value)
    {
        const scalar liquid = m*p.Y()[idLiquid];
        const scalarField& Y = p.YLiquid();
        forAll(captured, i)
        {
            captured[i] += liquid*Y[i];
        }
    }
    else
    {
        // One phase: Y() is its composition
        const scalarField& Y = p.Y();
        forAll(captured, i)
        {
            captured[i] += m*Y[i];
        }
    }
}


//- The phase change mass of c when it is a reacting cloud of ParcelType
template<class ParcelType>
bool addPhaseChange(const cloud& c, dropletFiber::cloudParcels::massReport& r)
{
    using cloudType = reactingCloudOf<ParcelType>;
    const auto* typed = dynamic_cast<const cloudType*>(&c);
    if (!typed)
    {
        return false;
    }
    r.evaporated += phaseChangeMassOf<cloudType>::total(typed->phaseChange());
    return true;
}


//- The liquid species of c when it is a reacting cloud of ParcelType
template<class ParcelType>
bool liquidSpeciesOf(const cloud& c, wordList& names)
{
    const auto* typed = dynamic_cast<const reactingCloudOf<ParcelType>*>(&c);
    if (!typed)
    {
        return false;
    }
    const label idLiquid = typed->composition().idLiquid();
    if (idLiquid >= 0)
    {
        names = typed->composition().componentNames(idLiquid);
    }
    return true;
}


//- addCapturedSpecies for c when it is a reacting cloud of ParcelType
template<class ParcelType>
bool capturedSpeciesOf
(
    const cloud& c,
    const scalar* fraction,
    const scalar* mass,
    const label count,
    const particle* const* address,
    scalarList& captured
)
{
    const auto* typed = dynamic_cast<const reactingCloudOf<ParcelType>*>(&c);
    if (!typed)
    {
        return false;
    }
    const label idLiquid = typed->composition().idLiquid();
    if (idLiquid < 0 || typed->size() != count)
    {
        return true;
    }
    dropletFiber::forEachCapturedParcel<ParcelType>
    (
        *typed, fraction, count, address,
        [&](const ParcelType& p, const scalar f, const label i)
        {
            addLiquidMass(p, idLiquid, f*mass[i], captured);
        }
    );
    return true;
}


//- The parcel types read directly: both families
using directParcelTypes =
    dropletFiber::kinematicParcelTypes::followedBy
    <
        dropletFiber::thermoParcelTypes
    >;


//- operation(parcelTypeTag<P>()) for the parcel types P read directly whose
//  clouds have a reacting level (those with a composition), in order, until
//  one returns true; whether one did
template<class Operation>
bool firstReacting(Operation&& operation)
{
    return dropletFiber::thermoParcelTypes::firstOf
    (
        [&](auto type)
        {
            using parcelType = typename decltype(type)::type;
            if constexpr (hasMember<parcelType, compositionOf>::value)
            {
                return operation(type);
            }
            else
            {
                return false;
            }
        }
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::dropletFiber::cloudParcels::addMassReport
(
    const cloud& c,
    massReport& report
)
{
    const bool direct = directParcelTypes::firstOf
    (
        [&](auto type)
        {
            using parcelType = typename decltype(type)::type;
            return dropletFiber::addKinematicMassReport<parcelType>(c, report);
        }
    );
    if (direct)
    {
        firstReacting
        (
            [&](auto type)
            {
                return addPhaseChange<typename decltype(type)::type>(c, report);
            }
        );
    }
    return direct;
}


Foam::wordList Foam::dropletFiber::cloudParcels::liquidSpecies
(
    const cloud& c
)
{
    wordList names;
    firstReacting
    (
        [&](auto type)
        {
            return liquidSpeciesOf<typename decltype(type)::type>(c, names);
        }
    );
    return names;
}


void Foam::dropletFiber::cloudParcels::addCapturedSpecies
(
    const cloud& c,
    const scalar* capturedFraction,
    const scalar* mass,
    const label count,
    const particle* const* address,
    scalarList& captured
)
{
    firstReacting
    (
        [&](auto type)
        {
            return capturedSpeciesOf<typename decltype(type)::type>
            (
                c, capturedFraction, mass, count, address, captured
            );
        }
    );
}

// ************************************************************************* //
