/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Output of dropletFiberCollision: the per-step table, the log and the VTK
    files (the restart state: dropletFiberCollisionRestart.C).

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "dictionaryChecks.H"
#include "Time.H"
#include "fvMesh.H"
#include "OFstream.H"
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
std::vector<::dropletFiber::VtkField> fiberPointFields(const bool turbulent)
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

void Foam::functionObjects::dropletFiberCollision::writeFileHeader
(
    Ostream& os
) const
{
    writeHeader(os, "Droplet-fiber coupling, per time step (masses in kg, times in s)");
    writeCommented(os, "Time");
    for
    (
        const char* column :
        {
            "fibers", "parcels", "droplets", "parcelMass", "massOnGrid", "massOutsideGrid",
            "capturedStep", "capturedTotal", "fiberMass",
            "maxSegmentLengthError"
        }
    )
    {
        writeTabbed(os, column);
    }
    // Depletion's binder balance: eq. 9 before the limit, the mass taken
    // from the parcels (= capturedStep), the parcel mass flying on
    if (depletion_)
    {
        for (const char* column : {"demandedStep", "removedStep", "airborneMass"})
        {
            writeTabbed(os, column);
        }
        // The clouds' own figures (sprayed = airborne + evaporated +
        // escaped + capturedTotal) and the captured mass per liquid species
        for (const char* column : {"sprayedMass", "evaporatedMass", "escapedMass"})
        {
            writeTabbed(os, column);
        }
        for (const word& species : liquidSpecies_)
        {
            writeTabbed(os, "captured_" + species);
        }
    }
    // One stage each: gather and deposit; collision (and depletion's
    // removal); the fibers' injection, step and hand-over
    writeTabbed(os, "wallTimeDeposition");
    writeTabbed(os, "wallTimeCollision");
    writeTabbed(os, "wallTimeFibers");
    os  << endl;
}


void Foam::functionObjects::dropletFiberCollision::reportStep
(
    const stepSummary& step
)
{
    // Over all processors (collective: before the master's writing)
    const label fibers = fiberCount();
    const scalar mass = fiberMass();
    if (depletion_)
    {
        readCloudMassReport();
    }
    Log << type() << " " << name() << ": parcels " << step.parcels
        << ", fibers " << fibers
        << ", captured " << step.capturedStep << " kg (total "
        << totals_.captured << " kg), segment-length error "
        << step.maxSegmentLengthError << ", sub-steps " << step.subSteps;
    if (depletion_)
    {
        Log << ", removed from the parcels " << depletionStep_.removed
            << " kg, airborne " << depletionStep_.airborne << " kg";
    }
    Log << endl;

    if (writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << fibers
            << tab << step.parcels
            << tab << step.droplets
            << tab << step.deposit.massIn
            << tab << step.deposit.massDeposited
            << tab << step.deposit.massOutside
            << tab << step.capturedStep
            << tab << totals_.captured
            << tab << mass
            << tab << step.maxSegmentLengthError;
        if (depletion_)
        {
            os  << tab << depletionStep_.demanded
                << tab << depletionStep_.removed
                << tab << depletionStep_.airborne
                << tab << cloudMass_.sprayed
                << tab << cloudMass_.evaporated
                << tab << cloudMass_.escaped;
            for (const scalar captured : capturedSpecies_)
            {
                os  << tab << captured;
            }
        }
        os  << tab << step.depositionTime
            << tab << step.collisionTime
            << tab << step.fiberTime
            << endl;
    }
    // With turbulent air, the fibers' dispersion (collective)
    writeFiberDispersion();
}


void Foam::functionObjects::dropletFiberCollision::writeParallelStatistics()
{
    // The grid nodes this processor stores (its block) and the fibers it
    // holds
    parallelStatistics_.holding(grid_->storageBox().nodeCount(), held_.size());
    const dropletFiber::parallelStatistics::spread all =
        parallelStatistics_.overProcessors();
    // Also in a serial run (one processor: sends nothing, max = mean), the
    // reference of the work per processor
    if (!writeToFile())
    {
        return;
    }
    if (!parallelStatisticsFile_.valid())
    {
        parallelStatisticsFile_ = createFile("parallelStatistics");
        writeParallelStatisticsHeader(parallelStatisticsFile_());
    }
    OFstream& os = parallelStatisticsFile_();
    const dropletFiber::parallelStatistics::figures& maxima = all.maxima;
    writeCurrentTime(os);
    os  << tab << maxima.nodesHeld
        << tab << maxima.fibersHeld
        << tab << maxima.bytesSent
        << tab << maxima.bytesParcels
        << tab << maxima.bytesGridQueries
        << tab << maxima.bytesFibers;
    for (label i = 0; i < dropletFiber::parallelStatistics::work::size; ++i)
    {
        os  << tab << all.maxWork[i] << tab << all.meanWork[i];
    }
    os  << endl;
}


