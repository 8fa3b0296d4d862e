#include "IndentationDriver.H"
#include <sstream>
#include "AtomicFile.H"
#include "Checkpoint.H"
#include "SolidError.H"
#include "fileDigest.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace fs = std::filesystem;


solid::IndentationDriver::IndentationDriver
(
    Model& model,
    std::shared_ptr<RigidSphereContact> contact,
    std::shared_ptr<IndentationProtocol> protocol,
    const NewtonSettings& newton,
    const IndentationSettings& settings,
    const std::string& outDir
)
:
    model_(model),
    contact_(std::move(contact)),
    protocol_(std::move(protocol)),
    settings_(settings),
    outDir_(outDir),
    solver_(model, newton)
{
    std::error_code ec;
    fs::create_directories(outDir_, ec);
    if (ec)
    {
        throw SolidError
        (
            SolidError::Kind::io,
            "cannot create " + outDir_ + ": " + ec.message()
        );
    }
}


solid::IndentationDriver::~IndentationDriver() = default;


std::string solid::IndentationDriver::path(const std::string& name) const
{
    return outDir_ + "/" + name;
}


void solid::IndentationDriver::checkResume()
{
    resumeFrom_.reset(new Checkpoint(Checkpoint::read(checkpointFile())));
    // Everything checked before any output is touched: a checkpoint of
    // another mesh, model or table is refused here
    const Checkpoint& c = *resumeFrom_;
    // The outputs must be this run's (a checkpoint of an earlier build has
    // no run id: then only solid.h5's checksums are checked) and solid.h5
    // undamaged anywhere, not only in the steps a restart reads
    runId_ = c.hasText("runId") ? c.text("runId") : "";
    ResultWriter::checkContinued(path("solid.h5"), runId_);
    if (!runId_.empty())
    {
        for (const char* f : {"force.dat", "peaks.dat"})
        {
            std::ifstream is(path(f));
            if (!is)
            {
                // missing (adv33 c24: was "belongs to another run: its
                // first line is ''")
                throw SolidError
                (
                    SolidError::Kind::io, path(f) + " is missing (or cannot"
                    " be read): the checkpoint " + checkpointFile()
                  + " continues run " + runId_ + ", whose " + f + " a"
                    " restart appends to. Restore it to continue; nothing"
                    " was changed"
                );
            }
            std::string first;
            std::getline(is, first);
            const std::size_t zero = first.find('\0');
            if (first != "# run " + runId_ && zero != std::string::npos)
            {
                // zero bytes where the run wrote its header: the file was
                // damaged (a power loss; adv40 z05 (d) was "belongs to
                // another run: its first line is '<NULs>'")
                throw SolidError
                (
                    SolidError::Kind::io, path(f) + " is damaged: it holds"
                    " zero bytes from byte " + std::to_string(zero + 1)
                  + " of its first line, where the run wrote '# run "
                  + runId_ + "' (a power loss or a disk error after the"
                    " run wrote it); the checkpoint " + checkpointFile()
                  + " continues run " + runId_ + ", whose " + f + " a"
                    " restart appends to. Restore the file as the run wrote"
                    " it, or start anew (-overwrite); nothing was changed"
                );
            }
            // The run's file with its first line damaged (adv42 g20: one
            // bit of peaks.dat's '# run' line flipped was "another run"):
            // its bytes up to the checkpoint, the run's line in place of
            // the first, are those the checkpoint's digest was made of
            const std::string own("# run " + runId_);
            const std::string key(std::string(f) + ".fnv1a64");
            if
            (
                first != own && first.size() == own.size()
             && c.hasText(key)
            )
            {
                const std::string line(own + "\n");
                std::uint64_t h =
                    fileDigest::add(fileDigest::basis, line.data(), line.size());
                std::uintmax_t zero = std::uintmax_t(-1);
                const double len = c.scalar(std::string(f) + ".length");
                if
                (
                    len >= double(line.size())
                 && fileDigest::bytes
                    (
                        path(f), line.size(), std::uintmax_t(len), h, zero
                    )
                 && c.text(key) == fileDigest::hex(h)
                )
                {
                    throw SolidError
                    (
                        SolidError::Kind::io, path(f) + " is damaged in"
                        " its first line, or belongs to another run of the"
                        " same inputs: its first line is '"
                      + first.substr(0, 80) + "' where this run wrote '"
                      + own + "', and its other bytes up to the checkpoint "
                      + checkpointFile() + " are those this run wrote (a"
                        " disk error or an edit of that line, or a copy of"
                        " the file of a run with the same inputs). Restore"
                        " the line to continue, or start anew"
                        " (-overwrite); nothing was changed"
                    );
                }
            }
            if (first != "# run " + runId_)
            {
                throw SolidError
                (
                    SolidError::Kind::io, path(f) + " belongs to another "
                    "run: its first line is '" + first.substr(0, 80)
                  + "', the checkpoint " + checkpointFile() + " continues"
                    " run " + runId_ + " (a file copied from another case "
                    "or run, or replaced since): a restart continues only "
                    "the files of its own run"
                );
            }
        }
    }
    c.restoreModel("model/", model_);
    contact_->report(model_, model_.u, model_.time);
    contact_->setMultipliers(c.get("contact/multipliers"));
    for
    (
        const char* e :
        {
            "contact/force", "contact/contactRadius",
            "contact/maxPenetration", "contact/nActive", "row",
            "holdDt", "extrapolate", "nextWrite", "delta0Found",
            "fieldSteps"
        }
    )
    {
        c.scalar(e);
    }
    c.get("rate", model_.u.size());
    c.get("counters", 6);
    const double row = c.scalar("row");
    if (row < 0 || row >= protocol_->rows().size())
    {
        throw SolidError
        (
            SolidError::Kind::io, "entry 'row' = " + std::to_string(row)
          + " is not a row of the loading table of "
            "constant/indenterProperties (changed since?)"
        );
    }
    // The output files must be at least as long as when checkpointed,
    // and hold up to that length what the run wrote (its digest: zero
    // bytes or a row cut or edited inside were continued without a word,
    // adv35 k32, k33); both checked before either is cut back
    int k = 0;
    for (const char* f : {"force.dat", "peaks.dat"})
    {
        const double len = c.scalar(std::string(f) + ".length");
        std::error_code ec;
        if
        (
            !fs::is_regular_file(path(f), ec)
         || double(fs::file_size(path(f), ec)) < len
        )
        {
            throw SolidError
            (
                SolidError::Kind::io, path(f) + " is missing or shorter "
                "than when the checkpoint was written ("
              + std::to_string(long(len)) + " bytes)"
            );
        }
        std::uint64_t h = fileDigest::basis;
        std::uintmax_t zero = std::uintmax_t(-1);
        const std::string key = std::string(f) + ".fnv1a64";
        if
        (
            !fileDigest::bytes(path(f), 0, std::uintmax_t(len), h, zero)
         || (c.hasText(key) && c.text(key) != fileDigest::hex(h))
        )
        {
            std::ostringstream os;
            os  << path(f) << " changed after the run wrote it: its first "
                << long(len) << " bytes (the rows up to the checkpoint "
                << checkpointFile() << ", t = " << c.scalar("model/time")
                << " s) differ from the digest the checkpoint recorded";
            if (zero != std::uintmax_t(-1))
            {
                // the line of the first zero byte
                std::ifstream is(path(f), std::ios::binary);
                long line = 1;
                for (std::uintmax_t b = 0; b < zero && is; ++b)
                {
                    line += (is.get() == '\n');
                }
                os  << "; it holds zero bytes from byte " << zero
                    << " (line " << line << ")";
            }
            os  << ". A restart would continue a damaged or edited file:"
                " nothing was changed. Restore it, or start anew"
                " (startFrom startTime, -overwrite)";
            throw SolidError(SolidError::Kind::io, os.str());
        }
        logDigest_[k] = h;
        logDigested_[k] = std::uintmax_t(len);
        ++k;
    }
    for (const char* f : {"force.dat", "peaks.dat"})
    {
        const double len = c.scalar(std::string(f) + ".length");
        // cut back and appended to in place: a file of its own first, not
        // one shared with a copy of the case by hard links (adv52 p26)
        ownCopy(path(f));
        std::error_code ec;
        fs::resize_file(path(f), std::uintmax_t(len), ec);
        if (ec)
        {
            throw SolidError
            (
                SolidError::Kind::io, "cannot cut " + path(f) + " back to "
              + std::to_string(long(len)) + " bytes: " + ec.message()
            );
        }
    }
    truncateSteps(path("solid.h5"), int(c.scalar("fieldSteps")));
}


