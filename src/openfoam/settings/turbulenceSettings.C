/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "turbulenceSettings.H"
#include "caseTurbulence.H"
#include "dictionaryChecks.H"
#include "dictionaryKeys.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The entries of fibers.turbulence: read by readFiberTurbulence
const Foam::wordList turbulenceKeys
{
    "model", "timeScaleCoeff", "lengthScaleCoeff", "seed"
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::dropletFiber::fiberTurbulence Foam::dropletFiber::readFiberTurbulence
(
    const dictionary& fibersDict,
    const fvMesh& mesh
)
{
    const dictionary dict = optionalSubDict(fibersDict, "turbulence");
    checkKeys(dict, turbulenceKeys);
    const word kind = turbulenceKind(mesh);
    const bool caseTurbulent = kind == "RAS" || kind == "LES";
    const word model = getChoice
    (
        dict,
        "model",
        caseTurbulent ? "ornsteinUhlenbeck" : "none",
        {"none", "ornsteinUhlenbeck"}
    );
    if (model == "ornsteinUhlenbeck" && !caseTurbulent)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'model' is 'ornsteinUhlenbeck' but the case's"
            << " turbulence model is '" << kind << "': it needs k and"
            << " epsilon (or omega) from a RAS or LES model"
            << " (constant/turbulenceProperties); allowed here is none."
            << exit(FatalIOError);
    }

    fiberTurbulence t;
    auto& s = t.settings;
    s.model = ::dropletFiber::turbulenceModelFromName(model);
    s.timeScaleCoeff = getPositive(dict, "timeScaleCoeff", s.timeScaleCoeff);
    s.lengthScaleCoeff =
        getPositive(dict, "lengthScaleCoeff", s.lengthScaleCoeff);
    s.seed = std::uint32_t(getLabelInRange(dict, "seed", 0, 0, labelMax));

    const bool given = dict.found("model");
    t.reason =
        string(given ? "fibers.turbulence.model" : "default")
      + " with the case's turbulence model '" + kind + "'";
    return t;
}

// ************************************************************************* //
