/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "airSampler.H"
#include "caseTurbulence.H"
#include "interpolationCellPoint.H"
#include "polyMeshTetDecomposition.H"
#include "PstreamReduceOps.H"
#include "PstreamBuffers.H"
#include "UIPstream.H"
#include "UOPstream.H"

#include <algorithm>

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::dropletFiber::airSampler::cellValue
(
    const source& s,
    const label celli
) const
{
    if (s.fieldName.empty())
    {
        return s.value;
    }
    return mesh_.lookupObject<volScalarField>(s.fieldName)[celli];
}


Foam::label Foam::dropletFiber::airSampler::countNonFinite
(
    const volVectorField& U
)
{
    // std::isfinite only: arithmetic on them would trap
    auto nonFinite = [](const vector& u)
    {
        return
            !std::isfinite(u.x())
         || !std::isfinite(u.y())
         || !std::isfinite(u.z());
    };
    label count = 0;
    for (const vector& u : U.primitiveField())
    {
        count += nonFinite(u) ? 1 : 0;
    }
    for (const fvPatchVectorField& patchU : U.boundaryField())
    {
        for (const vector& u : patchU)
        {
            count += nonFinite(u) ? 1 : 0;
        }
    }
    return returnReduce(count, sumOp<label>());
}


bool Foam::dropletFiber::airSampler::tetHolds
(
    const tetIndices& tet,
    const point& p,
    barycentric& w
) const
{
    // The test of cellPointWeight::findTetrahedron, with its tolerance SMALL
    const scalar det = tet.tet(mesh_).pointToBarycentric(p, w);
    return
        mag(det/mesh_.cellVolumes()[tet.cell()]) > SMALL
     && w[0] + SMALL > 0 && w[1] + SMALL > 0 && w[2] + SMALL > 0
     && w[0] + w[1] + w[2] < 1 + SMALL;
}


Foam::vector Foam::dropletFiber::airSampler::interpolateU
(
    const interpolationCellPoint<vector>& interpU,
    const point& p,
    const label celli,
    tetIndices& hint
) const
{
    barycentric w;
    if (hint.cell() == celli && tetHolds(hint, p, w))
    {
        return interpU.interpolate(w, hint);
    }
    // The cell's tets in OpenFOAM's order (polyMeshTetDecomposition::
    // cellTetIndices, without building its lists), so the first that holds p
    // is the one interpolationCellPoint::interpolate(p, celli) would use
    const faceList& faces = mesh_.faces();
    for (const label facei : mesh_.cells()[celli])
    {
        for (label tetPti = 1; tetPti < faces[facei].size() - 1; ++tetPti)
        {
            const tetIndices tet(celli, facei, tetPti);
            if (tetHolds(tet, p, w))
            {
                hint = tet;
                return interpU.interpolate(w, tet);
            }
        }
    }
    // None holds it (a point on a warped face): OpenFOAM's nearest-tet rule
    hint = tetIndices();
    return interpU.interpolate(p, celli);
}


Foam::label Foam::dropletFiber::airSampler::findCellNear
(
    const point& p,
    const label seed
) const
{
    if (seed < 0 || seed >= mesh_.nCells())
    {
        return -1;
    }
    // FACE_PLANES is exact for the convex cells of block meshes and cheap; a
    // point it misses (warped faces) still ends in the full search
    if (mesh_.pointInCell(p, seed, polyMesh::FACE_PLANES))
    {
        return seed;
    }
    for (const label nbr : mesh_.cellCells()[seed])
    {
        if (mesh_.pointInCell(p, nbr, polyMesh::FACE_PLANES))
        {
            return nbr;
        }
    }
    return -1;
}