void solid::IndentationDriver::openOutputs()
{
    const auto mode = resume_ ? std::ios::app : std::ios::trunc;
    // written in place: a file of its own, not one shared with a copy of
    // the case by hard links (adv52 p26)
    ownCopy(path("force.dat"));
    ownCopy(path("peaks.dat"));
    forceFile_.open(path("force.dat"), std::ios::out | mode);
    forceFile_.precision(settings_.precision);
    openDigests();
    if (!resume_)
    {
        if (!runId_.empty()) writeLine(0, "# run " + runId_ + "\n");
        writeLine
        (
            0, "# time [s]  depth [m]  force [N]  contactRadius [m]  "
               "maxPenetration [m]  stage\n"
        );
    }
    fields_.reset(new ResultWriter(path("solid"), model_, resume_, runId_));
    fieldSteps_ = resume_ ? int(resumeFrom_->scalar("fieldSteps")) : 0;
    peakFile_.open(path("peaks.dat"), std::ios::out | mode);
    peakFile_.precision(settings_.precision);
    if (!resume_)
    {
        if (!runId_.empty()) writeLine(1, "# run " + runId_ + "\n");
        writeLine(1, "# label  time [s]  depth [m]  force [N]\n");
    }
    if (!forceFile_ || !peakFile_)
    {
        throw SolidError
        (
            SolidError::Kind::io, "cannot open " + path("force.dat")
          + " and " + path("peaks.dat") + " for writing"
          + spaceNote(path("force.dat"))
        );
    }
}


