/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fiberDragSource.H"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "IOdictionary.H"
#include "dictionaryKeys.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(fiberDragSource, 0);
    addToRunTimeSelectionTable(option, fiberDragSource, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The entries of the fvOption's dictionary (docs/reference.md): its own and
//  OpenFOAM's of every fvOption
const Foam::wordList fiberDragSourceKeys
{
    "type", "libs", "active", "log", "fields", "rho", "semiImplicit", "force",
    "coefficient"
};

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fv::fiberDragSource::readDensity(const dictionary& dict)
{
    rho_ = -1;
    rhoOrigin_ = "not given";
    const bool given = dict.found("rho");
    if (given)
    {
        ITstream& is = dict.lookup("rho");
        const token tok(is);
        if (tok.isNumber())
        {
            rho_ = tok.number();
            rhoOrigin_ = "given";
            if (!(rho_ > 0) || !std::isfinite(rho_))
            {
                FatalIOErrorInFunction(dict)
                    << "fvOption " << name_ << ": entry 'rho' is " << rho_
                    << ": allowed are a density > 0 [kg/m3] or"
                    << " transportProperties." << exit(FatalIOError);
            }
            return;
        }
        if (!tok.isWord() || tok.wordToken() != "transportProperties")
        {
            FatalIOErrorInFunction(dict)
                << "fvOption " << name_ << ": entry 'rho' is " << tok
                << ": allowed are a density > 0 [kg/m3] or"
                << " transportProperties." << exit(FatalIOError);
        }
    }
    // transportProperties, read when an incompressible solver needs it
    // (compressible solvers have none and need none)
    const auto* tp = mesh_.findObject<IOdictionary>("transportProperties");
    for (const word key : {"rho", "rhoInf"})
    {
        if (tp && tp->found(key))
        {
            rho_ = dimensionedScalar(key, dimDensity, *tp).value();
            rhoOrigin_ = "transportProperties " + key;
            return;
        }
    }
    rhoOrigin_ =
        given
      ? "transportProperties, which has no rho or rhoInf"
      : "none (compressible solvers use their own density field)";
}


const Foam::volVectorField& Foam::fv::fiberDragSource::force() const
{
    const auto* F = mesh_.findObject<volVectorField>(forceName_);
    if (!F || !mesh_.foundObject<volScalarField>(coefficientName_))
    {
        FatalErrorInFunction
            << "fvOption " << name_ << " (fiberDragSource): the fields "
            << forceName_ << " and " << coefficientName_ << " are not there."
            << nl << "    The function object dropletFiberCollision makes"
            << " them when its fibers.coupled is true: list it in"
            << " system/controlDict with coupled true in its fibers"
            << " dictionary." << exit(FatalError);
    }
    return *F;
}


const Foam::volScalarField& Foam::fv::fiberDragSource::coefficient() const
{
    force();
    return mesh_.lookupObject<volScalarField>(coefficientName_);
}


void Foam::fv::fiberDragSource::addForce
(
    fvMatrix<vector>& eqn,
    const dimensionedScalar& divisor
)
{
    const volVectorField& U = eqn.psi();
    const volVectorField& F = force();
    eqn += F()/divisor;
    if (semiImplicit_)
    {
        const volScalarField& K = coefficient();
        eqn += K()*U()/divisor;
        eqn -= fvm::Sp(K()/divisor, U);
    }
    velocityAtAssembly_ = U.primitiveField();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::fiberDragSource::fiberDragSource
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    semiImplicit_(true),
    rho_(-1),
    loggedTimeIndex_(-1)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::fiberDragSource::addSup
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    if (!(rho_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "fvOption " << name_ << " (fiberDragSource): the momentum"
            << " equation is kinematic (an incompressible solver): it needs"
            << " the air's density, and 'rho' is "
            << (dict_.found("rho") ? rhoOrigin_.c_str() : "not given, and"
                " there is no transportProperties rho or rhoInf")
            << "." << nl << "    Give rho as a value [kg/m3]."
            << exit(FatalIOError);
    }
    addForce(eqn, dimensionedScalar("rho", dimDensity, rho_));
}


void Foam::fv::fiberDragSource::addSup
(
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    addForce(eqn, dimensionedScalar("one", dimless, 1.0));
}


void Foam::fv::fiberDragSource::correct(volVectorField& U)
{
    // Once per write time: at the first velocity update of the step (the
    // momentum predictor's, where the solver has one)
    const label timeIndex = mesh_.time().timeIndex();
    if (!mesh_.time().writeTime() || !log || timeIndex == loggedTimeIndex_)
    {
        return;
    }
    loggedTimeIndex_ = timeIndex;
    const volVectorField& F = force();
    vectorField applied(F.primitiveField());
    if (semiImplicit_ && velocityAtAssembly_.size() == U.size())
    {
        applied +=
            coefficient().primitiveField()
           *(velocityAtAssembly_ - U.primitiveField());
    }
    const vector total = gSum(applied*mesh_.V());
    const vector explicitPart = gSum(F.primitiveField()*mesh_.V());
    Info<< "fvOption " << name_ << " (fiberDragSource): the fibers' drag on"
        << " the air in this step's first velocity update " << total
        << " N (explicit part, the function object's of the step before: "
        << explicitPart << " N)" << endl;
}


bool Foam::fv::fiberDragSource::read(const dictionary& dict)
{
    option::read(dict);
    dropletFiber::checkKeys(coeffs_, fiberDragSourceKeys);
    fieldNames_ = coeffs_.lookupOrDefault<wordList>("fields", wordList({"U"}));
    if (fieldNames_.size() != 1)
    {
        FatalIOErrorInFunction(coeffs_)
            << "fvOption " << name_ << ": entry 'fields' is " << fieldNames_
            << ": allowed is one velocity field, e.g. (U)."
            << exit(FatalIOError);
    }
    applied_.setSize(1, false);
    forceName_ = coeffs_.lookupOrDefault<word>("force", "fiberDragForce");
    coefficientName_ =
        coeffs_.lookupOrDefault<word>("coefficient", "fiberDragCoeff");
    semiImplicit_ = coeffs_.lookupOrDefault<bool>("semiImplicit", true);
    readDensity(coeffs_);
    Info<< "    fiberDragSource " << name_ << ": the fields " << forceName_
        << ", " << coefficientName_ << " on " << fieldNames_[0]
        << (semiImplicit_ ? ", semi-implicit" : ", explicit")
        << "; density for kinematic solvers " << rhoOrigin_.c_str()
        << (rho_ > 0 ? string(" " + Foam::name(rho_)) : string()).c_str()
        << endl;
    return true;
}


// ************************************************************************* //
