/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Output (per-step table, VTK files) and the restart state of
    dropletFiberCollision.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "fiberStateIO.H"
#include "dictionaryChecks.H"
#include "Time.H"
#include "fvMesh.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"

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
            "maxSegmentLengthError", "wallTimeDeposition", "wallTimeFibers"
        }
    )
    {
        writeTabbed(os, column);
    }
    os  << endl;
}


void Foam::functionObjects::dropletFiberCollision::reportStep
(
    const stepSummary& step
)
{
    Log << type() << " " << name() << ": parcels " << step.parcels
        << ", fibers " << label(fibers_.size())
        << ", captured " << step.capturedStep << " kg (total "
        << totals_.captured << " kg), segment-length error "
        << step.maxSegmentLengthError << ", sub-steps " << step.subSteps
        << endl;

    if (writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << label(fibers_.size())
            << tab << step.parcels
            << tab << step.droplets
            << tab << step.deposit.massIn
            << tab << step.deposit.massDeposited
            << tab << step.deposit.massOutside
            << tab << step.capturedStep
            << tab << totals_.captured
            << tab << fiberMass()
            << tab << step.maxSegmentLengthError
            << tab << step.depositionTime
            << tab << step.fiberTime
            << endl;
    }
}


void Foam::functionObjects::dropletFiberCollision::writeParallelStatistics()
{
    // Today every processor stores the whole grid and every fiber
    parallelStatistics_.holding(grid_->spec().nodeCount(), fibers_.size());
    const dropletFiber::parallelStatistics::figures maxima =
        parallelStatistics_.maxOverProcessors();
    if (!writeToFile())
    {
        return;
    }
    if (!parallelStatisticsFile_.valid())
    {
        parallelStatisticsFile_ = createFile("parallelStatistics");
        OFstream& os = parallelStatisticsFile_();
        writeHeader(os, "Per time step, maxima over processors");
        writeCommented(os, "Time");
        writeTabbed(os, "nodesHeldMax");
        writeTabbed(os, "fibersHeldMax");
        writeTabbed(os, "bytesSentMax");
        os  << endl;
    }
    OFstream& os = parallelStatisticsFile_();
    writeCurrentTime(os);
    os  << tab << maxima.nodesHeld
        << tab << maxima.fibersHeld
        << tab << maxima.bytesSent
        << endl;
}


void Foam::functionObjects::dropletFiberCollision::reportConservation() const
{
    const scalar balance =
        totals_.fiberMassAdded + totals_.captured
      - totals_.fiberMassRemoved - fiberMass();
    Info<< type() << " " << name() << " conservation at time "
        << time_.timeName() << ", summed over all steps so far:" << nl
        << "    parcel mass " << totals_.parcelMass << " kg = on grid "
        << totals_.deposited << " + outside it " << totals_.outside
        << " (balance "
        << totals_.parcelMass - totals_.deposited - totals_.outside
        << " kg)" << nl
        << "    fiber mass " << fiberMass() << " kg = added "
        << totals_.fiberMassAdded << " + captured " << totals_.captured
        << " - removed " << totals_.fiberMassRemoved
        << " (balance " << balance << " kg)" << nl
        << "    parcel-steps with the influence radius capped at rMaxCap: "
        << totals_.parcelsCapped << nl << endl;
}


Foam::fileName Foam::functionObjects::dropletFiberCollision::statePath
(
    const word& timeName
) const
{
    return time_.path()/timeName/"uniform"/"dropletFiber"/name();
}