void solid::IndentationDriver::restoreState()
{
    const Checkpoint& c = *resumeFrom_;
    c.restoreModel("model/", model_);
    contact_->report(model_, model_.u, model_.time);
    contact_->setMultipliers(c.get("contact/multipliers"));
    last_.force = c.scalar("contact/force");
    last_.contactRadius = c.scalar("contact/contactRadius");
    last_.maxPenetration = c.scalar("contact/maxPenetration");
    last_.nActive = int(c.scalar("contact/nActive"));
    row0_ = long(c.scalar("row"));
    holdDt_ = c.scalar("holdDt");
    extrapolate_ = c.scalar("extrapolate") != 0;
    rate_ = c.vector("rate", model_.u.size());
    nextWrite_ = c.scalar("nextWrite");
    delta0Found_ = c.scalar("delta0Found");
    const std::vector<double>& n = c.get("counters", 6);
    counters_.steps = long(n[0]);
    counters_.iterations = long(n[1]);
    counters_.augmentations = long(n[2]);
    counters_.cuts = long(n[3]);
    counters_.assemblySeconds = n[4];
    counters_.solveSeconds = n[5];
    if (delta0Found_ > 0)
    {
        *protocol_ = protocol_->withFirstRowAmount(delta0Found_);
    }
}


void solid::IndentationDriver::start(bool resume)
{
    resume_ = resume;
    if (resume_)
    {
        checkResume();
    }
    else
    {
        std::remove(checkpointFile().c_str());
        runId_ = settings_.runId;
        logDigest_[0] = logDigest_[1] = fileDigest::basis;
        logDigested_[0] = logDigested_[1] = 0;
    }
    openOutputs();
    counters_ = IndentationCounters();
    last_ = ContactReport();
    nextWrite_ = settings_.writeInterval;
    extrapolate_ = false;
    rate_ = Eigen::VectorXd::Zero(model_.u.size());
    row0_ = 0;
    holdDt_ = settings_.holdDeltaT0;
    delta0Found_ = -1;
    if (resume_)
    {
        restoreState();
        if (settings_.log)
        {
            *settings_.log
                << "Continuing from " << checkpointFile() << ": t = "
                << model_.time << " s, row " << row0_ + 1 << ", step "
                << counters_.steps << '\n' << std::endl;
        }
    }
}


void solid::IndentationDriver::writeFields()
{
    fields_->write(model_);
    ++fieldSteps_;
}