Foam::label Foam::dropletFiber::airSampler::findCell
(
    const point& p,
    const label hint,
    const label previousPointCell,
    const boundBox& localBounds
) const
{
    if (!localBounds.contains(p))
    {
        return -1;
    }
    label celli = findCellNear(p, hint);
    if (celli < 0 && previousPointCell != hint)
    {
        celli = findCellNear(p, previousPointCell);
    }
    return celli >= 0 ? celli : mesh_.findCell(p);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::airSampler::airSampler
(
    const fvMesh& mesh,
    const dictionary& airDict
)
:
    mesh_(mesh)
{
    read(airDict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dropletFiber::airSampler::referenceDensity() const
{
    return rho_.fieldName.empty()
        ? rho_.value
        : gAverage(mesh_.lookupObject<volScalarField>(rho_.fieldName).primitiveField());
}


Foam::scalar Foam::dropletFiber::airSampler::referenceViscosity() const
{
    return mu_.fieldName.empty()
        ? mu_.value
        : gAverage(mesh_.lookupObject<volScalarField>(mu_.fieldName).primitiveField());
}


void Foam::dropletFiber::airSampler::sampleInCell
(
    const interpolationCellPoint<vector>* interpU,
    const point& p,
    const label celli,
    tetIndices& hint,
    scalar* v
) const
{
    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);
    const vector u = interpU ? interpolateU(*interpU, p, celli, hint) : U[celli];
    v[0] = u.x();
    v[1] = u.y();
    v[2] = u.z();
    v[3] = cellValue(rho_, celli);
    v[4] = cellValue(mu_, celli);
    v[5] = 1;
    v[6] = turbulenceK_ ? (*turbulenceK_)[celli] : 0;
    v[7] = turbulenceEpsilon_ ? (*turbulenceEpsilon_)[celli] : 0;
}


void Foam::dropletFiber::airSampler::askOtherProcessors
(
    const Eigen::Matrix3Xd& points,
    const processorBoxes& boxes,
    const interpolationCellPoint<vector>* interpU,
    List<scalar>& values,
    parallelStatistics& statistics
) const
{
    // The points in none of this processor's cells, to the processors whose
    // box contains them
    List<DynamicList<label>> asked(Pstream::nProcs());
    List<DynamicList<point>> where(Pstream::nProcs());
    for (label i = 0; i < points.cols(); ++i)
    {
        if (values[width*i + 5] == 0)
        {
            const point p(points(0, i), points(1, i), points(2, i));
            for (const label proci : boxes.candidates(p))
            {
                asked[proci].append(i);
                where[proci].append(p);
            }
        }
    }
    PstreamBuffers questions(Pstream::commsTypes::nonBlocking);
    const labelList recvSizes = askProcessors(where, questions, statistics);

    // Answer the others' points in this processor's cells (found: 1)
    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, questions);
            const List<point> theirs(is);
            List<scalar> answer(width*theirs.size(), Zero);
            labelList& cells = answeredCells_[proci];
            cells.setSize(theirs.size());
            forAll(theirs, j)
            {
                const label celli =
                    findCell(theirs[j], -1, -1, boxes.myBox());
                cells[j] = celli;
                if (celli >= 0)
                {
                    tetIndices hint;
                    sampleInCell(interpU, theirs[j], celli, hint, &answer[width*j]);
                }
            }
            UOPstream os(proci, answers);
            os << answer;
            statistics.countSent
            (
                answer.byteSize(), parallelStatistics::traffic::fibers
            );
        }
    }
    answers.finishedSends();

    // In increasing processor order: the lowest that found a point answers
    forAll(asked, proci)
    {
        if (asked[proci].empty())
        {
            continue;
        }
        UIPstream is(proci, answers);
        const List<scalar> answer(is);
        forAll(asked[proci], j)
        {
            scalar* v = &values[width*asked[proci][j]];
            const scalar* a = &answer[width*j];
            if (v[5] == 0 && a[5] > 0)
            {
                std::copy(a, a + width, v);
                answeringProcessor_[asked[proci][j]] = proci;
                answerIndex_[asked[proci][j]] = j;
            }
        }
    }
}


void Foam::dropletFiber::airSampler::forgetAnswers(const label n) const
{
    answeringProcessor_.setSize(n);
    answeringProcessor_ = -1;
    answerIndex_.setSize(n);
    answerIndex_ = -1;
    answeredCells_.setSize(Pstream::nProcs());
    for (labelList& cells : answeredCells_)
    {
        cells.clear();
    }
}


::dropletFiber::AirSample Foam::dropletFiber::airSampler::airOfValues
(
    const List<scalar>& values,
    const label n
) const
{
    const scalar rhoRef = referenceDensity();
    const scalar muRef = referenceViscosity();
    ::dropletFiber::AirSample air;
    air.velocity.resize(3, n);
    air.density.resize(n);
    air.viscosity.resize(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar* v = &values[width*i];
        if (v[5] > 0)
        {
            air.velocity.col(i) = Eigen::Vector3d(v[0], v[1], v[2]);
            air.density(i) = v[3];
            air.viscosity(i) = v[4];
        }
        else
        {
            air.velocity.col(i).setZero();
            air.density(i) = rhoRef;
            air.viscosity(i) = muRef;
        }
    }
    return air;
}


