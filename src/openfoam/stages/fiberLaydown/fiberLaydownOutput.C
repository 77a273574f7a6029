/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The laid fibers' table, the mat's map as VTK image data and the log's
    mat and balances at write times.
\*---------------------------------------------------------------------------*/

#include "fiberLaydown.H"
#include "OSspecific.H"
#include "OFstream.H"


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::fiberLaydown::startTable()
{
    if (filePtr_.valid() || !Pstream::master())
    {
        return;
    }
    writeToFile_ = true;
    filePtr_ = createFile("laydown");
    OFstream& os = file();
    writeHeader
    (
        os,
        "Fibers laid on the belt, one row each (one physical fiber's figures;"
        " represents: how many were laid with it). across, along [m] in the"
        " belt's frame; orientation: unit end-to-end (across, along, normal);"
        " masses in kg; endToEnd [m] between its ends; spread [m] its"
        " population's hat half-width on the belt (0: none)"
    );
    writeCommented(os, "Time");
    const char* columns[] =
    {
        "id", "across", "along", "orientation_across", "orientation_along",
        "orientation_normal", "length", "glassMass", "binderMass",
        "represents", "bareFraction", "sigmaCoV", "endToEnd", "spread"
    };
    for (const char* column : columns)
    {
        writeTabbed(os, column);
    }
    os  << endl;
}


void Foam::dropletFiber::fiberLaydown::writeRows
(
    const std::vector<::dropletFiber::LaidFiber>& laid
)
{
    if (!Pstream::master() || laid.empty())
    {
        return;
    }
    startTable();
    OFstream& os = file();
    for (const ::dropletFiber::LaidFiber& f : laid)
    {
        os  << f.time << tab << label(f.id);
        const scalar values[] =
        {
            f.across, f.along, f.orientation.x(), f.orientation.y(),
            f.orientation.z(), f.length, f.glassMass, f.binderMass,
            f.represents, f.bareFraction, f.sigmaVariation, f.endToEnd,
            f.spread
        };
        for (const scalar v : values)
        {
            os  << tab << v;
        }
        os  << nl;
    }
    os.flush();
}


void Foam::dropletFiber::fiberLaydown::writeMapVtk() const
{
    const auto& cells = map_->cells();
    if (!Pstream::master() || cells.empty())
    {
        return;
    }
    long c0 = 0, c1 = map_->lattice().columns() - 1;
    long r0 = cells.begin()->first.second, r1 = r0;
    for (const auto& entry : cells)
    {
        c0 = std::min(c0, entry.first.first);
        c1 = std::max(c1, entry.first.first);
        r0 = std::min(r0, entry.first.second);
        r1 = std::max(r1, entry.first.second);
    }
    const int nx = int(c1 - c0 + 1), ny = int(r1 - r0 + 1);
    const scalar h = map_->cell(), area = h*h;
    std::vector<::dropletFiber::VtkField> fields
    {
        {"areaWeight", 1, {}}, {"binderAreaWeight", 1, {}}, {"LOI", 1, {}},
        {"fibersPerArea", 1, {}}, {"orientationOrder", 1, {}},
        {"areaWeightError", 1, {}}, {"LOIError", 1, {}},
        {"computedFibers", 1, {}}
    };
    for (auto& f : fields)
    {
        f.values.assign(std::size_t(nx)*std::size_t(ny), 0.0);
    }
    for (const auto& [key, c] : cells)
    {
        const std::size_t k =
            std::size_t(key.second - r0)*std::size_t(nx) + std::size_t(key.first - c0);
        fields[0].values[k] = 1000*c.glass/area;     // g/m2
        fields[1].values[k] = 1000*c.binder/area;    // g/m2
        fields[2].values[k] =
            c.glass + c.binder > 0 ? 100*c.binder/(c.glass + c.binder) : 0;
        fields[3].values[k] = c.fibers/area;
        fields[4].values[k] = c.glass > 0 ? c.orientationSum/c.glass : 0;
        // P60: the standard errors from the computed fibers behind the cell
        fields[5].values[k] = 1000*::dropletFiber::cellAreaWeight(c, area).error;
        fields[6].values[k] = 100*::dropletFiber::cellLoi(c).error;
        fields[7].values[k] = c.computed;
    }
    const fileName dir =
        baseFileDir()/name()/time_.timeName(time_.startTime().value());
    mkDir(dir);
    const word file = "mat_" + time_.timeName() + ".vti";
    // x across, y along the belt, at the cells' centres
    ::dropletFiber::writeImageData
    (
        dir/file, time_.value(),
        Eigen::Vector3d(map_->acrossMin() + (c0 + 0.5)*h, (r0 + 0.5)*h, 0),
        Eigen::Vector3d(h, h, h), {nx, ny, 1}, fields
    );
    series_->add(file, time_.value());
}