void Foam::functionObjects::dropletFiberCollision::writeParallelStatisticsHeader
(
    OFstream& os
)
{
    writeHeader
    (
        os,
        "Per time step, maxima over processors; the work (parcels to"
        " cpuFibers, thread CPU time in s) as maximum and mean"
    );
    writeCommented(os, "Time");
    writeTabbed(os, "nodesHeldMax");
    writeTabbed(os, "fibersHeldMax");
    writeTabbed(os, "bytesSentMax");
    writeTabbed(os, "bytesParcelsMax");
    writeTabbed(os, "bytesGridQueriesMax");
    writeTabbed(os, "bytesFibersMax");
    // In the order of parallelStatistics::work::operator[]
    for
    (
        const char* figure :
        {
            "parcels", "parcelCopies", "nodeWeights", "collisionSamples",
            "fiberPoints", "cpuDeposit", "cpuCollision", "cpuFibers"
        }
    )
    {
        writeTabbed(os, word(figure) + "Max");
        writeTabbed(os, word(figure) + "Mean");
    }
    os  << endl;
}


void Foam::functionObjects::dropletFiberCollision::reportConservation() const
{
    const scalar mass = fiberMass();
    const scalar balance =
        totals_.fiberMassAdded + totals_.captured
      - totals_.fiberMassRemoved - mass;
    Info<< type() << " " << name() << " conservation at time "
        << time_.timeName() << ", summed over all steps so far:" << nl
        << "    parcel mass " << totals_.parcelMass << " kg = on grid "
        << totals_.deposited << " + outside it " << totals_.outside
        << " (balance "
        << totals_.parcelMass - totals_.deposited - totals_.outside
        << " kg)" << nl
        << "    fiber mass " << mass << " kg = added "
        << totals_.fiberMassAdded << " + captured " << totals_.captured
        << " - removed " << totals_.fiberMassRemoved
        << " (balance " << balance << " kg)" << nl
        << "    parcel-steps with the influence radius capped at rMaxCap: "
        << totals_.parcelsCapped << nl << endl;
}


void Foam::functionObjects::dropletFiberCollision::writeVtkFiles()
{
    if (!writeVtk_ && !writeGridVtk_)
    {
        return;
    }
    const fileName dir =
        baseFileDir()/name()/time_.timeName(time_.startTime().value());
    if (Pstream::master())
    {
        mkDir(dir);
    }
    // The time folder's name as the files' time: 0.3, not the sum of the
    // steps (0.30000000000000004)
    const scalar t = readScalar(time_.timeName());

    // Both collective in parallel: every processor writes its piece (its
    // fibers, its block of the grid), the master the index of the pieces
    if (writeVtk_)
    {
        writeFibersVtk(dir, t);
    }
    if (writeGridVtk_)
    {
        writeGridVtk(dir, t);
    }
}


void Foam::functionObjects::dropletFiberCollision::writeFibersVtk
(
    const fileName& dir,
    const scalar t
)
{
    const word stem = "fibers_" + time_.timeName();
    if (!Pstream::parRun())
    {
        writeHeldFibersVtk(dir/stem + ".vtp", t);
        fibersSeries_->add(stem + ".vtp", t);
        return;
    }
    // Each processor its piece, into the directory named as the .pvtp
    // (made by each: the case directory may be shared or not)
    mkDir(dir/stem);
    writeHeldFibersVtk(dir/stem/pieceName(Pstream::myProcNo()), t);
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
            fiberPointFields(turbulenceWritten()), fiberCellFields()
        );
        fibersSeries_->add(stem + ".pvtp", t);
    }
}


void Foam::functionObjects::dropletFiberCollision::writeHeldFibersVtk
(
    const fileName& file,
    const scalar t
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
    if (turbulenceWritten())
    {
        pointFields.push_back(turbulent);
    }
    ::dropletFiber::writePolylines
    (
        file, t, points, offsets, pointFields,
        {tension, segmentCaptured, segmentHits}
    );
}


