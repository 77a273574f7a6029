/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The fibers' drag per cell, the fields of the fvOption fiberDragSource,
    the table fiberDrag.dat and the one-way check.
\*---------------------------------------------------------------------------*/

#include "airReaction.H"
#include "dictionaryChecks.H"
#include "fvOptions.H"
#include "PstreamReduceOps.H"
#include "calculatedFvPatchFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::dropletFiber::airReaction::forceName("fiberDragForce");
const Foam::word Foam::dropletFiber::airReaction::coefficientName
(
    "fiberDragCoeff"
);


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{


//- Whether constant/fvOptions (or system/fvOptions) lists an active
//  fiberDragSource
bool fvOptionListed(const Foam::fvMesh& mesh)
{
    const auto* options = mesh.findObject<Foam::fv::options>("fvOptions");
    if (!options)
    {
        return false;
    }
    const Foam::fv::optionList& list = *options;
    for (const Foam::fv::option& o : list)
    {
        if (o.type() == "fiberDragSource" && o.active())
        {
            return true;
        }
    }
    return false;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::airReaction::registerFields()
{
    if (force_.valid())
    {
        return;
    }
    auto io = [this](const word& name)
    {
        return IOobject
        (
            name, time_.timeName(), mesh_,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE
        );
    };
    readAtStart_ =
        io(forceName).typeHeaderOk<volVectorField>(true)
     && io(coefficientName).typeHeaderOk<volScalarField>(true);
    force_.reset
    (
        new volVectorField
        (
            io(forceName), mesh_,
            dimensionedVector(dimForce/dimVolume, Zero),
            calculatedFvPatchField<vector>::typeName
        )
    );
    coefficient_.reset
    (
        new volScalarField
        (
            io(coefficientName), mesh_,
            dimensionedScalar(dimDensity/dimTime, Zero),
            calculatedFvPatchField<scalar>::typeName
        )
    );
}


void Foam::dropletFiber::airReaction::startTable()
{
    if (filePtr_.valid() || !Pstream::master())
    {
        return;
    }
    writeToFile_ = true;
    filePtr_ = createFile("fiberDrag");
    OFstream& os = file();
    writeHeader
    (
        os,
        "The fibers' drag per time step [N]: on the air (the cells' sum),"
        " on the fibers (weighted), of the fiber points outside the mesh"
    );
    writeCommented(os, "Time");
    for (const char* column : {"onAir", "onFibers", "outsideMesh"})
    {
        for (const char* component : {"_x", "_y", "_z"})
        {
            writeTabbed(os, word(column) + component);
        }
    }
    os  << endl;
}


Foam::scalar Foam::dropletFiber::airReaction::largestFluxRatio
(
    const volVectorField& U,
    const scalar rho,
    point& where
) const
{
    scalar largest = 0;
    where = point::max;
    forAll(cellForce_, celli)
    {
        const scalar flux =
            rho*magSqr(U[celli])*pow(mesh_.V()[celli], 2.0/3.0);
        const scalar ratio = mag(cellForce_[celli])/max(flux, VSMALL);
        if (ratio > largest)
        {
            largest = ratio;
            where = mesh_.C()[celli];
        }
    }
    // The largest over processors, with its place
    const scalar all = returnReduce(largest, maxOp<scalar>());
    if (largest < all)
    {
        where = point::max;
    }
    reduce(where, minOp<point>());
    return all;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::airReaction::airReaction
(
    const functionObject& owner,
    const fvMesh& mesh
)
:
    couplingStage(owner, mesh),
    writeFile(mesh, owner.name(), "fiberDrag", false),
    coupled_(false),
    warningFraction_(0.1),
    fiberDrag_(Zero),
    outside_(Zero),
    readAtStart_(false),
    warned_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::airReaction::read
(
    const dictionary& fibersDict,
    const label tablePrecision
)
{
    writePrecision_ = tablePrecision;
    coupled_ = getSwitch(fibersDict, "coupled", false);
    warningFraction_ = getPositive(fibersDict, "couplingWarning", 0.1);
    if (coupled_)
    {
        registerFields();
    }
    else if (force_.valid())
    {
        // Switched off during the run: the fvOption finds no force
        *force_ == dimensionedVector(force_->dimensions(), Zero);
        *coefficient_ == dimensionedScalar(coefficient_->dimensions(), Zero);
    }
}


bool Foam::dropletFiber::airReaction::wanted() const
{
    return coupled_ || time_.writeTime();
}


void Foam::dropletFiber::airReaction::startStep()
{
    cellForce_.setSize(mesh_.nCells());
    cellForce_ = Zero;
    cellCoefficient_.setSize(mesh_.nCells());
    cellCoefficient_ = Zero;
    fiberDrag_ = Zero;
    outside_ = Zero;
    spreadOnAir_ = Zero;
    spreadReturned_ = Zero;
}


void Foam::dropletFiber::airReaction::addDrag
(
    const airSampler& sampler,
    const Eigen::Matrix3Xd& force,
    const Eigen::VectorXd& coefficient,
    parallelStatistics& statistics,
    const dragPointFibers* fibers
)
{
    // The air feels the opposite of the fibers' drag, in the cell each
    // point's air was sampled in (on the processor that answered for it);
    // the spread populations' part over their kernels' cells (P56)
    vector outsideOnAir(Zero);
    Eigen::Matrix3Xd onAir = -force;
    Eigen::VectorXd pointCoefficient = coefficient;
    if (fibers && populations_)
    {
        spreadPopulationDrag(*fibers, onAir, pointCoefficient, statistics);
    }
    sampler.spreadToCells
    (
        onAir, pointCoefficient, cellForce_, cellCoefficient_, outsideOnAir,
        statistics
    );
    const Eigen::Vector3d total = force.rowwise().sum();
    fiberDrag_ += vector(total.x(), total.y(), total.z());
    outside_ -= outsideOnAir;
}


void Foam::dropletFiber::airReaction::finishStep
(
    const volVectorField& U,
    const scalar rho
)
{
    const vector onAir = gSum(cellForce_);
    const vector onFibers = returnReduce(fiberDrag_, sumOp<vector>());
    const vector outside = returnReduce(outside_, sumOp<vector>());
    if (coupled_)
    {
        force_->primitiveFieldRef() = cellForce_/mesh_.V();
        coefficient_->primitiveFieldRef() = cellCoefficient_/mesh_.V();
        startTable();
        if (Pstream::master())
        {
            OFstream& os = file();
            writeCurrentTime(os);
            for (const vector& v : {onAir, onFibers, outside})
            {
                for (direction d = 0; d < vector::nComponents; ++d)
                {
                    os  << tab << v[d];
                }
            }
            os  << endl;
        }
        if (time_.writeTime())
        {
            Info<< type() << " " << name() << ": the fibers' drag on the air"
                << " " << onAir << " N (on the fibers " << onFibers
                << " N, of points outside the mesh " << outside << " N)"
                << nl;
            reportSpreadDrag();
        }
        return;
    }
    if (!time_.writeTime() || warned_)
    {
        return;
    }
    point where;
    const scalar ratio = largestFluxRatio(U, rho, where);
    if (ratio > warningFraction_)
    {
        warned_ = true;
        WarningInFunction
            << type() << " " << name() << " at time " << time_.timeName()
            << ": the fibers' drag is " << ratio << " times the air's"
            << " momentum flux rho |U|^2 V^(2/3) in the cell at " << where
            << " (above fibers.couplingWarning " << warningFraction_
            << "), but it does not act on the air (one-way)." << nl
            << "    Set fibers.coupled true and list the fvOption"
            << " fiberDragSource (docs/reference.md) to let it." << endl;
    }
}


void Foam::dropletFiber::airReaction::warnIfAirFeelsNothing
(
    const bool atEnd
) const
{
    if (!coupled_ || fvOptionListed(mesh_))
    {
        return;
    }
    WarningInFunction
        << type() << " " << name() << ": fibers.coupled is true, but no"
        << " active fvOption fiberDragSource is listed (constant/fvOptions or"
        << " system/fvOptions): "
        << (
               atEnd
             ? "the air felt nothing of the fibers' drag during this run (the"
               " fields fiberDragForce and fiberDragCoeff were written, not"
               " applied)."
             : "the fields fiberDragForce and fiberDragCoeff are written, the"
               " air feels nothing."
           ) << nl
        << "    List the fvOption (docs/reference.md, fvOption"
        << " fiberDragSource) for two-way coupling, or set 'coupled false;'."
        << endl;
}


void Foam::dropletFiber::airReaction::report(Ostream& os) const
{
    os  << "    drag on the air: ";
    if (!coupled_)
    {
        os  << "none (one-way; fibers.coupled false), warning above "
            << warningFraction_ << " of the air's momentum flux" << nl;
        return;
    }
    os  << "fields " << forceName << ", " << coefficientName
        << " for the fvOption fiberDragSource, which is "
        << (fvOptionListed(mesh_) ? "listed" : "NOT listed: the air feels nothing")
        << (readAtStart_ ? "; read at the start time" : "") << nl;
}


//- The entries of fibers the air reaction reads
static const Foam::wordList couplingKeys
{
    "coupled", "couplingWarning"
};


Foam::wordList Foam::dropletFiber::airReaction::fibersEntries()
{
    return couplingKeys;
}


// ************************************************************************* //
