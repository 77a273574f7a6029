/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "airSampler.H"
#include "interpolationCellPoint.H"
#include "polyMeshTetDecomposition.H"
#include "IOdictionary.H"
#include "dictionaryChecks.H"
#include "dictionaryKeys.H"
#include "PstreamReduceOps.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dropletFiber::airSampler::source
Foam::dropletFiber::airSampler::readSource
(
    const dictionary& dict,
    const word& key
) const
{
    source s;
    if (!dict.found(key))
    {
        s.fieldName = "transportProperties";
    }
    else
    {
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
            return s;
        }
        if (!tok.isWord())
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << key << "' is " << tok
                << ": allowed are a value > 0, a field name, or "
                << "transportProperties." << exit(FatalIOError);
        }
        s.fieldName = tok.wordToken();
    }

    if (s.fieldName == "transportProperties")
    {
        const auto* tp = mesh_.findObject<IOdictionary>("transportProperties");
        if (!tp || !tp->found("rho") || (key == "mu" && !tp->found("nu")))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << key << "' is transportProperties (the default), "
                << "but there is no transportProperties dictionary with "
                << (key == "mu" ? "rho and nu" : "rho") << "." << nl
                << "    Give '" << key << "' as a value or a field name."
                << exit(FatalIOError);
        }
        const scalar rho = dimensionedScalar("rho", dimDensity, *tp).value();
        s.value =
            key == "mu"
          ? rho*dimensionedScalar("nu", dimViscosity, *tp).value()
          : rho;
        s.fieldName.clear();
    }
    else if (!mesh_.foundObject<volScalarField>(s.fieldName))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' names field '" << s.fieldName
            << "', which does not exist." << nl
            << "    Scalar fields: " << mesh_.sortedNames<volScalarField>() << nl
            << "    Allowed are a value > 0, a field name, or transportProperties."
            << exit(FatalIOError);
    }
    return s;
}


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

void Foam::dropletFiber::airSampler::read(const dictionary& airDict)
{
    // The entries read below; any other stops the run
    checkKeys(airDict, {"U", "rho", "mu"});
    UName_ = airDict.lookupOrDefault<word>("U", "U");
    if (!mesh_.foundObject<volVectorField>(UName_))
    {
        FatalIOErrorInFunction(airDict)
            << "Entry 'U' names velocity field '" << UName_
            << "', which does not exist." << nl
            << "    Vector fields: " << mesh_.sortedNames<volVectorField>()
            << exit(FatalIOError);
    }
    rho_ = readSource(airDict, "rho");
    mu_ = readSource(airDict, "mu");
}


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


::dropletFiber::AirSample Foam::dropletFiber::airSampler::sample
(
    const Eigen::Matrix3Xd& points,
    parallelStatistics& statistics
) const
{
    const label n = points.cols();
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

    // Per point: U (3), rho, mu, number of processors that found it; summed
    // across processors in one reduction
    constexpr label width = 6;
    List<scalar> values(width*n, Zero);
    // This processor's own box (not reduced: mesh_.bounds() is the box of
    // the whole mesh in parallel, which sent every point of the other
    // processors to the octree search), per sample so that a moving mesh is
    // searched where it is now (a few microseconds)
    const boundBox localBounds(mesh_.points(), false);
    cellHint_.setSize(n, -1);
    tetHint_.setSize(n);
    label previousPointCell = -1;
    for (label i = 0; i < n; ++i)
    {
        const point p(points(0, i), points(1, i), points(2, i));
        const label celli = findCell(p, cellHint_[i], previousPointCell, localBounds);
        cellHint_[i] = celli;
        previousPointCell = celli;
        if (celli < 0)
        {
            continue;
        }
        const vector u =
            interpU.valid()
          ? interpolateU(*interpU, p, celli, tetHint_[i])
          : U[celli];
        scalar* v = &values[width*i];
        v[0] = u.x();
        v[1] = u.y();
        v[2] = u.z();
        v[3] = cellValue(rho_, celli);
        v[4] = cellValue(mu_, celli);
        v[5] = 1;
    }
    Pstream::listCombineGather(values, plusEqOp<scalar>());
    Pstream::listCombineScatter(values);
    statistics.countCombineGatherScatter(values.byteSize());

    const scalar rhoRef = referenceDensity();
    const scalar muRef = referenceViscosity();
    ::dropletFiber::AirSample air;
    air.velocity.resize(3, n);
    air.density.resize(n);
    air.viscosity.resize(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar* v = &values[width*i];
        const scalar found = v[5];
        if (found > 0)
        {
            air.velocity.col(i) = Eigen::Vector3d(v[0], v[1], v[2])/found;
            air.density(i) = v[3]/found;
            air.viscosity(i) = v[4]/found;
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


void Foam::dropletFiber::airSampler::report(Ostream& os) const
{
    auto describe = [](const source& s)
    {
        return s.fieldName.empty() ? Foam::name(s.value) : "field " + s.fieldName;
    };
    os  << "    air: U field " << UName_ << ", rho " << describe(rho_).c_str()
        << ", mu " << describe(mu_).c_str() << nl;
}

// ************************************************************************* //