void Foam::functionObjects::dropletFiberCollision::writeState() const
{
    // Every processor holds the same fibers and grid: each writes its own
    // copy (processorN/<time>/uniform/...), so that every processor reads its
    // own on restart, also after a change of the number of processors
    // through reconstructPar/decomposePar (which copy uniform/).
    // Entries added to a dictionary are turned into tokens at the default
    // precision: raise it for the restart state (bit-for-bit restart).
    const unsigned oldPrecision = IOstream::defaultPrecision(17);
    dictionary state;
    state.add("time", time_.value());
    state.add("timeIndex", time_.timeIndex());

    dictionary fibers;
    for (std::size_t f = 0; f < fibers_.size(); ++f)
    {
        dictionary d = dropletFiber::fiberStateDict(fibers_[f].state());
        d.add("origin", fiberOrigin_[f]);
        fibers.add(word("fiber" + Foam::name(label(f))), d);
    }
    state.add("fibers", fibers);

    dictionary injectors;
    for (const auto& injector : injectors_)
    {
        injectors.add(word(injector.spec().name), label(injector.injectedCount()));
    }
    state.add("injectors", injectors);

    dictionary totals;
    totals.add("parcelMass", totals_.parcelMass);
    totals.add("deposited", totals_.deposited);
    totals.add("outside", totals_.outside);
    totals.add("captured", totals_.captured);
    totals.add("fiberMassAdded", totals_.fiberMassAdded);
    totals.add("fiberMassRemoved", totals_.fiberMassRemoved);
    totals.add("fibersRemoved", totals_.fibersRemoved);
    totals.add("parcelsCapped", totals_.parcelsCapped);
    state.add("totals", totals);

    const ::dropletFiber::WindowState window = grid_->saveWindow();
    state.add
    (
        "gridWindowCounters",
        dropletFiber::toScalarList
        (
            std::vector<double>(window.counters.begin(), window.counters.end())
        )
    );
    // The window's values are the bulk of the state (nodes x 7 x steps): they
    // go to a binary OpenFOAM list beside it, exact and ten times faster to
    // write than 17-digit text
    state.add("gridWindowValueCount", label(window.values.size()));

    IOstream::defaultPrecision(oldPrecision);

    const fileName path = statePath(time_.timeName());
    mkDir(path.path());
    {
        OFstream ws(path + ".gridWindow", IOstream::BINARY);
        // Written straight from the window's buffer (a view, no copy)
        ws << UList<scalar>
        (
            const_cast<scalar*>(window.values.data()),
            label(window.values.size())
        );
        if (!ws.good())
        {
            FatalErrorInFunction
                << "Cannot write restart state " << ws.name() << exit(FatalError);
        }
    }
    OFstream os(path);
    os.precision(17);
    os  << "// dropletFiber restart state of function object " << name()
        << " at time " << time_.timeName() << nl;
    state.write(os, false);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot write restart state " << path << exit(FatalError);
    }
}


bool Foam::functionObjects::dropletFiberCollision::readState()
{
    const word startName = time_.timeName();
    const fileName path = statePath(startName);
    if (!isFile(path))
    {
        Info<< type() << " " << name() << ": no restart state " << path
            << nl << "    "
            << (time_.value() > 0 ? "restart without state: " : "")
            << "starting fresh (fibers from the dictionary, empty grid window)"
            << nl;
        return false;
    }

    IFstream is(path);
    const dictionary state(is);

    const dictionary& fibers = state.subDict("fibers");
    fibers_.clear();
    fiberOrigin_.clear();
    for (const entry& e : fibers)
    {
        const dictionary& d = e.dict();
        fibers_.emplace_back(dropletFiber::fiberStateFromDict(d));
        fiberOrigin_.push_back(d.get<word>("origin"));
    }

    const dictionary& injectors = state.subDict("injectors");
    for (auto& injector : injectors_)
    {
        injector.setInjectedCount
        (
            injectors.lookupOrDefault<label>(word(injector.spec().name), 0)
        );
    }

    const dictionary& totals = state.subDict("totals");
    totals_.parcelMass = totals.get<scalar>("parcelMass");
    totals_.deposited = totals.get<scalar>("deposited");
    totals_.outside = totals.get<scalar>("outside");
    totals_.captured = totals.get<scalar>("captured");
    totals_.fiberMassAdded = totals.get<scalar>("fiberMassAdded");
    totals_.fiberMassRemoved = totals.get<scalar>("fiberMassRemoved");
    totals_.fibersRemoved = totals.get<label>("fibersRemoved");
    totals_.parcelsCapped = totals.lookupOrDefault<label>("parcelsCapped", 0);

    dropletFiber::checkedCoreCall
    (
        state,
        [&]()
        {
            ::dropletFiber::WindowState window;
            for (const scalar c : state.get<scalarList>("gridWindowCounters"))
            {
                window.counters.push_back(std::int64_t(c));
            }
            IFstream ws(path + ".gridWindow", IOstream::BINARY);
            const scalarList values(ws);
            if (!ws.good() || values.size() != state.get<label>("gridWindowValueCount"))
            {
                FatalIOErrorInFunction(state)
                    << "Restart state " << ws.name() << " is missing or does "
                    << "not hold the " << state.get<label>("gridWindowValueCount")
                    << " values of the averaging window: delete "
                    << path << " to start fresh." << exit(FatalIOError);
            }
            window.values = dropletFiber::toStdVector(values);
            grid_->restoreWindow(window);
        }
    );

    Info<< type() << " " << name() << ": restarted from " << path << ": "
        << label(fibers_.size()) << " fibers, captured mass so far "
        << totals_.captured << " kg" << nl;
    return true;
}


