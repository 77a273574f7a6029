/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fiberStateIO.H"

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

::dropletFiber::EndCondition endFromDict(const dictionary& d)
{
    ::dropletFiber::EndCondition end;
    const word type = d.get<word>("type");
    end.type =
        type == "free" ? ::dropletFiber::EndType::free
      : type == "pinned" ? ::dropletFiber::EndType::pinned
      : ::dropletFiber::EndType::clamped;
    const scalarList v = d.get<scalarList>("anchorVelocity");
    const scalarList c = d.get<scalarList>("clampDirection");
    end.anchorVelocity = Eigen::Vector3d(v[0], v[1], v[2]);
    end.clampDirection = Eigen::Vector3d(c[0], c[1], c[2]);
    return end;
}

template<class EigenType>
void readInto(const dictionary& d, const word& key, EigenType& m, const label rows)
{
    const scalarList values = d.get<scalarList>(key);
    if (values.size() % rows != 0)
    {
        FatalIOErrorInFunction(d)
            << "Entry '" << key << "' has " << values.size()
            << " values, not a multiple of " << rows << exit(FatalIOError);
    }
    m.resize(rows, values.size()/rows);
    std::copy(values.begin(), values.end(), m.data());
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
    return d;
}


::dropletFiber::FiberState Foam::dropletFiber::fiberStateFromDict
(
    const dictionary& d
)
{
    ::dropletFiber::FiberState s;
    s.material.radius = d.get<scalar>("radius");
    s.material.density = d.get<scalar>("density");
    s.material.youngsModulus = d.get<scalar>("youngsModulus");
    s.immobile = d.get<bool>("immobile");
    s.startEnd = endFromDict(d.subDict("startEnd"));
    s.endEnd = endFromDict(d.subDict("endEnd"));
    readInto(d, "positions", s.positions, 3);
    readInto(d, "velocities", s.velocities, 3);
    readInto(d, "externalForce", s.externalForce, 3);
    Eigen::Matrix<double, 1, Eigen::Dynamic> row;
    readInto(d, "restLengths", row, 1);
    s.restLengths = row.transpose();
    readInto(d, "capturedMass", row, 1);
    s.segmentCapturedMass = row.transpose();
    readInto(d, "tension", row, 1);
    s.tension = row.transpose();
    return s;
}

// ************************************************************************* //
