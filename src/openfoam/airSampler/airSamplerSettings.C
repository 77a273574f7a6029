/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The settings of airSampler, its sub-dictionary air: the velocity field's
    name, and where the density and the viscosity come from (a value, a
    field, transportProperties, or what the solver reads when the entry is
    not given), with the errors that name what is wrong and what is
    allowed; and the log's line of these settings.

\*---------------------------------------------------------------------------*/

#include "airSampler.H"
#include "IOdictionary.H"
#include "dictionaryChecks.H"
#include "dictionaryKeys.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::dropletFiber::airSampler::whatIs(const word& name) const
{
    // The object of that name in the mesh's registry, whatever its type
    const regIOobject* object = mesh_.cfindObject<regIOobject>(name);
    if (!object)
    {
        return "does not exist";
    }
    return "is a " + object->type();
}



Foam::dropletFiber::airSampler::source
Foam::dropletFiber::airSampler::readSource
(
    const dictionary& dict,
    const word& key
) const
{
    if (!dict.found(key))
    {
        return solverSource(dict, key);
    }
    source s;
    ITstream& is = dict.lookup(key);
    const token tok(is);
    if (tok.isNumber())
    {
        s.value = tok.number();
        if (!(s.value > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << key << "' is " << s.value
                << ": allowed are a value > 0, a field name, or "
                << "transportProperties." << exit(FatalIOError);
        }
        s.origin = "given";
        return s;
    }
    if (!tok.isWord())
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' is " << tok
            << ": allowed are a value > 0, a field name, or "
            << "transportProperties." << exit(FatalIOError);
    }
    if (tok.wordToken() == "transportProperties")
    {
        return transportPropertiesSource(dict, key);
    }
    s.fieldName = tok.wordToken();
    if (!mesh_.foundObject<volScalarField>(s.fieldName))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' names field '" << s.fieldName
            << "', which " << whatIs(s.fieldName).c_str() << ": '" << key
            << "' needs a volScalarField." << nl
            << "    Scalar fields: " << mesh_.sortedNames<volScalarField>() << nl
            << "    Allowed are a value > 0, a field name, or transportProperties."
            << exit(FatalIOError);
    }
    return s;
}


Foam::dropletFiber::airSampler::source
Foam::dropletFiber::airSampler::solverSource
(
    const dictionary& dict,
    const word& key
) const
{
    // What the stock Lagrangian solvers read: transportProperties for the
    // incompressible ones, the thermophysical model's fields (rho,
    // thermo:mu) for the compressible and reacting ones
    if (mesh_.foundObject<IOdictionary>("transportProperties"))
    {
        return transportPropertiesSource(dict, key);
    }
    const word field = key == "mu" ? "thermo:mu" : "rho";
    if
    (
        mesh_.foundObject<volScalarField>("thermo:mu")
     && mesh_.foundObject<volScalarField>(field)
    )
    {
        source s;
        s.fieldName = field;
        s.origin = "the solver's thermophysical model";
        return s;
    }
    FatalIOErrorInFunction(dict)
        << "Entry '" << key << "' is not given, and the solver has neither a"
        << " transportProperties dictionary (incompressible solvers) nor a"
        << " thermophysical model (the fields rho and thermo:mu of"
        << " compressible and reacting solvers)." << nl
        << "    Give '" << key << "' as a value or a field name."
        << exit(FatalIOError);
    return source();
}


Foam::dropletFiber::airSampler::source
Foam::dropletFiber::airSampler::transportPropertiesSource
(
    const dictionary& dict,
    const word& key
) const
{
    // The density as the solver names it: rho (icoUncoupledKinematicCloud,
    // pimpleFoam cases), rhoInf (icoUncoupledKinematicParcelFoam),
    // rho.<continuousPhase> (DPMFoam, MPPICFoam)
    const auto* tp = mesh_.findObject<IOdictionary>("transportProperties");
    wordList densityKeys({"rho", "rhoInf"});
    if (tp && tp->found("continuousPhase"))
    {
        densityKeys.append("rho." + tp->get<word>("continuousPhase"));
    }
    word densityKey;
    for (const word& k : densityKeys)
    {
        if (densityKey.empty() && tp && tp->found(k))
        {
            densityKey = k;
        }
    }
    if (densityKey.empty() || (key == "mu" && !tp->found("nu")))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' is transportProperties"
            << (dict.found(key) ? "" : " (the default)") << ", but "
            << (tp ? "constant/transportProperties has" : "there is no")
            << " no density entry of " << densityKeys
            << (key == "mu" ? " and nu" : "") << "." << nl
            << "    Give '" << key << "' as a value or a field name."
            << exit(FatalIOError);
    }
    source s;
    const scalar rho = dimensionedScalar(densityKey, dimDensity, *tp).value();
    s.value =
        key == "mu"
      ? rho*dimensionedScalar("nu", dimViscosity, *tp).value()
      : rho;
    s.origin =
        "transportProperties " + densityKey + (key == "mu" ? " * nu" : "");
    return s;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::airSampler::read(const dictionary& airDict)
{
    // The entries read below; any other stops the run
    checkKeys(airDict, {"U", "rho", "mu"});
    UName_ = airDict.lookupOrDefault<word>("U", "U");
    if (!mesh_.foundObject<volVectorField>(UName_))
    {
        FatalIOErrorInFunction(airDict)
            << "Entry 'U' names field '" << UName_ << "', which "
            << whatIs(UName_).c_str() << ": U needs a volVectorField."
            << nl << "    Vector fields: "
            << mesh_.sortedNames<volVectorField>() << exit(FatalIOError);
    }
    rho_ = readSource(airDict, "rho");
    mu_ = readSource(airDict, "mu");
}


void Foam::dropletFiber::airSampler::report(Ostream& os) const
{
    auto describe = [](const source& s)
    {
        const string what =
            s.fieldName.empty() ? Foam::name(s.value) : "field " + s.fieldName;
        return s.origin.empty() || s.origin == "given"
            ? what
            : string(what + " (" + s.origin + ")");
    };
    os  << "    air: U field " << UName_ << ", rho " << describe(rho_).c_str()
        << ", mu " << describe(mu_).c_str() << nl;
}

// ************************************************************************* //
