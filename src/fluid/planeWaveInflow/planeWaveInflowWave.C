#include "planeWaveInflowWave.H"
#include "isentropeTable.H"
#include "rhoEThermo.H"
#include "volFields.H"
#include "IFstream.H"
#include "Time.H"
#include "SHA1.H"
#include "inputChecks.H"
#include "keywordCheck.H"
#include "inputRecord.H"
#include "fileKind.H"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- A `table (...)` entry as a list of (time, value) pairs
Foam::List<Foam::Tuple2<Foam::scalar, Foam::scalar>> readTable
(
    const Foam::dictionary& dict,
    const Foam::word& key
)
{
    using namespace Foam;
    ITstream& is = dict.lookup(key);
    const word kind(is);
    if (kind != "table")
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " is `" << kind << " ...`; expected "
            << "`table ((t0 p0) (t1 p1) ...)` [s Pa]"
            << exit(FatalIOError);
    }
    List<Tuple2<scalar, scalar>> table(is);
    foamTools::checkEntryEnd
    (
        dict, key, is, "`table ((t0 p0) (t1 p1) ...)` [s Pa]"
    );
    return table;
}

//- A number for a message (10 significant digits, not the run's 17)
Foam::word num(const Foam::scalar x)
{
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.10g", x);
    return Foam::word(buf, false);
}

//- x as read back from its %.17g text: magnitudes up to 1e-300
//  (OpenFOAM's VSMALL: its reader rounds them to zero) and -0.0 ("-0":
//  the integer 0) are 0 (neuronFsi.planeWave._asRead)
double asRead(const double x)
{
    return std::fabs(x) <= 1e-300 ? 0.0 : x;
}

//- A row of a pulse table for a message
Foam::word row(const Foam::Tuple2<Foam::scalar, Foam::scalar>& r)
{
    return Foam::word("(" + num(r.first()) + " " + num(r.second()) + ")", false);
}