void solid::IndentationDriver::advance(double dt)
{
    // Predictor: while the indenter moves at a constant rate the
    // displacement is close to linear in time (see the class description)
    const Eigen::VectorXd uStart = model_.u;
    if (extrapolate_) model_.u += dt*rate_;
    const StepReport r = solver_.step(dt);
    rate_ = (model_.u - uStart)/dt;
    ++counters_.steps;
    counters_.iterations += r.iterations;
    counters_.augmentations += r.augmentations;
    counters_.cuts += r.cuts;
    counters_.assemblySeconds += r.assemblySeconds;
    counters_.solveSeconds += r.solveSeconds;
    last_ = contact_->report(model_, model_.u, model_.time);
}


void solid::IndentationDriver::openDigests()
{
    for (int k = 0; k < 2; ++k)
    {
        const std::string f(path(k ? "peaks.dat" : "force.dat"));
        const std::string side(f + ".fnv1a64");
        std::vector<std::string> kept;
        if (resume_)
        {
            // the checkpoint's part: the digest lines up to its length
            // (the rows after it are cut back and computed again), and
            // the running digest from the checkpoint's
            lineDigest_[k] = logDigest_[k];
            lineBytes_[k] = logDigested_[k];
            std::ifstream is(side, std::ios::binary);
            std::string text
            (
                (std::istreambuf_iterator<char>(is)),
                std::istreambuf_iterator<char>()
            );
            // whole lines only: one cut by a kill (no end of line) ends
            // the part
            text.erase(text.rfind('\n') == std::string::npos
                     ? 0 : text.rfind('\n') + 1);
            std::istringstream lines(text);
            std::string line;
            while (std::getline(lines, line))
            {
                std::istringstream ls(line);
                std::uintmax_t n = 0;
                std::string h;
                if (!(ls >> n >> h) || n > lineBytes_[k])
                {
                    break;
                }
                kept.push_back(line);
            }
            if
            (
                kept.empty()
             || kept.back() != std::to_string(lineBytes_[k]) + " "
                  + fileDigest::hex(lineDigest_[k])
            )
            {
                kept.push_back
                (
                    std::to_string(lineBytes_[k]) + " "
                  + fileDigest::hex(lineDigest_[k])
                );
            }
        }
        else
        {
            lineDigest_[k] = fileDigest::basis;
            lineBytes_[k] = 0;
        }
        // a file of its own (a hard-linked copy of the case keeps its
        // own, adv52 p26), written anew by replacement
        const std::string tmp(temporaryName(side));
        {
            std::ofstream os(tmp, std::ios::out | std::ios::trunc);
            for (const std::string& l : kept) os << l << '\n';
            if (!os.flush())
            {
                throw SolidError
                (
                    SolidError::Kind::io, "cannot write " + tmp
                  + spaceNote(tmp)
                );
            }
        }
        commitFile(tmp, side);
        digestFile_[k].open(side, std::ios::out | std::ios::app);
        if (!digestFile_[k])
        {
            throw SolidError
            (
                SolidError::Kind::io, "cannot open " + side + " for writing"
              + spaceNote(side)
            );
        }
    }
}


void solid::IndentationDriver::writeLine(int k, const std::string& line)
{
    std::ofstream& os = k ? peakFile_ : forceFile_;
    // the row reaches the file before its digest line (a killed run's
    // sidecar never records bytes the file does not hold)
    os << line << std::flush;
    lineDigest_[k] = fileDigest::add(lineDigest_[k], line.data(), line.size());
    lineBytes_[k] += line.size();
    digestFile_[k]
        << lineBytes_[k] << ' ' << fileDigest::hex(lineDigest_[k]) << '\n';
}


void solid::IndentationDriver::record(const std::string& stage)
{
    std::ostringstream os;
    os.precision(settings_.precision);
    os  << model_.time << ' ' << protocol_->depth(model_.time) << ' '
        << last_.force << ' ' << last_.contactRadius << ' '
        << last_.maxPenetration << ' ' << stage << '\n';
    writeLine(0, os.str());
}


solid::IndentationDriver::Saved solid::IndentationDriver::save() const
{
    return Saved{ModelSnapshot(model_), contact_->multipliers(), last_};
}


void solid::IndentationDriver::restore(const Saved& s)
{
    s.model.restore(model_);
    contact_->setMultipliers(s.lambda);
    last_ = s.report;
}