void Foam::functionObjects::dropletFiberCollision::writeVtkFiles()
{
    if (!Pstream::master() || (!writeVtk_ && !writeGridVtk_))
    {
        return;
    }
    const fileName dir =
        baseFileDir()/name()/time_.timeName(time_.startTime().value());
    mkDir(dir);
    const scalar t = time_.value();

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
    // Fibers: points of all fibers one after another, a polyline each
    std::vector<Eigen::Vector3d> points;
    std::vector<std::size_t> offsets;
    ::dropletFiber::VtkField velocity{"velocity", 3, {}};
    ::dropletFiber::VtkField sigma{"sigma", 1, {}};
    ::dropletFiber::VtkField captured{"capturedMass", 1, {}};
    ::dropletFiber::VtkField fiberId{"fiberId", 1, {}};
    ::dropletFiber::VtkField tension{"tension", 1, {}};
    ::dropletFiber::VtkField segmentCaptured{"segmentCapturedMass", 1, {}};
    for (std::size_t f = 0; f < fibers_.size(); ++f)
    {
        const auto& fiber = fibers_[f];
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
            fiberId.values.push_back(double(f));
        }
        for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
        {
            tension.values.push_back(fiber.tension()(j));
            segmentCaptured.values.push_back(segCaptured(j));
        }
    }
    const word file = "fibers_" + time_.timeName() + ".vtp";
    ::dropletFiber::writePolylines
    (
        dir/file, t, points, offsets,
        {velocity, sigma, captured, fiberId},
        {tension, segmentCaptured}
    );
    fibersSeries_->add(file, t);
}


void Foam::functionObjects::dropletFiberCollision::writeGridVtk
(
    const fileName& dir,
    const scalar t
)
{
    const ::dropletFiber::DensityGrid& grid = *grid_;
    const auto& g = gridSettings_.spec;
    const std::size_t n = g.nodeCount();
    ::dropletFiber::VtkField rho{"rho", 1, std::vector<double>(n)};
    ::dropletFiber::VtkField rNumber{"rMeanNumber", 1, std::vector<double>(n)};
    ::dropletFiber::VtkField rMass{"rMeanMass", 1, std::vector<double>(n)};
    ::dropletFiber::VtkField U{"U", 3, std::vector<double>(3*n)};
    for (std::size_t k = 0; k < n; ++k)
    {
        const ::dropletFiber::DropletFieldValue v = grid.nodeValue(k);
        rho.values[k] = v.rho;
        rNumber.values[k] = v.rMeanNumber;
        rMass.values[k] = v.rMeanMass;
        for (int c = 0; c < 3; ++c)
        {
            U.values[3*k + c] = v.velocity(c);
        }
    }
    Eigen::Vector3d origin, spacing;
    for (int d = 0; d < 3; ++d)
    {
        origin(d) = g.nodeCoordinate(d, 0);
        spacing(d) = g.spacing(d);  // a flat direction: its thickness
    }
    const word file = "grid_" + time_.timeName() + ".vti";
    ::dropletFiber::writeImageData
    (
        dir/file, t, origin, spacing, g.nodes, {rho, rNumber, rMass, U}
    );
    gridSeries_->add(file, t);
}

// ************************************************************************* //