//- The p entry of the type, its keywords checked first (before any entry
//  is read: a misspelt 'file' is named as such, not as 'file' missing):
//  unknown and duplicated keywords are the project's one keyword check's
//  errors, with the closest valid keyword (issue 19, adv28 p08: a keyword
//  given twice, p62: an unknown one, were taken without a word)
const Foam::dictionary& checked(const Foam::dictionary& entry)
{
    Foam::foamTools::checkKeywords
    (
        entry,
        {
            "type", "patchType", "value", "columnHeight", "pulse", "file",
            "ambientPressure", "ambientTemperature"
        }
    );
    return entry;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::planeWaveInflowWave::planeWaveInflowWave
(
    const dictionary& entry,
    const fvPatch& patch,
    const scalarField& pInitial
)
:
    columnHeight_(checked(entry).get<scalar>("columnHeight")),
    pulse_(readTable(entry, "pulse")),
    file_(entry.get<fileName>("file")),
    path_(file_),
    n_(Zero),
    haveAmbient_(false),
    ambientFromEntry_(false),
    pAmbient_(0),
    TAmbient_(0),
    pInitial_(pInitial),
    wavePAmbient_(0),
    waveTAmbient_(0)
{
    if (!(columnHeight_ > 0) || !std::isfinite(columnHeight_))
    {
        FatalIOErrorInFunction(entry)
            << "columnHeight " << num(columnHeight_) << " m of patch "
            << patch.name() << " must be positive and finite"
            << exit(FatalIOError);
    }
    if (entry.found("ambientPressure") || entry.found("ambientTemperature"))
    {
        pAmbient_ = entry.get<scalar>("ambientPressure");
        TAmbient_ = entry.get<scalar>("ambientTemperature");
        if (!std::isfinite(pAmbient_) || !(TAmbient_ > 0))
        {
            FatalIOErrorInFunction(entry)
                << "ambientPressure " << pAmbient_ << " Pa and "
                << "ambientTemperature " << TAmbient_ << " K of patch "
                << patch.name() << ": finite, T > 0 (they are written by "
                << "the solver; remove both for a new run)"
                << exit(FatalIOError);
        }
        haveAmbient_ = true;
        ambientFromEntry_ = true;
    }
    readWave(entry, patch);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::planeWaveInflowWave::readWave
(
    const dictionary& entry,
    const fvPatch& patch
)
{
    const Time& runTime = patch.boundaryMesh().mesh().time();
    path_ = file_;
    path_.expand();
    if (!path_.isAbsolute())
    {
        path_ = runTime.globalPath()/path_;
    }
    // A directory or a FIFO named by 'file' (adv28 p14: "Attempt to put
    // back onto bad stream"; a FIFO blocks the open): said as such
    const std::string kind(foamTools::notARegularFile(path_));
    if (!kind.empty())
    {
        FatalIOErrorInFunction(entry)
            << "Patch " << patch.name() << ": entry 'file' " << file_
            << " names " << path_ << ", which is " << kind.c_str()
            << ", not the wave file (written by `planeWave -inflow "
            << "<height>`, default constant/inflowWave)"
            << exit(FatalIOError);
    }
    // A file that is not text (adv29 w15: a file of zeros was
    // "Found ERROR but expected EOF" at line 1, the entry not named)
    const std::string binary(foamTools::binaryContent(path_));
    if (!binary.empty())
    {
        FatalIOErrorInFunction(entry)
            << "Patch " << patch.name() << ": entry 'file' " << file_
            << " names " << path_ << ", which holds binary data ("
            << binary.c_str() << "), not a text dictionary: give the wave"
            << " file written by `planeWave -inflow <height>` (default "
            << "constant/inflowWave)" << exit(FatalIOError);
    }
    IFstream is(path_);
    if (!is.good())
    {
        FatalIOErrorInFunction(entry)
            << "Patch " << patch.name() << ": cannot read the wave file "
            << path_ << " (written by `planeWave -inflow <height>`)"
            << exit(FatalIOError);
    }
    const dictionary wave(is);
    // The file's keywords: the project's one keyword check (adv29 w04: a
    // keyword given twice was taken without a word, OpenFOAM keeping the
    // last; an unknown one is a misspelt or foreign entry)
    foamTools::checkKeywords
    (
        wave,
        {
            "height", "columnHeight", "pulse", "dz", "ambientPressure",
            "ambientTemperature", "thermoDigest", "rowsDigest", "data"
        }
    );

    // A plane patch: one normal (the patch may have no faces on some
    // processors of a parallel run)
    const vector sumSf = gSum(patch.Sf());
    if (!(mag(sumSf) > 0))
    {
        FatalIOErrorInFunction(entry)
            << "Patch " << patch.name() << " has no faces"
            << exit(FatalIOError);
    }
    n_ = sumSf/mag(sumSf);
    const scalar skew = max(gMax(mag(patch.nf() - n_)), scalar(0));
    if (skew > 1e-6)
    {
        FatalIOErrorInFunction(entry)
            << "Patch " << patch.name() << " is not a plane: its face "
            << "normals differ by up to " << num(skew) << " (the inflow of "
            << "a plane wave needs a plane patch)" << exit(FatalIOError);
    }

    const scalar height = wave.get<scalar>("height");
    const scalar patchHeight =
        gSum(patch.magSf()*(patch.Cf() & n_))/gSum(patch.magSf());
    const scalar tol = 1e-6*columnHeight_;
    if (mag(height - patchHeight) > tol)
    {
        FatalIOErrorInFunction(wave)
            << "The wave in " << path_ << " is at height " << num(height)
            << " m, patch " << patch.name() << " at " << num(patchHeight)
            << " m (tolerance " << num(tol) << " m): compute it for this "
            << "mesh (planeWave -inflow " << num(patchHeight) << ")"
            << exit(FatalIOError);
    }
    const scalar column = wave.get<scalar>("columnHeight");
    if (mag(column - columnHeight_) > 1e-12*columnHeight_)
    {
        FatalIOErrorInFunction(wave)
            << "The wave in " << path_ << " is for a column of "
            << num(column) << " m, the p entry of patch " << patch.name()
            << " has columnHeight " << num(columnHeight_) << " m"
            << exit(FatalIOError);
    }
    const List<Tuple2<scalar, scalar>> pulse(readTable(wave, "pulse"));
    if (pulse != pulse_)
    {
        label i = 0;
        while (i < min(pulse.size(), pulse_.size()) && pulse[i] == pulse_[i])
        {
            ++i;
        }
        FatalIOErrorInFunction(wave)
            << "The wave in " << path_ << " is for another pulse than the "
            << "p entry of patch " << patch.name() << " has: row " << i
            << " is "
            << (i < pulse.size() ? row(pulse[i]) : Foam::word("missing"))
            << " in the file, "
            << (i < pulse_.size() ? row(pulse_[i]) : Foam::word("missing"))
            << " in the entry (" << pulse.size() << " and "
            << pulse_.size() << " rows): compute it again (planeWave "
            << "-inflow)" << exit(FatalIOError);
    }

    // The water the wave was computed with (issue 19, adv28 p27-p30b,
    // pk10: a changed law or ambient state ran with the old wave): the
    // column's state at rest (ambientPressure, ambientTemperature) and the
    // digest of its constant/thermophysicalProperties as rhoRiemannFoam
    // recorded it (foamTools::inputRecord, parsed entries), written by
    // planeWave -inflow. The law is compared here, the state once the
    // ambient state of this run is known (table())
    const char* record[] =
        {"ambientPressure", "ambientTemperature", "thermoDigest"};
    for (const char* key : record)
    {
        if (!wave.found(key, keyType::LITERAL))
        {
            FatalIOErrorInFunction(wave)
                << "The wave in " << path_ << " has no entry '" << key
                << "': it does not record the water it was computed with"
                << " (ambient p, T and the law of thermophysicalProperties;"
                << " written by planeWave -inflow since issue 19), so it"
                << " cannot be checked against this case's. Compute it"
                << " again: planeWave -inflow " << num(height)
                << " -overwrite" << exit(FatalIOError);
        }
    }
    wavePAmbient_ = wave.get<scalar>("ambientPressure");
    waveTAmbient_ = wave.get<scalar>("ambientTemperature");
    const fileName thermoFile
    (
        runTime.globalPath()/"constant"/"thermophysicalProperties"
    );
    const std::string thermoNow
    (
        foamTools::inputRecord::digest(thermoFile, true)
    );
    const string thermoThen(wave.get<string>("thermoDigest"));
    if (thermoNow != thermoThen)
    {
        FatalIOErrorInFunction(wave)
            << "The wave in " << path_ << " was computed with another "
            << "water law than this case's " << thermoFile << ": the "
            << "digest of its entries is " << thermoNow.c_str()
            << ", the wave's entry thermoDigest " << thermoThen.c_str()
            << " (the thermophysicalProperties of the 1D column). The "
            << "incident wave depends on the law: compute it again with "
            << "this one (planeWave -inflow " << num(height)
            << " -overwrite), or restore the law" << exit(FatalIOError);
    }

    const List<vector> data(wave.lookup("data"));
    if (data.size() < 2)
    {
        FatalIOErrorInFunction(wave)
            << "data of " << path_ << " has " << data.size() << " rows; "
            << "at least 2 (time [s], p [Pa], u [m/s])" << exit(FatalIOError);
    }
    t_.setSize(data.size());
    p_.setSize(data.size());
    u_.setSize(data.size());
    forAll(data, i)
    {
        t_[i] = data[i].x();
        p_[i] = data[i].y();
        u_[i] = data[i].z();
        if
        (
            !std::isfinite(t_[i]) || !std::isfinite(p_[i])
         || !std::isfinite(u_[i]) || (i > 0 && !(t_[i] > t_[i - 1]))
        )
        {
            FatalIOErrorInFunction(wave)
                << "data row " << i << " of " << path_ << " " << data[i]
                << ": numbers must be finite and the times increasing"
                << exit(FatalIOError);
        }
    }
    // The rows as planeWave -inflow wrote them: its rowsDigest is the SHA-1
    // of the rows at 17 digits as read (neuronFsi.planeWave.inflowDigest;
    // asRead: what OpenFOAM's reader rounds to zero is 0). A value
    // edited in the rows ran silently (issue 19, class 5: only the header
    // entries were compared). The entry is required like thermoDigest:
    // without it, an edited or damaged row ran unchecked (adv29 w09c,
    // w09e: the line removed, then a row edited, exit 0)
    if (!wave.found("rowsDigest", keyType::LITERAL))
    {
        FatalIOErrorInFunction(wave)
            << "The wave in " << path_ << " has no entry 'rowsDigest': its"
            << " data rows cannot be checked against what planeWave -inflow"
            << " wrote (an edited or damaged row would run unchecked; the"
            << " entry is written by planeWave -inflow since issue 19)."
            << " Compute it again: planeWave -inflow " << num(height)
            << " -overwrite" << exit(FatalIOError);
    }
    {
        const string expected(wave.get<string>("rowsDigest"));
        SHA1 sha;
        forAll(t_, i)
        {
            char line[96];
            std::snprintf
            (
                line, sizeof(line), "%.17g %.17g %.17g\n", asRead(t_[i]),
                asRead(p_[i]), asRead(u_[i])
            );
            sha.append(line);
        }
        const std::string found(sha.digest().str());
        if (found != expected)
        {
            FatalIOErrorInFunction(wave)
                << "The data rows of " << path_ << " are not those planeWave"
                << " -inflow wrote: their SHA-1 is " << found.c_str()
                << ", the file's entry rowsDigest " << expected.c_str()
                << " (a row edited or the file damaged). The incident wave"
                << " is an input computed from the full column: compute it"
                << " again (planeWave -inflow " << num(height) << "), do not"
                << " edit it" << exit(FatalIOError);
        }
    }
}


const riemann::isentropeTable& Foam::planeWaveInflowWave::table
(
    const fvPatch& patch,
    const rhoEThermo& thermo
) const
{
    if (table_)
    {
        return *table_;
    }
    if (!haveAmbient_)
    {
        // The water at rest next to the patch (a fresh run)
        // p as read (the cells' now may differ: this first evaluation
        // comes after the first stage, whose flux used the entry's value)
        const scalarField pI
        (
            pInitial_.size() == patch.size() ? pInitial_
          : scalarField(thermo.p().boundaryField()[patch.index()]
                .patchInternalField())
        );
        const scalarField TI(thermo.T().boundaryField()[patch.index()]
            .patchInternalField());
        const scalar cI = gMax(thermo.c().primitiveField());
        const scalar rhoI = gMax(thermo.rho().primitiveField());
        const scalar dp = gMax(pI) - gMin(pI);
        const scalar dT = gMax(TI) - gMin(TI);
        // A temperature at or below 0 K first (the tolerance of T's
        // uniformity below is relative to T: a negative T was reported as
        // not uniform)
        if (!(gMin(TI) > 0))
        {
            FatalErrorInFunction
                << "Patch " << patch.name() << " (planeWaveInflow): the "
                << "temperature of the cells next to it at the start is "
                << gMin(TI) << " K, not a temperature (valid range (0, inf)"
                << " K): the initial field T (" << thermo.T().objectPath()
                << ") is invalid there; the ambient isentrope is taken "
                << "from the water at rest next to the patch"
                << exit(FatalError);
        }
        const bool pVaries = dp > 1e-9*rhoI*cI*cI;
        const bool TVaries = dT > 1e-9*gMax(TI);
        if (pVaries || TVaries)
        {
            FatalErrorInFunction
                << "Patch " << patch.name() << " (planeWaveInflow): the "
                << "cells next to it are not at one state at the start: "
                << (pVaries ? "p" : "") << (pVaries && TVaries ? " and " : "")
                << (TVaries ? "T" : "") << " not uniform there (p from "
                << gMin(pI) << " to " << gMax(pI) << " Pa, T from "
                << gMin(TI) << " to " << gMax(TI) << " K; the initial "
                << "fields of " << thermo.T().time().timeName() << "/); the "
                << "ambient isentrope is taken from the water at rest there"
                << exit(FatalError);
        }
        pAmbient_ = gAverage(pI);
        TAmbient_ = gAverage(TI);
        haveAmbient_ = true;
    }
    // The ambient state of this run (the water next to the patch at a new
    // start, the entries ambientPressure/ambientTemperature of the p entry
    // when given: a restart's) is the water the wave was computed with
    const scalar tolP =
        1e-9*max(mag(pAmbient_), mag(wavePAmbient_)) + 1e-3;
    const scalar tolT = 1e-9*max(mag(TAmbient_), mag(waveTAmbient_));
    if
    (
        !(mag(pAmbient_ - wavePAmbient_) <= tolP)
     || !(mag(TAmbient_ - waveTAmbient_) <= tolT)
    )
    {
        FatalErrorInFunction
            << "Patch " << patch.name() << " (planeWaveInflow): the water "
            << "of this run is at " << num(pAmbient_) << " Pa, "
            << num(TAmbient_) << " K ("
            << (
                   ambientFromEntry_
                 ? "the entries ambientPressure and ambientTemperature of "
                   "the patch's p entry"
                 : "the cells next to the patch at the start, the initial "
                   "fields p and T"
               )
            << "), the wave in " << path_ << " was computed for water at "
            << num(wavePAmbient_) << " Pa, " << num(waveTAmbient_)
            << " K (its "
            << "entries ambientPressure, ambientTemperature). The incident "
            << "wave depends on the state it travels into: compute it "
            << "again for this water (planeWave -inflow ... -overwrite), or"
            << " restore "
            << (ambientFromEntry_ ? "the entries" : "the initial fields")
            << exit(FatalError);
    }
    scalarField rhoA(1), eA(1), cA(1);
    thermo.rhoEFromPT
    (
        scalarField(1, pAmbient_), scalarField(1, TAmbient_), rhoA, eA
    );
    thermo.cFromRhoE(rhoA, eA, cA);
    // The range: 4 times the wave's amplitude above (incident and
    // reflected waves overlap at the patch), once below; at least 1e-3 of
    // the bulk modulus
    const scalar amplitude =
        max(max(mag(p_ - pAmbient_)), 1e-3*rhoA[0]*sqr(cA[0]));
    try
    {
        table_ = std::make_shared<const riemann::isentropeTable>
        (
            thermo.isentrope
            (
                rhoA[0], eA[0], pAmbient_ - amplitude,
                pAmbient_ + 4*amplitude
            )
        );
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Patch " << patch.name() << " (planeWaveInflow): the "
            << "isentrope through the ambient state (" << pAmbient_
            << " Pa, " << TAmbient_ << " K) over [" << pAmbient_ - amplitude
            << ", " << pAmbient_ + 4*amplitude << "] Pa: " << err.what()
            << exit(FatalError);
    }
    Info<< "planeWaveInflow " << patch.name() << ": ambient "
        << pAmbient_ << " Pa, " << TAmbient_ << " K; wave from " << path_
        << " (" << t_.size() << " rows to " << t_.last() << " s)" << endl;
    return *table_;
}


void Foam::planeWaveInflowWave::waveAt
(
    const fvPatch& patch,
    const scalar t,
    scalar& p,
    scalar& u
) const
{
    if (!(t >= t_.first() && t <= t_.last()))
    {
        FatalErrorInFunction
            << "Patch " << patch.name() << " (planeWaveInflow): time "
            << num(t) << " s is outside the wave of " << path_ << " ["
            << num(t_.first()) << ", " << num(t_.last()) << "] s: compute "
            << "it to the "
            << "run's endTime (planeWave -inflow ... -endTime)"
            << exit(FatalError);
    }
    const label i = min
    (
        label(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()),
        t_.size() - 1
    ) - 1;
    const scalar w = (t - t_[i])/(t_[i + 1] - t_[i]);
    p = (1 - w)*p_[i] + w*p_[i + 1];
    u = (1 - w)*u_[i] + w*u_[i + 1];
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::planeWaveInflowWave::state
(
    const fvPatch& patch,
    scalarField& pb,
    vectorField& Ub,
    scalarField& Tb
) const
{
    const objectRegistry& db = patch.boundaryMesh().mesh();
    const rhoEThermo& thermo =
        db.lookupObject<rhoEThermo>("thermophysicalProperties");
    const volVectorField& U = db.lookupObject<volVectorField>("U");
    const riemann::isentropeTable& F = table(patch, thermo);

    const scalar t = db.time().value();
    scalar pw, uw;
    waveAt(patch, t, pw, uw);

    const scalarField pI
    (
        thermo.p().boundaryField()[patch.index()].patchInternalField()
    );
    const vectorField UI(U.boundaryField()[patch.index()].patchInternalField());

    pb.setSize(patch.size());
    Ub.setSize(patch.size());
    scalarField rhob(patch.size()), eb(patch.size());
    label face = -1;
    try
    {
        const scalar Jin = uw - F.F(pw);
        forAll(pI, i)
        {
            face = i;
            const scalar un = UI[i] & n_;
            const scalar Jout = un + F.F(pI[i]);
            pb[i] = F.pressure(0.5*(Jout - Jin));
            Ub[i] = UI[i] + (0.5*(Jout + Jin) - un)*n_;
            rhob[i] = F.rho(pb[i]);
            eb[i] = F.e(pb[i]);
        }
    }
    catch (const std::out_of_range& err)
    {
        FatalErrorInFunction
            << "Patch " << patch.name() << " (planeWaveInflow), time " << t
            << " s, face " << face << " (p next to it "
            << (face >= 0 ? pI[face] : pw) << " Pa, wave " << pw
            << " Pa): " << err.what() << " (the isentrope is tabulated "
            << "for pressures up to 4 times the wave's largest)"
            << exit(FatalError);
    }
    Tb.setSize(patch.size());
    thermo.TFromRhoE(rhob, eb, Tb);
}


void Foam::planeWaveInflowWave::write(Ostream& os) const
{
    // All digits: a restart compares the pulse with the file's and builds
    // the same isentrope
    const int precision = os.precision(17);
    os.writeEntry("columnHeight", columnHeight_);
    os.writeKeyword("pulse") << "table " << pulse_
        << token::END_STATEMENT << nl;
    os.writeEntry("file", file_);
    if (haveAmbient_)
    {
        os.writeEntry("ambientPressure", pAmbient_);
        os.writeEntry("ambientTemperature", TAmbient_);
    }
    os.precision(precision);
}


// ************************************************************************* //