void solid::IndentationDriver::peakLine(const std::string& label)
{
    const double depth = protocol_->depth(model_.time);
    std::ostringstream os;
    os.precision(settings_.precision);
    os  << label << ' ' << model_.time << ' ' << depth << ' '
        << last_.force << '\n';
    writeLine(1, os.str());
    if (settings_.log)
    {
        *settings_.log
            << "    " << label << ": t = " << model_.time << " s, depth "
            << depth << " m, force " << last_.force << " N" << std::endl;
    }
}


void solid::IndentationDriver::checkpoint(long row)
{
    Checkpoint c(checkpointFile());
    c.storeModel("model/", model_);
    c.set("contact/multipliers", contact_->multipliers());
    c.set("contact/force", last_.force);
    c.set("contact/contactRadius", last_.contactRadius);
    c.set("contact/maxPenetration", last_.maxPenetration);
    c.set("contact/nActive", double(last_.nActive));
    c.set("row", double(row));
    c.set("holdDt", holdDt_);
    c.set("extrapolate", double(extrapolate_));
    c.set("rate", rate_);
    c.set("nextWrite", nextWrite_);
    c.set("delta0Found", delta0Found_);
    c.set("counters", std::vector<double>
    {
        double(counters_.steps), double(counters_.iterations),
        double(counters_.augmentations), double(counters_.cuts),
        counters_.assemblySeconds, counters_.solveSeconds
    });
    c.set("fieldSteps", double(fieldSteps_));
    c.setText("inputDigests", settings_.inputDigests);
    if (!runId_.empty()) c.setText("runId", runId_);
    // The lengths the outputs have now (flushed)
    forceFile_.flush();
    peakFile_.flush();
    digestFile_[0].flush();
    digestFile_[1].flush();
    int k = 0;
    for (const char* f : {"force.dat", "peaks.dat"})
    {
        const std::uintmax_t len = outputLength(f);
        c.set(std::string(f) + ".length", double(len));
        // The digest continued over the bytes written since the last one
        std::uintmax_t zero = std::uintmax_t(-1);
        if
        (
            !fileDigest::bytes
            (
                path(f), logDigested_[k], len, logDigest_[k], zero
            )
        )
        {
            throw SolidError
            (
                SolidError::Kind::io, "cannot read back " + path(f)
              + " (changed during the run?)"
            );
        }
        logDigested_[k] = len;
        c.setText
        (
            std::string(f) + ".fnv1a64", fileDigest::hex(logDigest_[k])
        );
        ++k;
    }
    c.write();
    if (settings_.committed) settings_.committed();
}


std::uintmax_t solid::IndentationDriver::outputLength(const std::string& f)
{
    // A write that failed (a full disk) or an output removed during the
    // run is an error naming the file, not a std::filesystem exception
    // that ended the run in std::terminate (issue 19, class 4)
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path(f), ec);
    if (ec || !(f == "force.dat" ? forceFile_ : peakFile_))
    {
        throw SolidError
        (
            SolidError::Kind::io, "cannot write " + path(f) + ": "
          + (ec ? ec.message() + " (removed during the run?)"
                : std::string("the write failed (disk full?)"))
        );
    }
    return size;
}