::dropletFiber::AirSample Foam::dropletFiber::airSampler::sample
(
    const Eigen::Matrix3Xd& points,
    const processorBoxes& boxes,
    parallelStatistics& statistics,
    ::dropletFiber::TurbulenceSample* turbulence
) const
{
    const label n = points.cols();
    tmp<volScalarField> k, epsilon;
    if (turbulence && turbulenceFields(mesh_, k, epsilon))
    {
        turbulenceK_ = &k().primitiveField();
        turbulenceEpsilon_ = &epsilon().primitiveField();
    }
    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);
    // A diverged flow: OpenFOAM's cell-point interpolation traps on
    // non-finite values (SIGFPE: its parallel synchronisation compares
    // them), so then the points get their cells' values, and the caller
    // stops on the first that is not finite
    nonFiniteVelocityCells_ = countNonFinite(U);
    autoPtr<interpolationCellPoint<vector>> interpU;
    if (!nonFiniteVelocityCells_)
    {
        interpU.reset(new interpolationCellPoint<vector>(U));
    }

    // Per point: U (3), rho, mu, found (1: by this or another processor)
    List<scalar> values(width*n, Zero);
    cellHint_.setSize(n, -1);
    tetHint_.setSize(n);
    forgetAnswers(n);
    label previousPointCell = -1;
    for (label i = 0; i < n; ++i)
    {
        const point p(points(0, i), points(1, i), points(2, i));
        const label celli =
            findCell(p, cellHint_[i], previousPointCell, boxes.myBox());
        cellHint_[i] = celli;
        previousPointCell = celli;
        if (celli >= 0)
        {
            sampleInCell(interpU.get(), p, celli, tetHint_[i], &values[width*i]);
        }
    }
    if (Pstream::parRun())
    {
        askOtherProcessors(points, boxes, interpU.get(), values, statistics);
    }

    turbulenceK_ = nullptr;
    turbulenceEpsilon_ = nullptr;
    if (turbulence)
    {
        turbulence->kineticEnergy.resize(n);
        turbulence->dissipation.resize(n);
        for (label i = 0; i < n; ++i)
        {
            turbulence->kineticEnergy(i) = values[width*i + 6];
            turbulence->dissipation(i) = values[width*i + 7];
        }
    }

    return airOfValues(values, n);
}


Foam::label Foam::dropletFiber::airSampler::firstNonFinite
(
    const ::dropletFiber::AirSample& air,
    string& quantity
) const
{
    auto describe = [](const source& s)
    {
        return
            s.fieldName.empty()
          ? "value " + Foam::name(s.value)
          : "field " + s.fieldName;
    };
    // std::isfinite only: arithmetic on inf (Eigen's allFinite) would raise
    // the floating-point exception this check is there to prevent
    for (Eigen::Index i = 0; i < air.pointCount(); ++i)
    {
        const bool velocityFinite =
            std::isfinite(air.velocity(0, i))
         && std::isfinite(air.velocity(1, i))
         && std::isfinite(air.velocity(2, i));
        if (!velocityFinite)
        {
            quantity = "velocity (field " + UName_ + ")";
        }
        else if (!std::isfinite(air.density(i)))
        {
            quantity = "density (" + describe(rho_) + ")";
        }
        else if (!std::isfinite(air.viscosity(i)))
        {
            quantity = "viscosity (" + describe(mu_) + ")";
        }
        else
        {
            continue;
        }
        return label(i);
    }
    return -1;
}


void Foam::dropletFiber::airSampler::spreadToCells
(
    const Eigen::Matrix3Xd& force,
    const Eigen::VectorXd& coefficient,
    vectorField& cellForce,
    scalarField& cellCoefficient,
    vector& outside,
    parallelStatistics& statistics
) const
{
    if (force.cols() != cellHint_.size())
    {
        FatalErrorInFunction
            << "the reaction has " << force.cols() << " points, the last"
            << " sample " << cellHint_.size() << abort(FatalError);
    }
    // Per point handed on: its place in the question, force (3), coefficient
    constexpr label perPoint = 5;
    List<DynamicList<scalar>> handed(Pstream::nProcs());
    for (label i = 0; i < force.cols(); ++i)
    {
        const vector f(force(0, i), force(1, i), force(2, i));
        if (cellHint_[i] >= 0)
        {
            cellForce[cellHint_[i]] += f;
            cellCoefficient[cellHint_[i]] += coefficient(i);
        }
        else if (answeringProcessor_[i] >= 0)
        {
            DynamicList<scalar>& to = handed[answeringProcessor_[i]];
            to.append(scalar(answerIndex_[i]));
            to.append(f.x());
            to.append(f.y());
            to.append(f.z());
            to.append(coefficient(i));
        }
        else
        {
            outside += f;
        }
    }
    if (!Pstream::parRun())
    {
        return;
    }
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(handed, proci)
    {
        if (handed[proci].size())
        {
            UOPstream os(proci, buffers);
            os << handed[proci];
            statistics.countSent
            (
                handed[proci].byteSize(), parallelStatistics::traffic::fibers
            );
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);
    forAll(recvSizes, proci)
    {
        if (!recvSizes[proci])
        {
            continue;
        }
        UIPstream is(proci, buffers);
        const List<scalar> theirs(is);
        for (label k = 0; k < theirs.size(); k += perPoint)
        {
            const label celli = answeredCells_[proci][label(theirs[k])];
            cellForce[celli] += vector(theirs[k+1], theirs[k+2], theirs[k+3]);
            cellCoefficient[celli] += theirs[k+4];
        }
    }
}


// ************************************************************************* //
