/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The belt's settings and the laying of the fibers that reached it.
\*---------------------------------------------------------------------------*/

#include "fiberLaydown.H"
#include "dictionaryChecks.H"
#include "dictionaryKeys.H"
#include "plausibility.H"
#include "fiberStateIO.H"
#include "OStringStream.H"
#include "volFields.H"
#include "PstreamReduceOps.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The entries of fibers.laydown (docs/reference.md)
const Foam::wordList laydownKeys
{
    "patch", "point", "normal", "width", "velocity", "cell", "footprint",
    "populations", "steadyFrom"
};

//- Values per laid fiber in the exchange
constexpr Foam::label laidWidth = 15;

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::fiberLaydown::beltFromPatch
(
    const dictionary& dict,
    scalar& acrossMin,
    scalar& acrossMax
)
{
    const word patchName = dict.get<word>("patch");
    const label patchi = mesh_.boundaryMesh().findPatchID(patchName);
    if (patchi < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'patch' names patch '" << patchName << "', which does"
            << " not exist: allowed are the mesh's patches "
            << mesh_.boundaryMesh().names() << exit(FatalIOError);
    }
    const polyPatch& pp = mesh_.boundaryMesh()[patchi];
    const scalar area = gSum(mag(pp.faceAreas()));
    if (!(area > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'patch' names patch '" << patchName << "', which has"
            << " no faces: the belt needs a planar patch with faces."
            << exit(FatalIOError);
    }
    const vector areaSum = gSum(pp.faceAreas());
    if (mag(areaSum) < 0.5*area)
    {
        // Faces facing opposite ways (the two walls of a channel): no plane
        FatalIOErrorInFunction(dict)
            << "Entry 'patch' names patch '" << patchName << "', which is not"
            << " planar: its faces face different ways (the sum of their"
            << " area vectors is " << mag(areaSum)/area << " of their area)."
            << nl << "    Give the belt as point, normal and width instead."
            << exit(FatalIOError);
    }
    belt_.point = toEigen(gSum(pp.faceCentres()*mag(pp.faceAreas()))/area);
    belt_.normal = toEigen(areaSum/mag(areaSum));
    // Planar: every face centre on the mean plane, to 1e-6 of the patch's size
    scalar offPlane = 0;
    for (const point& c : pp.faceCentres())
    {
        offPlane =
            max(offPlane, mag(toEigen(c).dot(belt_.normal) - belt_.point.dot(belt_.normal)));
    }
    offPlane = returnReduce(offPlane, maxOp<scalar>());
    const scalar size = Foam::sqrt(area);
    if (offPlane > 1e-6*size)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'patch' names patch '" << patchName << "', which is not"
            << " planar: its faces lie up to " << offPlane << " m off their"
            << " mean plane (allowed: 1e-6 of its size " << size << " m)."
            << nl << "    Give the belt as point, normal and width instead."
            << exit(FatalIOError);
    }
    // The width: the patch's points across the belt
    const Eigen::Vector3d across = belt_.acrossDirection();
    acrossMin = GREAT;
    acrossMax = -GREAT;
    for (const point& p : pp.localPoints())
    {
        const scalar a = (toEigen(p) - belt_.point).dot(across);
        acrossMin = min(acrossMin, a);
        acrossMax = max(acrossMax, a);
    }
    reduce(acrossMin, minOp<scalar>());
    reduce(acrossMax, maxOp<scalar>());
}


