/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The binder balance of the clouds with depletion: what the clouds'
    injectors sprayed is airborne, evaporated (phase change), escaped
    through the domain's patches or captured by the fibers,

        sprayed = airborne + evaporated + escaped + captured,

    with the cloud's own figures for the first (injectors), third and fourth
    (their submodels: cloudParcels::addMassReport) and the capture stage's
    for airborne (the parcel mass after the removal) and captured.
    Where the parcels carry a liquid composition the captured mass is also
    summed per liquid species, parcel by parcel as it is removed:
    captured_i = sum_p c_p m_p Y_p,i (c_p the fraction of its droplets
    captured, m_p its mass, Y_p,i the species' mass fraction at the moment
    of capture); a running total over the run, carried over a restart.

\*---------------------------------------------------------------------------*/

#include "sprayParcels.H"
#include "cloud.H"
#include "Time.H"
#include "fvMesh.H"
#include "PstreamReduceOps.H"
#include "grid/Parcel.hpp"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::sprayParcels::findLiquidSpecies()
{
    liquidSpecies_.clear();
    const wordList clouds =
        cloudNames_.empty()
      ? cloudParcels::cloudNames(mesh_)
      : cloudNames_;
    DynamicList<word> species;
    for (const word& cloudName : clouds)
    {
        if (!mesh_.foundObject<cloud>(cloudName))
        {
            continue; // created later (selectClouds reports it if never)
        }
        const cloud& c = mesh_.lookupObject<cloud>(cloudName);
        for (const word& s : cloudParcels::liquidSpecies(c))
        {
            if (!species.found(s))
            {
                species.append(s);
            }
        }
    }
    liquidSpecies_.transfer(species);
    capturedSpecies_.setSize(liquidSpecies_.size());
    capturedSpecies_ = Zero;
}


void Foam::dropletFiber::sprayParcels::addCapturedSpecies
(
    const std::vector<double>& fraction
)
{
    if (liquidSpecies_.empty())
    {
        return;
    }
    // The parcel mass the removal takes its fraction of
    std::vector<double> mass(fraction.size(), 0.0);
    for (std::size_t p = 0; p < fraction.size(); ++p)
    {
        if (fraction[p] > 0)
        {
            mass[p] = ::dropletFiber::parcelMass(stepParcels_[p]);
        }
    }
    const bool addressed = parcels_.address.size() == parcels_.size();
    scalarList step(liquidSpecies_.size(), Zero);
    forAll(stepClouds_, k)
    {
        const cloud& c = mesh_.lookupObject<cloud>(stepClouds_[k]);
        const wordList names = cloudParcels::liquidSpecies(c);
        if (names.empty())
        {
            continue;
        }
        const label start = cloudStarts_[k];
        const label end = cloudEnd(k);
        scalarList captured(names.size(), Zero);
        cloudParcels::addCapturedSpecies
        (
            c,
            fraction.data() + start,
            mass.data() + start,
            end - start,
            addressed ? parcels_.address.cdata() + start : nullptr,
            captured
        );
        forAll(names, i)
        {
            const label column = liquidSpecies_.find(names[i]);
            if (column >= 0)
            {
                step[column] += captured[i];
            }
        }
    }
    Pstream::listCombineGather(step, plusEqOp<scalar>());
    Pstream::listCombineScatter(step);
    forAll(step, i)
    {
        capturedSpecies_[i] += step[i];
    }
}


const Foam::dropletFiber::cloudParcels::massReport&
Foam::dropletFiber::sprayParcels::readCloudMassReport()
{
    cloudMass_ = cloudParcels::massReport();
    for (const word& cloudName : stepClouds_)
    {
        cloudParcels::addMassReport
        (
            mesh_.lookupObject<cloud>(cloudName), cloudMass_
        );
    }
    return cloudMass_;
}


void Foam::dropletFiber::sprayParcels::reportCloudBalance
(
    const scalar airborne,
    const scalar captured
) const
{
    if (!depletion_)
    {
        return;
    }
    const auto& m = cloudMass_;
    const scalar accounted = airborne + m.evaporated + m.escaped + captured;
    Info<< type() << " " << name() << " cloud balance at time "
        << time_.timeName() << ": sprayed " << m.sprayed << " kg = airborne "
        << airborne << " + evaporated " << m.evaporated
        << " + escaped " << m.escaped << " + captured " << captured
        << " kg (relative difference "
        << (m.sprayed > 0 ? (m.sprayed - accounted)/m.sprayed : scalar(0))
        << ")" << nl;
    if (!liquidSpecies_.empty())
    {
        Info<< "    captured per liquid species:";
        scalar sum = 0;
        forAll(liquidSpecies_, i)
        {
            Info<< (i ? ", " : " ") << liquidSpecies_[i] << " "
                << capturedSpecies_[i] << " kg";
            sum += capturedSpecies_[i];
        }
        Info<< " (sum " << sum << " kg of " << captured << " kg)"
            << nl;
    }
    Info<< endl;
}

// ************************************************************************* //