void Foam::dropletFiber::fiberLaydown::reportMat
(
    const long rowFrom,
    const long rowTo
) const
{
    // P60, P61: the complete rows' figures with their errors
    const ::dropletFiber::AcrossProfile profile =
        ::dropletFiber::acrossProfileWithErrors(*map_, rowFrom, rowTo);
    const ::dropletFiber::NonUniformity u =
        ::dropletFiber::nonUniformity(profile);
    Info<< "    mat (rows " << rowFrom << " to " << rowTo << ", along "
        << rowFrom*map_->cell() << " to " << (rowTo + 1)*map_->cell()
        << " m, " << profile.areaWeight.size() << " columns across):"
        << " glass area weight " << 1000*u.mean << " +- "
        << 1000*Foam::sqrt(profile.meanVariance) << " g/m2, LOI "
        << 100*profile.loiAll.value << " +- " << 100*profile.loiAll.error
        << " %, across-width CoV " << u.observed << nl
        << "    mat's across-width CoV: counting noise " << u.noise
        << ", the mat's own " << u.real << " (two-sigma bound "
        << u.realUpper << ")" << nl;
    if (Pstream::master())
    {
        writeProfile(rowFrom, rowTo, profile, u);
    }
}


void Foam::dropletFiber::fiberLaydown::writeProfile
(
    const long rowFrom,
    const long rowTo,
    const ::dropletFiber::AcrossProfile& profile,
    const ::dropletFiber::NonUniformity& u
) const
{
    const fileName dir =
        baseFileDir()/name()/time_.timeName(time_.startTime().value());
    mkDir(dir);
    OFstream os(dir/("matProfile_" + time_.timeName() + ".dat"));
    os.precision(writePrecision_);
    os  << "# The mat across the belt's width at time " << time_.timeName()
        << ", over its complete rows " << rowFrom << " to " << rowTo
        << " (along " << rowFrom*map_->cell() << " to " << (rowTo + 1)*map_->cell()
        << " m): glass area weight [g/m2] and LOI [%] per column with their"
        << " standard errors (docs/model.md sec. 11, P60)" << nl
        << "# glass area weight " << 1000*u.mean << " +- "
        << 1000*Foam::sqrt(profile.meanVariance) << " g/m2, LOI "
        << 100*profile.loiAll.value << " +- " << 100*profile.loiAll.error
        << " %, across-width CoV " << u.observed << ": counting noise " << u.noise
        << ", the mat's own " << u.real << " (two-sigma bound " << u.realUpper
        << ")" << nl
        << "# across\tareaWeight\tareaWeightError\tLOI\tLOIError" << nl;
    for (std::size_t k = 0; k < profile.areaWeight.size(); ++k)
    {
        os  << map_->acrossMin() + (scalar(k) + 0.5)*map_->cell()
            << tab << 1000*profile.areaWeight[k].value
            << tab << 1000*profile.areaWeight[k].error
            << tab << 100*profile.loi[k].value
            << tab << 100*profile.loi[k].error << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberLaydown::reportAtWrite()
{
    if (!on_)
    {
        return;
    }
    coreCall("writing the mat's map", [this]() { writeMapVtk(); });
    const laidTotals& t = totals_;
    Info<< type() << " " << name() << " laydown at time " << time_.timeName()
        << ": " << t.computed << " computed fibers laid (" << t.physical
        << " physical), glass " << t.glass << " kg, binder " << t.binder
        << " kg: LOI "
        << (t.glass + t.binder > 0 ? 100*t.binder/(t.glass + t.binder) : 0)
        << " %" << nl;
    const std::pair<long, long> rows = completeRows();
    if (rows.first <= rows.second)
    {
        reportMat(rows.first, rows.second);
    }
    else
    {
        Info<< "    mat: no complete row yet (the belt has not carried a row"
            << " across the whole laying zone)" << nl;
    }
}


// ************************************************************************* //
