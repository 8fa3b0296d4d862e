#include "indentationInput.H"
#include "solidInput.H"
#include "inputChecks.H"
#include "keywordCheck.H"
#include "resultGuard.H"
#include "IOstream.H"
#include "ITstream.H"
#include "token.H"

#include "Checkpoint.H"
#include "SolidError.H"

#include <iostream>
#include <sstream>
#include <utility>
#include <vector>

namespace
{

// The valid ranges of the numbers of constant/indenterProperties: the one
// place they are written, read by the constructor's readers (inRange) and
// by the scan of the numbers (foamTools::checkNumbers, through the
// scanRangeFunction registered below), which names an entry's range and
// unit for a value OpenFOAM's reader would not take as written (1e-320,
// 1e400; was: the reader's limits only, fix19f's list). The ranges that
// depend on other entries (tolerance at most a tenth of
// maxDepthIncrement, holdDeltaT0 at most maxDeltaT) are checked after
const std::vector<std::pair<std::string, Foam::foamTools::numberRange>>&
indenterRanges()
{
    static const
        std::vector<std::pair<std::string, Foam::foamTools::numberRange>>
        rows
    {
        {"radius", {0, 1, false, true, "m"}},
        {"tolerance", {0, 1, false, true, "m"}},
        {"penaltyFactor", {0, 1e6, false, true, ""}},
        {"maxDepthIncrement", {0, 1, false, true, "m"}},
        {"holdDeltaT0", {0, 1e6, false, true, "s"}},
        {"maxDeltaT", {0, 1e6, false, true, "s"}},
        {"holdGrowth", {1, 10, true, true, ""}},
        {"forceTarget", {0, 1, true, true, "N"}},
        {"forceTargetTolerance", {0, 1, false, true, ""}},
        {"maxFactorMemory", {0, 1e15, false, true, "B"}},
        {"maxFactorFlops", {0, 1e18, false, true, "flop"}}
    };
    return rows;
}

const Foam::foamTools::numberRange* indenterRange(const std::string& key)
{
    for (const auto& row : indenterRanges())
    {
        if (row.first == key)
        {
            return &row.second;
        }
    }
    return nullptr;
}

// Entry key of indenterProperties d in its range (deflt, when given,
// for an absent entry)
Foam::scalar inRange
(
    const Foam::dictionary& d,
    const Foam::word& key,
    const Foam::scalar* deflt = nullptr
)
{
    const Foam::foamTools::numberRange* r = indenterRange(key);
    if (!r)
    {
        FatalErrorInFunction
            << "no range of entry '" << key << "' of indenterProperties "
            << "(a bug)" << Foam::exit(Foam::FatalError);
    }
    return deflt
      ? Foam::foamTools::readInRangeOrDefault<Foam::scalar>
        (
            d, key, r->unit, r->lo, r->hi, r->closedLo, *deflt, r->closedHi
        )
      : Foam::foamTools::readInRange<Foam::scalar>
        (
            d, key, r->unit, r->lo, r->hi, r->closedLo, r->closedHi
        );
}

Foam::scalar inRange
(
    const Foam::dictionary& d,
    const Foam::word& key,
    const Foam::scalar deflt
)
{
    return inRange(d, key, &deflt);
}

// The scan of the numbers' range of an entry of constant/indenterProperties
std::string indenterPropertiesRange
(
    const std::string& dictName,
    const std::vector<std::string>& scope,
    const std::string& key
)
{
    if (dictName != "indenterProperties" || !scope.empty())
    {
        return std::string();
    }
    const Foam::foamTools::numberRange* r = indenterRange(key);
    return r ? r->text() : std::string();
}

const bool indenterPropertiesRangeAdded =
    Foam::foamTools::addScanRange(indenterPropertiesRange);

} // End anonymous namespace

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::indentationInput::indentationInput
(
    const dictionary& indenterProperties,
    const dictionary& controlDict
)
:
    dict_(indenterProperties),
    contactPatch_(),
    continueRun_(false),
    endTime_(-1)
{
    using foamTools::readInRange;
    using foamTools::readInRangeOrDefault;
    const dictionary& d = dict_;
    foamTools::checkKeywords
    (
        d,
        {
            "radius", "tolerance", "penaltyFactor", "contactPatch",
            "maxDepthIncrement", "holdDeltaT0", "maxDeltaT", "holdGrowth",
            "forceTarget", "forceTargetTolerance", "protocol", "logNewton",
            "maxFactorMemory", "maxFactorFlops"
        }
    );
    // Our entries of system/controlDict (OpenFOAM's are the Time's)
    foamTools::checkDuplicates
    (
        controlDict, {"fieldWriteInterval", "checkpointInterval", "maxSteps"}
    );

    sphere_.radius = inRange(d, "radius");
    sphere_.tolerance = inRange(d, "tolerance");
    sphere_.penaltyFactor = inRange(d, "penaltyFactor", 10.0);
    contactPatch_ = d.getOrDefault<word>("contactPatch", "outerSurface");

    settings_.maxDepthIncrement = inRange(d, "maxDepthIncrement");
    settings_.holdDeltaT0 = inRange(d, "holdDeltaT0");
    settings_.maxDeltaT = inRange(d, "maxDeltaT");
    settings_.holdGrowth = inRange(d, "holdGrowth", 1.5);
    settings_.forceTarget = inRange(d, "forceTarget", 0.0);
    settings_.forceTargetTolerance = inRange(d, "forceTargetTolerance", 0.01);

    // The first step of a hold is at most the largest step: holdDeltaT0
    // 10 s with maxDeltaT 1 s ran every hold step at 1 s, silently
    // (adv30 n17)
    if (settings_.holdDeltaT0 > settings_.maxDeltaT)
    {
        FatalIOErrorInFunction(d)
            << "entry 'holdDeltaT0' = "
            << foamTools::numberText(settings_.holdDeltaT0).c_str()
            << " s is outside the valid range "
            << foamTools::rangeText
               (
                   0.0, settings_.maxDeltaT, false,
                   foamTools::numberText(settings_.holdDeltaT0)
               ).c_str()
            << " s: at most maxDeltaT (" << settings_.maxDeltaT << " s), "
            << "the largest step" << exit(FatalIOError);
    }

    // The penetration the contact accepts must be small against the depth
    // change of a step: tolerance 1e3 m (or 0.5 m, inside (0, 1]) let the
    // sphere sink into the cell without a contact force, silently (the
    // forces a fraction of the real ones; issue 19)
    {
        const scalar hi = 0.1*settings_.maxDepthIncrement;
        if (sphere_.tolerance > hi)
        {
            FatalIOErrorInFunction(d)
                << "entry 'tolerance' = "
                << foamTools::numberText(sphere_.tolerance).c_str()
                << " m is outside the valid range "
                << foamTools::rangeText
                   (
                       0.0, hi, false,
                       foamTools::numberText(sphere_.tolerance)
                   ).c_str()
                << " m: at most a "
                << "tenth of maxDepthIncrement (" << settings_.maxDepthIncrement
                << " m); a larger penetration lets the sphere sink into the "
                << "cell without its contact force" << exit(FatalIOError);
        }
    }

    // The largest sparse factorisation the run may start (addContact
    // estimates it; a 3D mesh sat for many minutes in the first one)
    maxFactorMemory_ = inRange(d, "maxFactorMemory", 1e9);
    maxFactorFlops_ = inRange(d, "maxFactorFlops", 1e11);

    protocol_ = std::make_shared<solid::IndentationProtocol>(readProtocol());

    // A step at most the table's rows: maxDepthIncrement above every load
    // and unload amount, or holdDeltaT0 above every hold, made each such
    // row one step (a force curve of its end points), silently (issue 19)
    {
        scalar depthMax = 0, holdMax = 0;
        for (const solid::ProtocolRow& row : protocol_->rows())
        {
            scalar& m = row.motion == "hold" ? holdMax : depthMax;
            m = max(m, scalar(row.amount));
        }
        if (depthMax > 0 && settings_.maxDepthIncrement > depthMax)
        {
            FatalIOErrorInFunction(d)
                << "entry 'maxDepthIncrement' = "
                << settings_.maxDepthIncrement << " m is longer than the "
                << "longest load or unload row of entry 'protocol' ("
                << depthMax << " m): each row would be one step; valid "
                << "range (0, " << depthMax << "] m" << exit(FatalIOError);
        }
        if (holdMax > 0 && settings_.holdDeltaT0 > holdMax)
        {
            FatalIOErrorInFunction(d)
                << "entry 'holdDeltaT0' = " << settings_.holdDeltaT0
                << " s is longer than the longest hold row of entry "
                << "'protocol' (" << holdMax << " s): each hold would be "
                << "one step; valid range (0, " << holdMax << "] s"
                << exit(FatalIOError);
        }
    }

    // The steps of the whole table, estimated from the step settings: a
    // hold at a constant holdDeltaT0 of 1e-299 s (holdGrowth 1) ran
    // without end (adv48b g44 (b): 1e299 steps). At most controlDict's
    // maxSteps (default 1e8, valid range [1, inf); the fluid solvers'
    // limit, foamTools::checkStepCount), counted per row as the driver
    // steps (solid::IndentationDriver::run): a load or unload row in steps
    // of min(maxDepthIncrement/rate, maxDeltaT), a hold from holdDeltaT0
    // growing by holdGrowth up to maxDeltaT
    {
        const scalar maxSteps = readInRangeOrDefault<scalar>
        (
            controlDict, "maxSteps", "", 1, foamTools::noUpperBound<scalar>(),
            true, 1e8
        );
        const scalar cap = 1e300;
        scalar total = 0;
        label worst = -1;
        scalar worstSteps = 0;
        const auto& rows = protocol_->rows();
        // every row counted (a formula per row), so that the figure
        // printed is the whole table's and accepted as the limit (adv49a
        // j07, adv49b i33: the sum up to the row past the limit was
        // printed, 3, then 13, 18, 23 as maxSteps was raised to each)
        for (label i = 0; i < label(rows.size()); ++i)
        {
            const solid::ProtocolRow& row = rows[i];
            scalar n = 0;
            if (row.motion == "hold")
            {
                const scalar T = row.amount;
                const scalar dt0 =
                    min(settings_.holdDeltaT0, settings_.maxDeltaT);
                const scalar g = settings_.holdGrowth;
                const scalar dtMax = settings_.maxDeltaT;
                if (g == 1 || dt0 >= dtMax)
                {
                    n = std::ceil(T/dt0);
                }
                else
                {
                    // k growing steps reach dtMax, covering S
                    const scalar k =
                        std::ceil(std::log(dtMax/dt0)/std::log(g));
                    const scalar S = dt0*(std::pow(g, k) - 1)/(g - 1);
                    n = S >= T
                      ? std::ceil(std::log1p(T*(g - 1)/dt0)/std::log(g))
                      : k + std::ceil((T - S)/dtMax);
                }
            }
            else if (row.rate > 0)
            {
                const scalar dt = min
                (
                    settings_.maxDepthIncrement/row.rate, settings_.maxDeltaT
                );
                n = std::ceil((row.amount/row.rate)/dt);
            }
            n = std::isfinite(n) ? min(n, cap) : cap;
            if (n > worstSteps)
            {
                worstSteps = n;
                worst = i;
            }
            total = min(total + n, cap);
        }
        if (total > maxSteps)
        {
            const solid::ProtocolRow& row = rows[worst];
            FatalIOErrorInFunction(d)
                << "the loading table would take about "
                << foamTools::countAboveText(total, maxSteps).c_str()
                << " steps, more than entry 'maxSteps' = "
                << foamTools::countText(maxSteps).c_str()
                << " of system/controlDict (default 100000000): row "
                << worst + 1 << " of entry 'protocol' (" << row.motion.c_str()
                << ") alone takes about "
                << foamTools::countAboveText(worstSteps, 0).c_str()
                << " steps (holdDeltaT0 = "
                << foamTools::numberText(settings_.holdDeltaT0).c_str()
                << " s, holdGrowth = "
                << foamTools::numberText(settings_.holdGrowth).c_str()
                << ", maxDeltaT = "
                << foamTools::numberText(settings_.maxDeltaT).c_str()
                << " s, maxDepthIncrement = "
                << foamTools::numberText(settings_.maxDepthIncrement).c_str()
                << " m). Nothing was run: lengthen the steps, or raise "
                << "'maxSteps' (valid range [1, inf)) if so many are meant"
                << exit(FatalIOError);
        }
    }

    // The table starts at 0 s: a startTime other than 0 in controlDict was
    // taken by OpenFOAM's Time and ignored by the table (issue 19). A
    // restart continues from restart.h5 (startFrom latestTime), not from
    // startTime
    if (controlDict.found("startTime"))
    {
        const scalar t0 = readInRange<scalar>
        (
            controlDict, "startTime", "s", -GREAT, GREAT, true
        );
        if (t0 != 0)
        {
            FatalIOErrorInFunction(controlDict)
                << "entry 'startTime' = " << t0 << " s is outside the valid "
                << "range [0, 0] s: cellIndentationFoam starts the loading "
                << "table (constant/indenterProperties, entry 'protocol') "
                << "at 0 s; a run continues from its checkpoint with "
                << "startFrom latestTime, not from a startTime"
                << exit(FatalIOError);
        }
    }
    // endTime: the table decides the end of the run (its last row); an
    // endTime of controlDict is only OpenFOAM's Time's, printed with the
    // table (addContact) when it differs
    if (controlDict.found("endTime"))
    {
        endTime_ = readInRange<scalar>
        (
            controlDict, "endTime", "s", 0, GREAT, true
        );
    }

    // The Time's entries cellIndentationFoam does not use, said as endTime
    // is, whatever their value (adv33 cd03: deltaT 0 accepted without a
    // word): the steps are indenterProperties', the outputs ours
    {
        DynamicList<word> unused;
        for
        (
            const char* key :
            {
                "deltaT", "writeControl", "writeInterval", "writeFrequency",
                "adjustTimeStep", "maxCo", "maxDeltaT", "purgeWrite"
            }
        )
        {
            if (controlDict.found(key))
            {
                unused.append(key);
            }
        }
        if (unused.size())
        {
            Info<< "Note: system/controlDict's";
            for (const word& key : unused)
            {
                Info<< " " << key;
            }
            Info<< " (OpenFOAM's Time's entries) are not used by"
                << " cellIndentationFoam, whatever their values: its steps"
                << " are constant/indenterProperties' maxDepthIncrement,"
                << " holdDeltaT0, maxDeltaT and holdGrowth, its outputs"
                << " controlDict's fieldWriteInterval and checkpointInterval"
                << nl << endl;
        }
    }

    settings_.writeInterval = readInRange<scalar>
    (
        controlDict, "fieldWriteInterval", "s", 0, GREAT, true
    );
    settings_.checkpointInterval = readInRangeOrDefault<label>
    (
        controlDict, "checkpointInterval", "steps", 0, 1000000000, true, 10
    );
    // force.dat and peaks.dat at the precision of the case's other outputs
    settings_.precision = IOstream::defaultPrecision();
    settings_.log = &std::cout;

    newton_.maxCuts = 10;
    if (d.getOrDefault<bool>("logNewton", false))
    {
        newton_.log = &std::cout;
    }

    continueRun_ =
        controlDict.getOrDefault<word>("startFrom", "startTime")
     == "latestTime";
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

std::vector<solid::ProtocolRow> Foam::indentationInput::readProtocol() const
{
    if (!dict_.found("protocol"))
    {
        FatalIOErrorInFunction(dict_)
            << "missing entry 'protocol' (list of (stage motion rate "
            << "amount) rows)" << exit(FatalIOError);
    }
    ITstream& is = dict_.lookup("protocol");
    std::vector<solid::ProtocolRow> rows;
    auto bad = [&](const std::string& why)
    {
        FatalIOErrorInFunction(dict_)
            << "entry 'protocol', row " << rows.size() + 1 << ": " << why
            << "; expected (stage load|unload|hold rate[m/s] "
            << "amount[m or s])" << exit(FatalIOError);
    };
    token t(is);
    if (!t.isPunctuation() || t.pToken() != token::BEGIN_LIST)
    {
        bad("the table must start with '('");
    }
    while (true)
    {
        token r(is);
        if (r.isPunctuation() && r.pToken() == token::END_LIST) break;
        if (!r.isPunctuation() || r.pToken() != token::BEGIN_LIST)
        {
            bad("a row must start with '('");
        }
        // The row's items up to its ')', named in the message: a number
        // written 0x1p-22 or +3e-6 is two tokens to OpenFOAM's reader,
        // and the row was "more than four items" without a word why
        // (adv46b d37; readInRange's wording for a single entry)
        DynamicList<token> items;
        while (true)
        {
            token x(is);
            if
            (
                !x.good()
             || (x.isPunctuation() && x.pToken() == token::BEGIN_LIST)
            )
            {
                bad("a row must end with ')' after its four items");
            }
            if (x.isPunctuation() && x.pToken() == token::END_LIST)
            {
                break;
            }
            items.append(x);
        }
        OStringStream text;
        text.precision(12);     // 1e-06, not 9.9999999999999995e-07
        forAll(items, i)
        {
            text << (i ? " " : "") << items[i];
        }
        const std::string given("(" + std::string(text.str()) + ")");
        if (items.size() != 4)
        {
            bool split = false;
            for (label i = 1; i < items.size(); ++i)
            {
                split = split
                 || (
                        items[i - 1].isNumber() && items[i].isWord()
                     && items[i].wordToken().size()
                     && (items[i].wordToken()[0] == 'x'
                      || items[i].wordToken()[0] == 'X')
                    );
            }
            for (const token& x : items)
            {
                split = split || x.isPunctuation();
            }
            bad
            (
                given + " has " + std::to_string(items.size()) + " items, not"
                " four"
              + (
                    split
                  ? std::string(" (a number written with a prefix such as 0x"
                    " or a '+' sign is read as 2 tokens: write each number"
                    " as a plain decimal number)")
                  : std::string()
                )
            );
        }
        if
        (
            !items[0].isWord() || !items[1].isWord()
         || !items[2].isNumber() || !items[3].isNumber()
        )
        {
            bad(given + ": wrong types (two words, then two numbers)");
        }
        solid::ProtocolRow row;
        row.stage = items[0].wordToken();
        row.motion = items[1].wordToken();
        row.rate = items[2].number();
        row.amount = items[3].number();
        rows.push_back(row);
    }
    foamTools::checkEntryEnd
    (
        dict_, "protocol", is,
        "one list of (stage load|unload|hold rate[m/s] amount[m or s]) rows"
    );
    try
    {
        solid::IndentationProtocol check(rows);
    }
    catch (const solid::SolidError& err)
    {
        FatalIOErrorInFunction(dict_)
            << "entry 'protocol': " << err.what() << exit(FatalIOError);
    }
    return rows;
}


void Foam::indentationInput::checkFactorisation(solid::Model& model) const
{
    // The count goes on past the limits (it stopped just above them:
    // maxFactorMemory 1 refused "at least 17880 B", then 17880 refused "at
    // least 17952 B", adv47b f71) to 4 times them, and at least to the
    // default limits' size (2e9 B, 4e11 flop: a few seconds of counting),
    // so that the figure printed is the whole estimate unless far above
    // both, and a limit set to it is accepted
    const solid::FactorisationEstimate e = solid::estimateFactorisation
    (
        model.tangentPattern(), std::max(4*maxFactorMemory_, 2e9),
        std::max(4*maxFactorFlops_, 4e11)
    );
    const bool memory = e.memory > maxFactorMemory_;
    const bool flops = e.operations > maxFactorFlops_;
    const solid::Mesh& mesh = model.mesh();
    Info<< "Newton's linear systems: " << e.n << " unknowns, a sparse "
        << "factorisation of " << (e.complete ? "about " : "at least ")
        << e.memory << " B and " << e.operations << " flop (estimate; "
        << "limits maxFactorMemory " << maxFactorMemory_ << " B, "
        << "maxFactorFlops " << maxFactorFlops_ << " flop)" << nl << endl;
    if (!memory && !flops)
    {
        return;
    }
    const word entry(memory ? "maxFactorMemory" : "maxFactorFlops");
    const scalar limit(memory ? maxFactorMemory_ : maxFactorFlops_);
    const scalar hi(memory ? 1e15 : 1e18);
    const char* unit(memory ? "B" : "flop");
    FatalIOErrorInFunction(dict_)
        << "the cell mesh (" << mesh.nElements() << " elements, "
        << mesh.nNodes() << " nodes, "
        << (mesh.axisymmetric() ? "axisymmetric" : "3D") << ": " << e.n
        << " unknowns) needs a sparse factorisation of the Newton matrix "
        << (e.complete ? "of about " : "of at least ")
        << foamTools::countAboveText
           (
               memory ? e.memory : e.operations, limit
           ).c_str() << ' ' << unit
        << (memory ? " of memory" : " per Newton iteration")
        << " (estimate from its sparsity pattern: minimum-degree ordering, "
        << "the factor's non-zeros), more than entry '" << entry << "' = "
        << limit << ' ' << unit << " (default "
        << (memory ? "1e+09" : "1e+11") << ' ' << unit << "): the run would"
        << " sit for a long time in its first factorisation. Use a coarser "
        << "mesh (the axisymmetric cell costs a small fraction), or raise '"
        << entry << "' in constant/indenterProperties (valid range (0, "
        << hi << "] " << unit << ") if the machine has the memory and the "
        << "time" << exit(FatalIOError);
}


Foam::label Foam::indentationInput::rowOf(const std::string& name)
{
    const std::string marker("entry 'protocol', row ");
    const auto at = name.find(marker);
    return at == std::string::npos
        ? 0 : std::stol(name.substr(at + marker.size()));
}


void Foam::indentationInput::checkRestart
(
    const fileName& checkpoint,
    const foamTools::inputRecord::digestMap& inputs,
    const std::map<std::string, std::string>& sources
) const
{
    using foamTools::inputRecord;
    if (!continueRun_ || !solid::Checkpoint::exists(checkpoint))
    {
        return;
    }
    inputRecord::digestMap was, now;
    label lastRow = 0;
    try
    {
        const solid::Checkpoint c(solid::Checkpoint::read(checkpoint));
        if (!c.hasText("inputDigests"))
        {
            // A checkpoint of a version before the record
            Info<< "Warning: " << checkpoint << " holds no record of its "
                << "inputs (written by an earlier version): the inputs "
                << "are not compared" << nl << endl;
            return;
        }
        was = inputRecord::parse(c.text("inputDigests"));
        lastRow = label(c.scalar("row")) + 1;
    }
    catch (const solid::SolidError& err)
    {
        FatalErrorInFunction
            << "Cannot continue from " << checkpoint << ": " << err.what()
            << nl << "Set startFrom startTime in system/controlDict to "
            << "start again" << exit(FatalError);
    }
    // The rows after the checkpoint's have not run: they may change
    for (const auto& item : inputs)
    {
        if (rowOf(item.first) <= lastRow) now.insert(item);
    }
    for (auto it = was.begin(); it != was.end();)
    {
        it = rowOf(it->first) > lastRow ? was.erase(it) : std::next(it);
    }
    solidInput::sameVersion(now, was);
    const std::string list(inputRecord::differences(now, was, sources));
    if (!list.empty())
    {
        FatalErrorInFunction
            << "Cannot continue from " << checkpoint << ": its state was "
            << "computed with other inputs than those of the case now (the "
            << "restart would continue the results with other inputs):"
            << list.c_str() << nl
            << "    Nothing was changed. Restore those inputs to continue "
            << "(rows of the loading table after row " << lastRow
            << ", not yet run, may change); to use the new ones, start "
            << "anew (startFrom startTime, -overwrite) or run a copy of "
            << "the case." << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::foamTools::inputRecord::digestMap
Foam::indentationInput::digests() const
{
    using foamTools::inputRecord;
    const std::string file("constant/indenterProperties, entry ");
    inputRecord::digestMap record;
    auto add = [&](const std::string& name, const auto& value)
    {
        std::ostringstream os;
        os.precision(17);
        os << value;
        record[file + "'" + name + "'"] = inputRecord::sha1(os.str());
    };
    add("radius", sphere_.radius);
    add("tolerance", sphere_.tolerance);
    add("penaltyFactor", sphere_.penaltyFactor);
    add("contactPatch", std::string(contactPatch_));
    add("maxDepthIncrement", settings_.maxDepthIncrement);
    add("holdDeltaT0", settings_.holdDeltaT0);
    add("maxDeltaT", settings_.maxDeltaT);
    add("holdGrowth", settings_.holdGrowth);
    add("forceTarget", settings_.forceTarget);
    add("forceTargetTolerance", settings_.forceTargetTolerance);
    const std::vector<solid::ProtocolRow>& rows = protocol_->rows();
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        std::ostringstream os;
        os.precision(17);
        os << rows[i].stage << ' ' << rows[i].motion << ' ' << rows[i].rate
            << ' ' << rows[i].amount;
        record[file + "'protocol', row " + std::to_string(i + 1)] =
            inputRecord::sha1(os.str());
    }
    return record;
}



std::shared_ptr<solid::RigidSphereContact>
Foam::indentationInput::addContact(solid::Model& model) const
{
    const solid::Mesh& mesh = model.mesh();

    // The sphere above the highest point of the contact surface, on the
    // axis, moving down (-z in 3D, -z in r-z: the second coordinate)
    scalar zTop = -GREAT;
    try
    {
        for (const auto& f : mesh.faceSet(contactPatch_))
        {
            for (int n : f) zTop = max(zTop, mesh.X[n](mesh.dim() - 1));
        }
    }
    catch (const solid::SolidError& err)
    {
        FatalIOErrorInFunction(dict_)
            << "entry 'contactPatch': " << err.what() << exit(FatalIOError);
    }
    // The table must not push the sphere through the cell: its deepest
    // point below the top of the contact patch stays above the cell's
    // bottom (was: the steps failed in Newton's iterations, naming no
    // input; issue 19)
    {
        scalar zBottom = GREAT;
        for (const solid::Vec3& x : mesh.X)
        {
            zBottom = min(zBottom, x(mesh.dim() - 1));
        }
        // The sphere comes down from above the cell: the contact patch
        // must reach the cell's top (adv33 ip15: the substrate face set
        // fixedBottom was taken, and the table blamed for a depth "as
        // deep as the cell")
        scalar zMax = -GREAT;
        for (const solid::Vec3& x : mesh.X)
        {
            zMax = max(zMax, x(mesh.dim() - 1));
        }
        if (zTop < zMax - 1e-6*(zMax - zBottom))
        {
            FatalIOErrorInFunction(dict_)
                << "entry 'contactPatch' = '" << contactPatch_ << "': its"
                << " highest point, at z = " << zTop << " m, is below the"
                << " top of the cell at " << zMax << " m: the sphere comes"
                << " down onto the cell from above, the contact patch must"
                << " be the cell's top surface (e.g. outerSurface)"
                << exit(FatalIOError);
        }
        const scalar height = zTop - zBottom;
        const auto& rows = protocol_->rows();
        for (std::size_t i = 0; i < rows.size(); ++i)
        {
            const scalar depth = protocol_->depth(protocol_->rowEnd(i));
            if (depth >= height)
            {
                FatalIOErrorInFunction(dict_)
                    << "entry 'protocol', row " << label(i + 1) << " (stage "
                    << rows[i].stage.c_str() << "): the table indents the"
                    << " sphere " << depth << " m deep, as deep as or deeper"
                    << " than the cell (" << height << " m from the top of"
                    << " the contact patch '" << contactPatch_ << "' at "
                    << zTop << " m to the bottom at " << zBottom << " m):"
                    << " valid depths are below " << height << " m"
                    << " (amounts of load rows in m)" << exit(FatalIOError);
            }
        }
    }
    // The sphere must be resolved by the contact patch's faces: at the
    // deepest depth of the table the contact radius reaches past the faces
    // at the top (a radius of 1e-12 m touched one node, silently; issue 19)
    {
        const label top = mesh.dim() - 1;
        scalar h = 0;
        for (const auto& f : mesh.faceSet(contactPatch_))
        {
            bool atTop = false;
            for (int n : f) atTop = atTop || mesh.X[n](top) == zTop;
            if (!atTop) continue;
            for (std::size_t i = 0; i < f.size(); ++i)
            {
                const solid::Vec3 e =
                    mesh.X[f[(i + 1) % f.size()]] - mesh.X[f[i]];
                h = max(h, scalar(e.norm()));
            }
        }
        scalar depth = 0;
        for (std::size_t i = 0; i < protocol_->rows().size(); ++i)
        {
            depth = max(depth, protocol_->depth(protocol_->rowEnd(i)));
        }
        const scalar R = sphere_.radius;
        const scalar a = depth >= R ? R : std::sqrt(depth*(2*R - depth));
        if (depth > 0 && a < h)
        {
            // the smallest radius whose contact reaches h at this depth
            const scalar rMin = 0.5*(h*h/depth + depth);
            FatalIOErrorInFunction(dict_)
                << "entry 'radius' = " << R << " m is outside the valid "
                << "range [" << rMin << ", 1] m for this mesh and table: at "
                << "the table's deepest depth, " << depth << " m, the "
                << "contact radius would be " << a << " m, smaller than the "
                << "faces of the contact patch '" << contactPatch_ << "' at "
                << "its top (" << h << " m): the contact would be one node."
                << " Use a larger sphere, or a finer mesh under the contact"
                << " (cellMesh: contactSize)" << exit(FatalIOError);
        }
    }
    solid::RigidSphereSettings sphere(sphere_);
    sphere.centre0 = mesh.axisymmetric()
        ? solid::Vec3(0, zTop + sphere.radius, 0)
        : solid::Vec3(0, 0, zTop + sphere.radius);
    sphere.direction = mesh.axisymmetric()
        ? solid::Vec3(0, -1, 0) : solid::Vec3(0, 0, -1);
    const std::shared_ptr<solid::IndentationProtocol> protocol(protocol_);
    sphere.depth = [protocol](double t) { return protocol->depth(t); };

    auto contact =
        std::make_shared<solid::RigidSphereContact>(contactPatch_, sphere);
    model.add(contact);
    try
    {
        model.initialise();
    }
    catch (const solid::SolidError& err)
    {
        FatalErrorInFunction << err.what() << exit(FatalError);
    }
    checkFactorisation(model);
    // The contact's points now, not at the first step: a patch without
    // area (the axis in r-z) named as the entry that chose it
    try
    {
        contact->report(model, model.u, model.time);
    }
    catch (const solid::SolidError& err)
    {
        FatalIOErrorInFunction(dict_)
            << "entry 'contactPatch' = '" << contactPatch_.c_str() << "': "
            << err.what() << ": the contact patch must be a surface of the"
            << " cell with area (e.g. outerSurface)" << exit(FatalIOError);
    }

    Info<< "Indenter: radius " << sphere.radius << " m, top of the cell z = "
        << zTop << " m, penetration tolerance " << sphere.tolerance << " m"
        << nl << "Protocol: " << protocol_->rows().size() << " rows, "
        << protocol_->endTime() << " s";
    if (settings_.forceTarget > 0)
    {
        Info<< " (stage " << protocol_->rows()[0].stage << " ends when the "
            << "force reaches " << settings_.forceTarget << " N, at the "
            << "latest at depth " << protocol_->rows()[0].amount
            << " m: else an error)";
    }
    Info<< nl;
    if (endTime_ >= 0 && endTime_ != protocol_->endTime())
    {
        // The table decides; endTime is only OpenFOAM's Time's
        Info<< "Note: the run ends with the loading table at "
            << protocol_->endTime() << " s";
        if (settings_.forceTarget > 0)
        {
            Info<< " (at most: the first row ends at its force)";
        }
        Info<< ", not at system/controlDict's endTime " << endTime_
            << " s (not used by cellIndentationFoam: shorten or lengthen"
            << " the table, entry 'protocol', to change the run)" << nl;
    }
    Info<< endl;
    return contact;
}


std::unique_ptr<solid::IndentationDriver> Foam::indentationInput::driver
(
    solid::Model& model,
    const std::shared_ptr<solid::RigidSphereContact>& contact,
    const fileName& outDir,
    const foamTools::inputRecord::digestMap& inputs,
    const std::map<std::string, std::string>& sources
) const
{
    const bool resume = resumes(outDir);
    checkRestart(outDir/"restart.h5", inputs, sources);
    solid::IndentationSettings settings(settings_);
    settings.inputDigests = foamTools::inputRecord::format(inputs);
    // The identity of a new run: its inputs and what decides the steps of
    // solid.h5 (a run of the same inputs writes the same files, so that a
    // restart stays bitwise an uninterrupted run's)
    std::ostringstream runText;
    runText.precision(17);
    runText
        << settings.inputDigests << "fieldWriteInterval "
        << settings.writeInterval << '\n';
    settings.runId = foamTools::inputRecord::sha1(runText.str());
    // -overwrite: the earlier run's results stay (moved aside) until this
    // run has a checkpoint or its end (adv35 o14: a first step that failed
    // had emptied force.dat and peaks.dat and removed restart.h5)
    settings.committed = []{ foamTools::resultGuard::confirmOverwrite(); };
    std::unique_ptr<solid::IndentationDriver> driver;
    try
    {
        driver.reset
        (
            new solid::IndentationDriver
            (
                model, contact, protocol_, newton_, settings, outDir
            )
        );
        driver->start(resume);
    }
    catch (const solid::SolidError& err)
    {
        if (resume)
        {
            FatalErrorInFunction
                << "Cannot continue from " << outDir/"restart.h5" << ": "
                << err.what() << nl << "Set startFrom startTime in "
                << "system/controlDict to start again" << exit(FatalError);
        }
        FatalErrorInFunction
            << "Cannot start in " << outDir << ": " << err.what()
            << exit(FatalError);
    }
    return driver;
}


// ************************************************************************* //
