/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The fibers as VTK polylines at write times: velocity, sigma (mass per
    length), captured mass per point, fiberId, with turbulent air u', with
    weighted fibers the physical fibers each represents; per segment
    tension, captured mass and hits (one physical fiber's). In parallel each processor
    writes its piece and the master the .pvtp listing them.

\*---------------------------------------------------------------------------*/

#include "fiberPopulation.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- A processor's piece of the fibers' file, in the directory named as it
Foam::word pieceName(const Foam::label proci)
{
    return "processor" + Foam::name(proci) + ".vtp";
}


//- The arrays of the fibers' pieces (names and components), for the .pvtp
std::vector<::dropletFiber::VtkField> fiberPointFields
(
    const bool turbulent,
    const bool weighted
)
{
    std::vector<::dropletFiber::VtkField> fields
    {
        {"velocity", 3, {}}, {"sigma", 1, {}}, {"capturedMass", 1, {}},
        {"fiberId", 1, {}}
    };
    if (turbulent)
    {
        fields.push_back({"turbulentVelocity", 3, {}});
    }
    if (weighted)
    {
        fields.push_back({"represents", 1, {}});
    }
    return fields;
}


std::vector<::dropletFiber::VtkField> fiberCellFields()
{
    return
    {
        {"tension", 1, {}}, {"segmentCapturedMass", 1, {}},
        {"segmentHits", 1, {}}
    };
}


//- u' of the fiber's points onto field (zero where it has none: immobile
//  fibers, or before its first turbulent step)
void addTurbulentVelocity
(
    const ::dropletFiber::Fiber& fiber,
    ::dropletFiber::VtkField& field
)
{
    const Eigen::Matrix3Xd& u = fiber.state().turbulentVelocity;
    for (Eigen::Index i = 0; i < fiber.pointCount(); ++i)
    {
        for (int c = 0; c < 3; ++c)
        {
            field.values.push_back(u.cols() ? u(c, i) : 0.0);
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::fiberPopulation::writeHeldFibersVtk
(
    const fileName& file,
    const scalar t,
    const bool withTurbulence
) const
{
    // Fibers: points of all fibers one after another, a polyline each
    std::vector<Eigen::Vector3d> points;
    std::vector<std::size_t> offsets;
    ::dropletFiber::VtkField velocity{"velocity", 3, {}};
    ::dropletFiber::VtkField sigma{"sigma", 1, {}};
    ::dropletFiber::VtkField captured{"capturedMass", 1, {}};
    ::dropletFiber::VtkField fiberId{"fiberId", 1, {}};
    ::dropletFiber::VtkField tension{"tension", 1, {}};
    ::dropletFiber::VtkField segmentCaptured{"segmentCapturedMass", 1, {}};
    ::dropletFiber::VtkField segmentHits{"segmentHits", 1, {}};
    ::dropletFiber::VtkField turbulent{"turbulentVelocity", 3, {}};
    ::dropletFiber::VtkField represents{"represents", 1, {}};
    for (std::size_t f = 0; f < held_.size(); ++f)
    {
        addTurbulentVelocity(held_.fibers[f], turbulent);
        const auto& fiber = held_.fibers[f];
        offsets.push_back(points.size());
        const Eigen::VectorXd lineDensity = fiber.lineDensityAtPoints();
        const Eigen::VectorXd& segCaptured = fiber.capturedMassPerSegment();
        for (Eigen::Index i = 0; i < fiber.pointCount(); ++i)
        {
            points.push_back(fiber.positions().col(i));
            for (int c = 0; c < 3; ++c)
            {
                velocity.values.push_back(fiber.velocities()(c, i));
            }
            sigma.values.push_back(lineDensity(i));
            // captured mass a point stands for: half of each neighbour segment
            const double left = i > 0 ? 0.5*segCaptured(i - 1) : 0.0;
            const double right =
                i < fiber.segmentCount() ? 0.5*segCaptured(i) : 0.0;
            captured.values.push_back(left + right);
            fiberId.values.push_back(double(held_.id[f]));
            represents.values.push_back(fiber.represents());
        }
        for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
        {
            tension.values.push_back(fiber.tension()(j));
            segmentCaptured.values.push_back(segCaptured(j));
            segmentHits.values.push_back(fiber.state().segmentHits(j));
        }
    }
    std::vector<::dropletFiber::VtkField> pointFields
    {
        velocity, sigma, captured, fiberId
    };
    if (withTurbulence)
    {
        pointFields.push_back(turbulent);
    }
    if (held_.weighted)
    {
        pointFields.push_back(represents);
    }
    ::dropletFiber::writePolylines
    (
        file, t, points, offsets, pointFields,
        {tension, segmentCaptured, segmentHits}
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberPopulation::writeVtk
(
    const fileName& dir,
    const scalar t,
    ::dropletFiber::SeriesFile& series,
    const bool turbulent
)
{
    const word stem = "fibers_" + time_.timeName();
    if (!Pstream::parRun())
    {
        writeHeldFibersVtk(dir/stem + ".vtp", t, turbulent);
        series.add(stem + ".vtp", t);
        return;
    }
    // Each processor its piece, into the directory named as the .pvtp
    // (made by each: the case directory may be shared or not)
    mkDir(dir/stem);
    writeHeldFibersVtk(dir/stem/pieceName(Pstream::myProcNo()), t, turbulent);
    if (Pstream::master())
    {
        std::vector<std::string> pieces;
        for (label proci = 0; proci < Pstream::nProcs(); ++proci)
        {
            pieces.push_back(stem + "/" + pieceName(proci));
        }
        ::dropletFiber::writeParallelPolylines
        (
            dir/stem + ".pvtp", t, pieces,
            fiberPointFields(turbulent, held_.weighted), fiberCellFields()
        );
        series.add(stem + ".pvtp", t);
    }
}


// ************************************************************************* //
