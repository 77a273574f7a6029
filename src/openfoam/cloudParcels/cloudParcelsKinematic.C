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
    d, nParticle, rho; the position with the mesh's arrays looked up once).
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

//- particle::position() of the parcels of a static mesh, with the mesh's
//  arrays looked up once per cloud instead of through several calls per
//  parcel (it was ~0.19 us per parcel, nearly all of the gathering). The
//  same arithmetic as particle::stationaryTetTransform() and
//  tetIndices::faceTriIs(): the same barycentric tensor, the same product,
//  so the same bits (a case test compares with cloud::writeObjects, which
//  calls position()).
class stationaryPositions
{
    const Foam::faceList& faces_;
    const Foam::labelList& owner_;
    const Foam::labelList& basePoint_;
    const Foam::pointField& points_;
    const Foam::vectorField& cellCentres_;

public:

    explicit stationaryPositions(const Foam::polyMesh& mesh)
    :
        faces_(mesh.faces()),
        owner_(mesh.faceOwner()),
        basePoint_(mesh.tetBasePtIs()),
        points_(mesh.points()),
        cellCentres_(mesh.cellCentres())
    {}

    Foam::point operator()(const Foam::particle& p) const
    {
        const Foam::label facei = p.tetFace();
        const Foam::face& f = faces_[facei];
        // A face without a base point: the first (faceTriIs, whose warning
        // the tracking has given already)
        const Foam::label base = Foam::max(basePoint_[facei], 0);
        Foam::label facePt = (p.tetPt() + base) % f.size();
        Foam::label otherPt = f.fcIndex(facePt);
        if (owner_[facei] != p.cell())
        {
            Foam::Swap(facePt, otherPt);
        }
        const Foam::barycentricTensor transform
        (
            cellCentres_[p.cell()],
            points_[f[base]],
            points_[f[facePt]],
            points_[f[otherPt]]
        );
        return transform & p.coordinates();
    }
};


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
    // On a moving mesh position() interpolates between the old and new
    // points: leave that to it
    const bool moving = typed->pMesh().moving();
    const stationaryPositions stationaryPosition(typed->pMesh());
    for (const ParcelType& p : *typed)
    {
        const Foam::KinematicParcel<Foam::particle>& k = p;
        parcels.position.append
        (
            moving ? k.position() : stationaryPosition(k)
        );
        parcels.U.append(k.U());
        parcels.d.append(k.d());
        parcels.nParticle.append(k.nParticle());
        parcels.rho.append(k.rho());
    }
    return true;
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

// ************************************************************************* //