void Foam::dropletFiber::fiberLaydown::beltFromPlane
(
    const dictionary& dict,
    scalar& acrossMin,
    scalar& acrossMax
)
{
    const vector normal = dict.get<vector>("normal");
    if (!(mag(normal) > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'normal' is " << normal << ": allowed are non-zero"
            << " vectors (out of the air, through the belt)."
            << exit(FatalIOError);
    }
    belt_.point = toEigen(dict.get<vector>("point"));
    belt_.normal = toEigen(normal/mag(normal));
    const scalar width = getPositive(dict, "width");
    acrossMin = -0.5*width;
    acrossMax = 0.5*width;
}


std::vector<::dropletFiber::LaidFiber>
Foam::dropletFiber::fiberLaydown::gathered
(
    const std::vector<::dropletFiber::LaidFiber>& here
)
{
    List<List<scalar>> all(Pstream::nProcs());
    List<scalar>& mine = all[Pstream::myProcNo()];
    mine.setSize(laidWidth*label(here.size()));
    label k = 0;
    for (const ::dropletFiber::LaidFiber& f : here)
    {
        const scalar values[laidWidth] =
        {
            f.time, f.across, f.along, f.orientation.x(), f.orientation.y(),
            f.orientation.z(), f.length, f.glassMass, f.binderMass,
            f.represents, f.bareFraction, f.sigmaVariation, scalar(f.id),
            f.endToEnd, f.spread
        };
        for (const scalar v : values)
        {
            mine[k++] = v;
        }
    }
    if (Pstream::parRun())
    {
        Pstream::gatherList(all);
        Pstream::scatterList(all);
    }
    std::vector<::dropletFiber::LaidFiber> laid;
    for (const List<scalar>& values : all)
    {
        for (label i = 0; i + laidWidth <= values.size(); i += laidWidth)
        {
            const scalar* v = &values[i];
            ::dropletFiber::LaidFiber f;
            f.time = v[0];
            f.across = v[1];
            f.along = v[2];
            f.orientation = Eigen::Vector3d(v[3], v[4], v[5]);
            f.length = v[6];
            f.glassMass = v[7];
            f.binderMass = v[8];
            f.represents = v[9];
            f.bareFraction = v[10];
            f.sigmaVariation = v[11];
            f.id = long(std::llround(v[12]));
            f.endToEnd = v[13];
            f.spread = v[14];
            laid.push_back(f);
        }
    }
    // In birth order whatever the decomposition: the map's sums the same bits
    std::stable_sort
    (
        laid.begin(), laid.end(),
        [](const ::dropletFiber::LaidFiber& a, const ::dropletFiber::LaidFiber& b)
        {
            return a.id < b.id;
        }
    );
    return laid;
}


std::pair<long, long> Foam::dropletFiber::fiberLaydown::completeRows() const
{
    if (totals_.zone.firstTime < 0 || map_->cells().empty())
    {
        return {1, 0};
    }
    if (!(belt_.speed() > 0))
    {
        // At rest: the whole deposit is the mat (the cells are in column order)
        long first = map_->cells().begin()->first.second, last = first;
        for (const auto& entry : map_->cells())
        {
            first = std::min(first, entry.first.second);
            last = std::max(last, entry.first.second);
        }
        return {first, last};
    }
    return totals_.zone.completeRows
    (
        belt_.speed(), map_->cell(), steadyFrom_, time_.value()
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::fiberLaydown::fiberLaydown
(
    const functionObject& owner,
    const fvMesh& mesh
)
:
    couplingStage(owner, mesh),
    writeFile(mesh, owner.name(), "laydown", false),
    on_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberLaydown::read
(
    const dictionary& fibersDict,
    const bool running,
    const label tablePrecision
)
{
    writePrecision_ = tablePrecision;
    const dictionary* ld = findSubDict(fibersDict, "laydown");
    if (running)
    {
        OStringStream was, now;
        if (on_)
        {
            was << settings_;
        }
        if (ld)
        {
            now << *ld;
        }
        if ((ld != nullptr) != on_ || was.str() != now.str())
        {
            FatalIOErrorInFunction(fibersDict)
                << "Entry 'fibers.laydown' was edited during the run: the mat"
                << " laid so far is on the belt in force." << nl
                << "    Start a new run for it; the results written so far"
                << " are kept." << exit(FatalIOError);
        }
        return;
    }
    on_ = ld != nullptr;
    if (!on_)
    {
        return;
    }
    settings_ = *ld;
    checkKeys(*ld, laydownKeys);
    const scalar cell = getPositive(*ld, "cell");
    // P58: along its length, or whole in its centre's cell (the map before P58)
    footprintAtCentre_ =
        getChoice(*ld, "footprint", "length", {"length", "centre"}) == "centre";
    // P59: a weighted fiber's population over its hat, or on its line
    populationsOnLine_ =
        getChoice(*ld, "populations", "spread", {"spread", "line"}) == "line";
    steadyFrom_ =
        ld->found("steadyFrom")
      ? getCheckedScalar
        (
            *ld, "steadyFrom", nullptr, [](scalar v) { return v >= 0; },
            ">= 0 [s] (the time from which the laying is steady)"
        )
      : -1;
    if (steadyFrom_ >= time_.endTime().value())
    {
        IOWarningInFunction(*ld)
            << "Entry 'steadyFrom' is " << steadyFrom_ << " s, not before the"
            << " run's endTime " << time_.endTime().value() << " s: no row of"
            << " the mat will be complete (the log and matProfile give none)."
            << endl;
    }
    scalar acrossMin = 0, acrossMax = 0;
    readBelt(*ld, acrossMin, acrossMax);
    checkBeltGeometry(*ld, cell, acrossMax - acrossMin);
    map_.reset(new ::dropletFiber::MatMap(cell, acrossMin, acrossMax));
    const fileName dir =
        baseFileDir()/name()/time_.timeName(time_.startTime().value());
    series_.reset(new ::dropletFiber::SeriesFile(dir/"mat.vti.series"));
    if (Pstream::master())
    {
        series_->load(time_.value() + 0.5*time_.deltaTValue());
    }
}


void Foam::dropletFiber::fiberLaydown::readBelt
(
    const dictionary& ld,
    scalar& acrossMin,
    scalar& acrossMax
)
{
    const bool plane = ld.found("point") || ld.found("normal");
    if (ld.found("patch") == plane)
    {
        FatalIOErrorInFunction(ld)
            << "Entry 'laydown' needs the belt as 'patch', or as 'point',"
            << " 'normal' and 'width'"
            << (plane ? ", not both." : ".") << exit(FatalIOError);
    }
    if (!plane && ld.found("width"))
    {
        FatalIOErrorInFunction(ld)
            << "Entry 'width' is for a belt given as point and normal: with"
            << " 'patch' the belt's width is the patch's extent across it."
            << exit(FatalIOError);
    }
    belt_.velocity = toEigen(ld.lookupOrDefault<vector>("velocity", Zero));
    if (plane)
    {
        beltFromPlane(ld, acrossMin, acrossMax);
    }
    else
    {
        beltFromPatch(ld, acrossMin, acrossMax);
    }
    const scalar offPlane = mag(belt_.velocity.dot(belt_.normal));
    if (offPlane > 1e-9*max(1.0, belt_.velocity.norm()))
    {
        FatalIOErrorInFunction(ld)
            << "Entry 'velocity' is " << ld.get<vector>("velocity")
            << ", which leaves the belt's plane (normal "
            << toFoam(belt_.normal) << ") at " << offPlane << " m/s:"
            << " allowed are velocities in the plane." << exit(FatalIOError);
    }
}


void Foam::dropletFiber::fiberLaydown::checkBeltGeometry
(
    const dictionary& ld,
    const scalar cell,
    const scalar width
) const
{
    // The air is the mesh: its volume's centre must lie on the side the
    // normal points away from, else every fiber is laid when born
    const scalarField& V = mesh_.V().field();
    const vectorField& C = mesh_.C().primitiveField();
    vector moment(Zero);
    scalar volume = 0;
    forAll(V, i)
    {
        moment += V[i]*C[i];
        volume += V[i];
    }
    reduce(moment, sumOp<vector>());
    reduce(volume, sumOp<scalar>());
    const vector n = toFoam(belt_.normal);
    const point p = toFoam(belt_.point);
    const scalar airSide = ((moment/max(volume, VSMALL)) - p) & n;
    if (airSide >= 0)
    {
        FatalIOErrorInFunction(ld)
            << "Entry 'normal' " << n << ": the belt's normal points into"
            << " the air (the mesh's centre lies " << airSide << " m on its"
            << " side of the plane through " << p << "): every fiber would be"
            << " laid the moment it is born." << nl
            << "    Allowed: a normal pointing out of the air, through the"
            << " belt (here " << -n << ")." << exit(FatalIOError);
    }
    // A unit slip of the speed runs, warned once (a belt at rest is allowed)
    const scalar speed = belt_.velocity.norm();
    const string slip = implausible(speed, beltSpeedRange);
    if (speed > 0 && !slip.empty())
    {
        IOWarningInFunction(ld)
            << "Entry 'velocity': the belt's speed " << slip.c_str() << endl;
    }
    // The plane must meet the mesh's bounds: beyond them no fiber reaches it
    scalar nearest = -GREAT;
    const pointField corners(mesh_.bounds().points());
    for (const point& corner : corners)
    {
        nearest = max(nearest, (corner - p) & n);
    }
    if (nearest < 0)
    {
        WarningInFunction
            << type() << " " << name() << ": fibers.laydown: the belt's plane"
            << " through " << p << " lies " << -nearest << " m beyond the"
            << " mesh's bounds: no fiber reaches it; they leave the mesh's"
            << " bounding box first and none is laid." << endl;
    }
    if (cell >= width)
    {
        FatalIOErrorInFunction(ld)
            << "Entry 'cell' is " << cell << " m, not smaller than the belt's"
            << " width " << width << " m: the map would hold one column, with"
            << " no profile across the belt." << nl
            << "    Allowed: 0 < cell < " << width << " m (a few fiber lengths"
            << " or less)." << exit(FatalIOError);
    }
}


Foam::labelList Foam::dropletFiber::fiberLaydown::layDown
(
    const heldFibers& held
)
{
    if (!on_)
    {
        return labelList();
    }
    std::vector<::dropletFiber::LaidFiber> here;
    DynamicList<label> reached;
    const scalar t = time_.value();
    for (std::size_t f = 0; f < held.fibers.size(); ++f)
    {
        const ::dropletFiber::Fiber& fiber = held.fibers[f];
        if (::dropletFiber::reachesBelt(fiber, belt_))
        {
            here.push_back(::dropletFiber::layFiber(fiber, belt_, t, held.id[f]));
            if (populationsOnLine_)
            {
                here.back().spread = 0;
            }
            reached.append(label(f));
        }
    }
    const std::vector<::dropletFiber::LaidFiber> laid = gathered(here);
    for (const ::dropletFiber::LaidFiber& f : laid)
    {
        const ::dropletFiber::LaidFiber onMap =
            footprintAtCentre_ ? ::dropletFiber::wholeAtCentre(f) : f;
        map_->add(onMap);
        totals_.computed += 1;
        totals_.physical += f.represents;
        totals_.glass += f.represents*f.glassMass;
        totals_.binder += f.represents*f.binderMass;
        totals_.zone.add(onMap, belt_.speed());
    }
    writeRows(laid);
    labelList laidHere;
    laidHere.transfer(reached);
    return laidHere;
}


void Foam::dropletFiber::fiberLaydown::report(Ostream& os) const
{
    os  << "    laydown: ";
    if (!on_)
    {
        os  << "none (fibers leave through the mesh's bounding box)" << nl;
        return;
    }
    os  << "belt through " << toFoam(belt_.point) << ", normal "
        << toFoam(belt_.normal) << ", velocity "
        << toFoam(belt_.velocity) << " m/s, across "
        << map_->acrossMin() << " to " << map_->acrossMax() << " m, map cells "
        << map_->cell() << " m; fibers "
        << (footprintAtCentre_ ? "whole at their centres" : "along their length (P58)")
        << "; populations "
        << (populationsOnLine_ ? "on their fibers' lines" : "spread (P59)")
        << "; complete rows entered the laying zone after ";
    if (steadyFrom_ >= 0)
    {
        os  << "steadyFrom " << steadyFrom_ << " s" << nl;
    }
    else
    {
        os  << "the first fiber was laid" << nl;
    }
}


//- The entries of fibers the belt reads (laydown's own: laydownKeys)
static const Foam::wordList beltKeys
{
    "laydown"
};


Foam::wordList Foam::dropletFiber::fiberLaydown::fibersEntries()
{
    return beltKeys;
}


// ************************************************************************* //
