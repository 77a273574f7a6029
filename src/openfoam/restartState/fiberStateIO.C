/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fiberStateIO.H"
#include "dictionaryChecks.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

dictionary endDict(const ::dropletFiber::EndCondition& end)
{
    dictionary d;
    const word type =
        end.type == ::dropletFiber::EndType::free ? "free"
      : end.type == ::dropletFiber::EndType::pinned ? "pinned"
      : "clamped";
    d.add("type", type);
    d.add("anchorVelocity", Foam::dropletFiber::toScalarList(end.anchorVelocity.data(), 3));
    d.add("clampDirection", Foam::dropletFiber::toScalarList(end.clampDirection.data(), 3));
    return d;
}

//- Entry key of d: a list of finite values, size values if size >= 0, else
//  a non-empty multiple of 3; each allowed(value) (allowedText says what)
template<class Predicate>
scalarList checkedList
(
    const dictionary& d,
    const word& key,
    const label size,
    Predicate allowed,
    const char* allowedText
)
{
    const scalarList values = d.get<scalarList>(key);
    if (size >= 0 ? values.size() != size : values.empty() || values.size() % 3)
    {
        FatalIOErrorInFunction(d)
            << "Entry '" << key << "' has " << values.size() << " values: "
            << "expected " << (size >= 0 ? Foam::name(size) : word("3 per point"))
            << " (positions and velocities: 3 per point, segment entries:"
            << " one per segment, points - 1)." << exit(FatalIOError);
    }
    forAll(values, i)
    {
        if (!std::isfinite(values[i]) || !allowed(values[i]))
        {
            FatalIOErrorInFunction(d)
                << "Entry '" << key << "': value " << i << " is " << values[i]
                << ": allowed are finite values" << allowedText << "."
                << exit(FatalIOError);
        }
    }
    return values;
}

bool anyValue(scalar)
{
    return true;
}

template<class EigenType>
void readInto
(
    const dictionary& d,
    const word& key,
    EigenType& m,
    const label rows,
    const label cols
)
{
    const scalarList values = checkedList(d, key, rows*cols, anyValue, "");
    m.resize(rows, cols);
    std::copy(values.begin(), values.end(), m.data());
}

