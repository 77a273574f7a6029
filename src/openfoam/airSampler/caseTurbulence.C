/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "caseTurbulence.H"
#include "turbulenceModel.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

const Foam::turbulenceModel* findModel(const Foam::fvMesh& mesh)
{
    return mesh.findObject<Foam::turbulenceModel>
    (
        Foam::turbulenceModel::propertiesName
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::word Foam::dropletFiber::turbulenceKind(const fvMesh& mesh)
{
    const turbulenceModel* model = findModel(mesh);
    if (!model)
    {
        return "none";
    }
    // The model is the IOdictionary of constant/turbulenceProperties
    return model->lookupOrDefault<word>("simulationType", "laminar");
}


bool Foam::dropletFiber::turbulenceFields
(
    const fvMesh& mesh,
    tmp<volScalarField>& k,
    tmp<volScalarField>& epsilon
)
{
    const turbulenceModel* model = findModel(mesh);
    if (!model)
    {
        return false;
    }
    k = model->k();
    epsilon = model->epsilon();
    return true;
}

// ************************************************************************* //