std::vector<::dropletFiber::VtkField>
Foam::functionObjects::dropletFiberCollision::gridFields
(
    const ::dropletFiber::IndexBox& box
)
{
    const ::dropletFiber::DensityGrid& grid = *grid_;
    const auto& g = gridSettings_.spec;
    std::vector<std::size_t> nodes;
    nodes.reserve(box.nodeCount());
    ::dropletFiber::forEachRow
    (
        box, g.nodes,
        [&nodes](const ::dropletFiber::IndexRow& row)
        {
            for (std::size_t i = 0; i < row.length; ++i)
            {
                nodes.push_back(row.first + i);
            }
        }
    );
    // One pass over the window's slots, row by row, brings the sums of every
    // owned node up to date; the per-node reads below then copy them (summed
    // node by node, each node's W slots miss the cache: ~50 ms per write of
    // the spray3D grid against ~5 ms). The same additions in the same order.
    grid.windowTotals();
    // Serial: every node is owned here, nothing is exchanged
    std::vector<double> totals;
    blocks_->windowTotals(grid, nodes, totals, parallelStatistics_);
    const std::size_t n = nodes.size();
    ::dropletFiber::VtkField rho{"rho", 1, std::vector<double>(n)};
    ::dropletFiber::VtkField rNumber{"rMeanNumber", 1, std::vector<double>(n)};
    ::dropletFiber::VtkField rMass{"rMeanMass", 1, std::vector<double>(n)};
    ::dropletFiber::VtkField U{"U", 3, std::vector<double>(3*n)};
    for (std::size_t k = 0; k < n; ++k)
    {
        const ::dropletFiber::DropletFieldValue v =
            grid.nodeValueFromTotals
            (
                nodes[k], totals.data() + k*::dropletFiber::nQuantities
            );
        rho.values[k] = v.rho;
        rNumber.values[k] = v.rMeanNumber;
        rMass.values[k] = v.rMeanMass;
        for (int c = 0; c < 3; ++c)
        {
            U.values[3*k + c] = v.velocity(c);
        }
    }
    std::vector<::dropletFiber::VtkField> fields;
    fields.reserve(4);
    for (::dropletFiber::VtkField* field : {&rho, &rNumber, &rMass, &U})
    {
        fields.push_back(std::move(*field));
    }
    return fields;
}


void Foam::functionObjects::dropletFiberCollision::writeGridVtk
(
    const fileName& dir,
    const scalar t
)
{
    const auto& g = gridSettings_.spec;
    Eigen::Vector3d origin, spacing;
    for (int d = 0; d < 3; ++d)
    {
        origin(d) = g.nodeCoordinate(d, 0);
        spacing(d) = g.spacing(d);  // a flat direction: its thickness
    }
    const word file = "grid_" + time_.timeName() + ".vti";
    if (!Pstream::parRun())
    {
        ::dropletFiber::writeImageData
        (
            dir/file, t, origin, spacing, g.nodes, gridFields(g.fullBox())
        );
        gridSeries_->add(file, t);
        return;
    }
    // A piece per processor: its owned nodes and the layer above them (owned
    // by the next processor), so that the pieces' cells tile the grid
    const auto pieceBox = [&g](const ::dropletFiber::IndexBox& owned)
    {
        ::dropletFiber::IndexBox box = owned;
        for (int d = 0; d < 3; ++d)
        {
            box.hi[d] = std::min(owned.hi[d] + 1, g.nodes[d] - 1);
        }
        return box;
    };
    const auto extent = [](const ::dropletFiber::IndexBox& box)
    {
        return ::dropletFiber::VtkExtent
        {{box.lo[0], box.hi[0], box.lo[1], box.hi[1], box.lo[2], box.hi[2]}};
    };
    const auto pieceFile = [this](const label proci)
    {
        return word("grid_" + time_.timeName() + "_" + Foam::name(proci) + ".vti");
    };
    const ::dropletFiber::IndexBox mine = pieceBox(grid_->ownedBox());
    const std::vector<::dropletFiber::VtkField> fields = gridFields(mine);
    ::dropletFiber::writeImageDataPiece
    (
        dir/pieceFile(Pstream::myProcNo()), t, origin, spacing, extent(mine), fields
    );
    if (Pstream::master())
    {
        std::vector<::dropletFiber::VtkPiece> pieces;
        for (label proci = 0; proci < Pstream::nProcs(); ++proci)
        {
            pieces.push_back
            (
                {extent(pieceBox(blocks_->partition().owned(proci))), pieceFile(proci)}
            );
        }
        const word index = "grid_" + time_.timeName() + ".pvti";
        ::dropletFiber::writePImageData
        (
            dir/index, t, origin, spacing, extent(g.fullBox()), fields, pieces
        );
        gridSeries_->add(index, t);
    }
}


// ************************************************************************* //