void solid::IndentationDriver::run()
{
    const IndentationSettings& s = settings_;
    const long nRows = long(protocol_->rows().size());
    for (long i = row0_; i < nRows; ++i)
    {
        // A copy: the first row's amount may change below
        const ProtocolRow row = protocol_->rows()[i];
        const bool hold = row.motion == "hold";
        const bool untilForce = (i == 0 && s.forceTarget > 0 && !hold);
        if (s.log)
        {
            *s.log
                << "Row " << i + 1 << ": stage " << row.stage << ' '
                << row.motion << " to t = " << protocol_->rowEnd(i)
                << " s" << std::endl;
        }
        if (!(resume_ && i == row0_))
        {
            holdDt_ = s.holdDeltaT0;
            extrapolate_ = false;
        }
        while
        (
            model_.time
          < protocol_->rowEnd(i) - 1e-9*protocol_->rowEnd(i)
        )
        {
            double dt = hold ? holdDt_ : s.maxDepthIncrement/row.rate;
            dt = std::min
            (
                std::min(dt, s.maxDeltaT), protocol_->rowEnd(i) - model_.time
            );
            // Capped where it is stored, not only where it is used: a row
            // of more than ln(DBL_MAX/holdDeltaT0)/ln(holdGrowth) steps
            // (1760 at 1e-4 s and 1.5) overflowed it to inf, a sigFpe
            // under OpenFOAM's trapping (adv35 s15, s16, s20). The steps
            // are unchanged: min(holdDt_, maxDeltaT) is the same either way
            holdDt_ = std::min(holdDt_*s.holdGrowth, s.maxDeltaT);
            const Saved before = save();
            advance(dt);
            extrapolate_ = !hold;
            if (untilForce && last_.force >= s.forceTarget)
            {
                // Secant on F(depth) from the last step below the target
                Saved lo = before;
                double tLo = before.model.time(), fLo = before.report.force;
                double tHi = model_.time, fHi = last_.force;
                for (int k = 0; k < 8; ++k)
                {
                    if
                    (
                        std::abs(last_.force/s.forceTarget - 1)
                     <= s.forceTargetTolerance
                    )
                    {
                        break;
                    }
                    const double tNew =
                        tLo + (s.forceTarget - fLo)*(tHi - tLo)/(fHi - fLo);
                    restore(lo);
                    advance(tNew - tLo);
                    if (last_.force < s.forceTarget)
                    {
                        lo = save();
                        tLo = model_.time;
                        fLo = last_.force;
                    }
                    else
                    {
                        tHi = model_.time;
                        fHi = last_.force;
                    }
                }
                const double delta0 = protocol_->depth(model_.time);
                *protocol_ = protocol_->withFirstRowAmount(delta0);
                delta0Found_ = delta0;
                if (s.log)
                {
                    *s.log
                        << "    force target " << s.forceTarget
                        << " N reached: delta0 = " << delta0 << " m at t = "
                        << model_.time << " s (force " << last_.force
                        << " N)" << std::endl;
                }
            }
            record(row.stage);
            // Every step, checkpoints or not (checkpointInterval 0)
            outputLength("force.dat");
            outputLength("peaks.dat");
            if (s.writeInterval > 0 && model_.time >= nextWrite_ - 1e-9)
            {
                writeFields();
                nextWrite_ += s.writeInterval;
            }
            if
            (
                s.checkpointInterval > 0
             && counters_.steps % s.checkpointInterval == 0
            )
            {
                checkpoint(i);
            }
        }
        // A force target not reached by the row's full amount: the run
        // went on with the table's depth, the log saying the stage ends at
        // the target (adv30 n21); refused
        if (untilForce && delta0Found_ < 0)
        {
            std::ostringstream os;
            os  << "entry 'forceTarget' = " << s.forceTarget << " N was not "
                << "reached in protocol row 1 (stage '" << row.stage
                << "', load): the force at the row's full amount "
                << row.amount << " m (its largest depth) is " << last_.force
                << " N; give a larger amount for row 1 or a smaller "
                << "forceTarget";
            throw SolidError(SolidError::Kind::parameter, os.str());
        }
        // Peaks and stage ends
        const bool peak = !hold && i + 1 < nRows && row.motion == "load"
            && protocol_->rows()[i + 1].motion == "unload"
            && protocol_->rows()[i + 1].stage == row.stage;
        const bool stageEnd =
            i + 1 == nRows || protocol_->rows()[i + 1].stage != row.stage;
        if (peak)
        {
            for (const auto& p : protocol_->peaks())
            {
                if (std::abs(p.time - model_.time) < 1e-6) peakLine(p.label);
            }
            writeFields();
        }
        else if (stageEnd && hold)
        {
            peakLine("end" + row.stage);
            writeFields();
        }
    }
    forceFile_.flush();
    peakFile_.flush();
    outputLength("force.dat");
    outputLength("peaks.dat");
    for (int k = 0; k < 2; ++k)
    {
        if (!digestFile_[k].flush())
        {
            const std::string side
            (
                path(k ? "peaks.dat.fnv1a64" : "force.dat.fnv1a64")
            );
            throw SolidError
            (
                SolidError::Kind::io, "cannot write " + side
              + ": the write failed" + spaceNote(side)
            );
        }
    }
    if (settings_.committed) settings_.committed();
}