::dropletFiber::EndCondition endFromDict(const dictionary& d)
{
    ::dropletFiber::EndCondition end;
    const word type =
        Foam::dropletFiber::getChoice(d, "type", "", {"free", "pinned", "clamped"});
    end.type =
        type == "free" ? ::dropletFiber::EndType::free
      : type == "pinned" ? ::dropletFiber::EndType::pinned
      : ::dropletFiber::EndType::clamped;
    readInto(d, "anchorVelocity", end.anchorVelocity, 3, 1);
    readInto(d, "clampDirection", end.clampDirection, 3, 1);
    return end;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::scalarList Foam::dropletFiber::toScalarList(const double* data, const label n)
{
    scalarList list(n);
    std::copy(data, data + n, list.begin());
    return list;
}


Foam::scalarList Foam::dropletFiber::toScalarList(const std::vector<double>& v)
{
    return toScalarList(v.data(), label(v.size()));
}


std::vector<double> Foam::dropletFiber::toStdVector(const scalarList& list)
{
    return std::vector<double>(list.begin(), list.end());
}


Foam::dictionary Foam::dropletFiber::fiberStateDict
(
    const ::dropletFiber::FiberState& s
)
{
    dictionary d;
    d.add("radius", s.material.radius);
    d.add("density", s.material.density);
    d.add("youngsModulus", s.material.youngsModulus);
    d.add("immobile", s.immobile);
    // Weighted fibers only: a state of fibers that stand for one each is
    // that of a run without weights
    if (s.represents != 1)
    {
        d.add("represents", s.represents);
    }
    // A weighted fiber's population's last spread (P59); absent: none
    if (s.populationSpread != 0)
    {
        d.add("populationSpread", s.populationSpread);
    }
    d.add("startEnd", endDict(s.startEnd));
    d.add("endEnd", endDict(s.endEnd));
    d.add("positions", toScalarList(s.positions.data(), s.positions.size()));
    d.add("velocities", toScalarList(s.velocities.data(), s.velocities.size()));
    d.add("restLengths", toScalarList(s.restLengths.data(), s.restLengths.size()));
    // Keyword capturedMass (per segment): kept so that existing restart
    // files load
    d.add
    (
        "capturedMass",
        toScalarList(s.segmentCapturedMass.data(), s.segmentCapturedMass.size())
    );
    d.add("tension", toScalarList(s.tension.data(), s.tension.size()));
    d.add
    (
        "externalForce",
        toScalarList(s.externalForce.data(), s.externalForce.size())
    );
    // Droplets caught per segment (the binder distribution output)
    d.add
    (
        "segmentHits",
        toScalarList(s.segmentHits.data(), s.segmentHits.size())
    );
    // The expected mode's mass per segment (the binder table of both modes)
    d.add
    (
        "segmentExpectedMass",
        toScalarList
        (
            s.segmentExpectedMass.data(), s.segmentExpectedMass.size()
        )
    );
    // The turbulent fluctuation (docs/model.md sec. 8), when the fiber has
    // one: a restart continues its realisation
    if (s.turbulentVelocity.cols())
    {
        d.add
        (
            "turbulentVelocity",
            toScalarList(s.turbulentVelocity.data(), s.turbulentVelocity.size())
        );
    }
    return d;
}


::dropletFiber::FiberState Foam::dropletFiber::fiberStateFromDict
(
    const dictionary& d
)
{
    // Every value checked here, naming the entry: the core's own checks
    // (Fiber::validate) do not see NaN and name no file
    ::dropletFiber::FiberState s;
    s.material.radius = getPositive(d, "radius");
    s.material.density = getPositive(d, "density");
    s.material.youngsModulus = getCheckedScalar
    (
        d, "youngsModulus", nullptr, [](scalar v) { return v >= 0; }, ">= 0"
    );
    s.immobile = d.get<bool>("immobile");
    s.represents = getCheckedScalar
    (
        d, "represents", &s.represents,
        [](scalar v) { return v > 0; }, "> 0"
    );
    s.populationSpread = getCheckedScalar
    (
        d, "populationSpread", &s.populationSpread,
        [](scalar v) { return v >= 0; }, ">= 0"
    );
    s.startEnd = endFromDict(d.subDict("startEnd"));
    s.endEnd = endFromDict(d.subDict("endEnd"));
    const label points =
        checkedList(d, "positions", -1, anyValue, "").size()/3;
    readInto(d, "positions", s.positions, 3, points);
    readInto(d, "velocities", s.velocities, 3, points);
    readInto(d, "externalForce", s.externalForce, 3, points);
    const label segments = points - 1;
    Eigen::Matrix<double, 1, Eigen::Dynamic> row;
    const scalarList restLengths = checkedList
    (
        d, "restLengths", segments, [](scalar v) { return v > 0; }, " > 0"
    );
    s.restLengths = Eigen::Map<const Eigen::VectorXd>(restLengths.cdata(), segments);
    const scalarList captured = checkedList
    (
        d, "capturedMass", segments, [](scalar v) { return v >= 0; }, " >= 0"
    );
    s.segmentCapturedMass = Eigen::Map<const Eigen::VectorXd>(captured.cdata(), segments);
    readInto(d, "tension", row, 1, segments);
    s.tension = row.transpose();
    // Optional: states written before the hits were counted read as none
    if (d.found("segmentHits"))
    {
        const scalarList hits = checkedList
        (
            d, "segmentHits", segments, [](scalar v) { return v >= 0; }, " >= 0"
        );
        s.segmentHits = Eigen::Map<const Eigen::VectorXd>(hits.cdata(), segments);
    }
    // Optional: states written before it was kept read as the captured mass
    if (d.found("segmentExpectedMass"))
    {
        const scalarList expected = checkedList
        (
            d, "segmentExpectedMass", segments,
            [](scalar v) { return v >= 0; }, " >= 0"
        );
        s.segmentExpectedMass =
            Eigen::Map<const Eigen::VectorXd>(expected.cdata(), segments);
    }
    // Optional: states written without turbulent air have none
    if (d.found("turbulentVelocity"))
    {
        readInto(d, "turbulentVelocity", s.turbulentVelocity, 3, points);
    }
    return s;
}

// ************************************************************************* //
