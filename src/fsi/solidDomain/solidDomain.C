#include "solidDomain.H"
#include "fsiRanges.H"
#include "solidInput.H"
#include "keywordCheck.H"
#include "inputChecks.H"
#include "subDict.H"
#include "inputRecord.H"
#include "uniformState.H"
#include "runLogFiles.H"
#include "SolidError.H"
#include "IOobject.H"
#include "pointField.H"
#include "Pair.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "SubList.H"
#include "Pstream.H"

#include <mpi.h>

#include <algorithm>
#include <cmath>

namespace
{

//- Entry key of dict as a point (x y z) of three finite numbers [m]; what:
//  the entry's context in the message ("interfacePlaces", "probes: probe
//  'p1'"). Anything else is a FatalIOError naming the entry as written
//  (adv50b k30: "(1e-06 2e-06)" and "(nan 0 0)" got OpenFOAM's "Wrong
//  token type - expected scalar value, found ... punctuation ')'")
Foam::point readPoint
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const std::string& what
)
{
    using namespace Foam;
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    bool good = e && e->isStream();
    point X(Zero);
    if (good)
    {
        const ITstream& is = e->stream();
        good =
            is.size() == 5
         && is[0].isPunctuation() && is[0].pToken() == token::BEGIN_LIST
         && is[4].isPunctuation() && is[4].pToken() == token::END_LIST;
        for (label k = 0; good && k < 3; ++k)
        {
            good = is[k + 1].isNumber() && std::isfinite(is[k + 1].number());
            if (good)
            {
                X[k] = is[k + 1].number();
            }
        }
    }
    if (!good)
    {
        OStringStream text;
        if (e && e->isStream())
        {
            const ITstream& is = e->stream();
            forAll(is, i)
            {
                text << (i ? " " : "") << foamTools::tokenText(is[i]).c_str();
            }
        }
        else
        {
            text << (e ? "a sub-dictionary" : "missing");
        }
        fileName file;
        label line = e ? e->startLineNumber() : 0;
        if (!foamTools::keywordCheckDetail::entryPlace(dict, key, file, line))
        {
            file = dict.name();
        }
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file, line)
            << what.c_str() << ": entry '" << key << "' = '"
            << text.str().c_str() << "' is not a point (x y z) of three "
            << "finite numbers [m] (r-z: (r z 0))" << exit(FatalIOError);
    }
    return X;
}

//- Run f; a solid::SolidError (any std::exception) it throws stops the run
//  naming the context and, when the input came from a dictionary entry
//  (dict not null), the file, the entry and its line (FatalIOError)
template<class F>
void guarded(const Foam::dictionary* dict, const char* context, F&& f)
{
    try
    {
        f();
    }
    catch (const std::exception& e)
    {
        if (dict)
        {
            FatalIOErrorInFunction(*dict)
                << context << ": " << e.what()
                << Foam::exit(Foam::FatalIOError);
        }
        FatalErrorInFunction
            << context << ": " << e.what() << Foam::exit(Foam::FatalError);
    }
}

//- The same for failures of the running solid (no input to name)
template<class F>
void guarded(const char* context, F&& f)
{
    guarded(nullptr, context, f);
}

//- The same for what a dictionary entry gave
template<class F>
void guarded(const Foam::dictionary& dict, const char* context, F&& f)
{
    guarded(&dict, context, f);
}

} // namespace


Foam::solidDomain::solidDomain(const Time& runTime)
:
    runTime_(runTime),
    dict_
    (
        IOobject
        (
            "solidProperties",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    startTime_(0),
    substeps_(0)
{
    const solidInput input
    (
        dict_, runTime.globalPath(),
        {
            "explicitSafety", "hourglassViscosity",
            "hourglassViscosityRegions", "shearViscosity",
            "shearViscosityFilter",
            "volumetricIntegration", "probes", "interfaceProbe", "interfaces",
            "fluidInterfaces", "interfacePatchLength", "interfacePlaces"
        }
    );
    model_.reset(new solid::Model(input.mesh()));
    input.setup(*model_);
}


Foam::boolList Foam::solidDomain::fixedDofs() const
{
    const label dim = mesh().dim();
    boolList fixed(mesh().nNodes()*dim, false);
    for
    (
        const auto& f
      : dict_.get<List<Tuple2<word, label>>>("fixed")
    )
    {
        const auto it = mesh().nodeSets.find(f.first());
        if (it == mesh().nodeSets.end() || f.second() < 0 || f.second() >= dim)
        {
            continue;       // reported by the model (constructor)
        }
        for (const int node : it->second)
        {
            fixed[dim*node + f.second()] = true;
        }
    }
    return fixed;
}


void Foam::solidDomain::couple(const labelList& interfaceNodes)
{
    interfaceNodes_.assign(interfaceNodes.begin(), interfaceNodes.end());
    force_ =
        std::make_shared<solid::NodalLoad>(interfaceNodes_, mesh().dim());
    model_->add(force_);

    // Fractions in [0, 1) (explicitSafety (0, 1)), checked here so that a
    // bad value is named as the file's entry (the solver's own check names
    // its settings: 'safety', 'hourglass'); nan and inf with that range too
    // (adv42 g25: "valid range [-inf, inf)")
    const auto fraction = [](const dictionary& d, const word& scope,
                             const word& key, const scalar deflt)
    {
        return fsiRanges::readOrDefault<scalar>(d, scope, key, deflt);
    };
    solid::ExplicitSettings set;
    set.safety = fraction(dict_, "solidProperties", "explicitSafety", 0.8);
    set.hourglass =
        fraction(dict_, "solidProperties", "hourglassViscosity", 0);
    set.shearViscosity =
        fraction(dict_, "solidProperties", "shearViscosity", 0);
    {
        // The filtered (scale-selective) form of that viscosity: yes/no,
        // or region (its neighbourhood averages within each region)
        const word filter
        (
            dict_.getOrDefault<word>("shearViscosityFilter", "no")
        );
        const bool byRegion = (filter == "region");
        const Switch sw(byRegion ? word("yes") : filter, true);
        if (!sw.valid())
        {
            FatalIOErrorInFunction(dict_)
                << "entry 'shearViscosityFilter' = '" << filter << "': "
                << "valid values are yes/no (on/off, true/false) or region"
                << " (filtered within each region)"
                << exit(FatalIOError);
        }
        if (sw && !(set.shearViscosity > 0))
        {
            FatalIOErrorInFunction(dict_)
                << "entry 'shearViscosityFilter' is " << filter << " but "
                << "'shearViscosity' is " << set.shearViscosity << ": the "
                << "filter shapes that viscosity; give shearViscosity in "
                << "(0, 1) or leave the filter out" << exit(FatalIOError);
        }
        set.shearViscosityFilter = sw;
        set.shearViscosityFilterByRegion = byRegion;
    }
    if (dict_.found("hourglassViscosityRegions"))
    {
        // kappa per region name, overriding hourglassViscosity there
        const dictionary& hr =
            foamTools::subDict(dict_, "hourglassViscosityRegions");
        foamTools::checkKeywords
        (
            hr, wordList(mesh().regionNames.begin(), mesh().regionNames.end())
        );
        for (const entry& e : hr)
        {
            set.hourglassRegions[e.keyword()] = fraction
            (
                hr, "solidProperties/hourglassViscosityRegions",
                e.keyword(), 0
            );
        }
    }
    // Volumetric law on the element dilatation (the Q1/P0 mean-dilatation
    // element, needs hourglass control in the explicit path) or at the
    // Gauss points (no zero-energy mode, volumetric locking: for cells
    // whose response to the blast is volumetric, docs/userGuide/fsi.md)
    const word integration
    (
        dict_.getOrDefault<word>("volumetricIntegration", "element")
    );
    if (integration != "element" && integration != "gaussPoints")
    {
        FatalIOErrorInFunction(dict_)
            << "volumetricIntegration '" << integration << "' in "
            << dict_.name() << ": valid values are 'element' (the Q1/P0 "
            << "mean dilatation) and 'gaussPoints'" << exit(FatalIOError);
    }
    model_->setPointVolumetric(integration == "gaussPoints");
    // The probes and interfaces (their elements are evaluated every step)
    setupOutputElements();
    if (Pstream::parRun())
    {
        // The solid's elements shared over the ranks, the forces summed
        // through MPI (OpenFOAM's world communicator is MPI_COMM_WORLD)
        solid::Partition part
        (
            Pstream::myProcNo(),
            Pstream::nProcs(),
            [](const double* mine, std::size_t n, double* all)
            {
                MPI_Allgather
                (
                    const_cast<double*>(mine), int(n), MPI_DOUBLE,
                    all, int(n), MPI_DOUBLE, MPI_COMM_WORLD
                );
            }
        );
        // By count within the output's elements (the probes' patches and
        // the interface elements: evaluated by their owners at the end of
        // every step, before the step's exchange) and within the others:
        // the blocks of all elements gave one rank most of the output's
        // evaluations (issue 18 item 5, docs/results/blast3D.md)
        std::vector<bool> output(mesh().nElements(), false);
        for (const int e : probeElements_) output[e] = true;
        for (const labelList& elems : interfaceElements_)
        {
            for (const label e : elems) output[e] = true;
        }
        for (const int e : patchElements_) output[e] = true;
        part.shareOut(output);
        model_->setPartition(std::move(part));
        Info<< "Solid: " << mesh().nElements() << " elements, "
            << std::count(output.begin(), output.end(), true)
            << " of them evaluated for the output every step; each class"
            << " shared out by count over " << Pstream::nProcs()
            << " ranks" << endl;
    }
    guarded("solid initialise", [&]
    {
        model_->initialise();
        solver_.reset(new solid::ExplicitSolver(*model_, set));
    });
    // The solid's steps counted as the fluid's, before anything is written:
    // every coupled step takes at least its solid steps (adv pass fo13:
    // explicitSafety 1e-12 made the stable step tiny and the run crawl)
    {
        OStringStream how;
        how << "the solid's stable time step x explicitSafety (entry "
            << "'explicitSafety' = "
            << foamTools::numberText(set.safety).c_str() << " of "
            << runTime_.constant()/"solidProperties"
            << "; the cell's materials and mesh decide its stable step)";
        foamTools::checkStepCount(runTime_, solver_->timeStep(), how.str());
    }

    setupOutput();

    // One result file for the case, written by the master (in parallel
    // every rank holds the whole solid, src/fsi/globalInterfacePatch.H)
    const fileName dir(runTime_.globalPath()/"solid");
    const fileName h5(dir/"solid.h5");
    const bool restart = runTime_.value() > 0;
    if (restart)
    {
        const fileName stateFile
        (
            runTime_.timePath()/"uniform"
           /foamTools::uniformState::solidState()
        );
        if (!isFile(stateFile))
        {
            FatalErrorInFunction
                << "Restart from t = " << runTime_.timeName() << " s: no "
                << stateFile << " (the run stopped while writing this time?"
                << " Start from the previous write time)" << exit(FatalError);
        }
        IFstream is(stateFile);
        const dictionary d(is);
        runId_ = d.lookupOrDefault<string>("runId", string());
        const label k = restartStep(runTime_);
        guarded("solid restart", [&]
        {
            solid::ResultWriter::restart(h5, k, *model_);
        });
        auto vec = [&](const word& name)
        {
            const scalarList l(d.get<scalarList>(name));
            return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>
            (
                l.cdata(), l.size()
            ));
        };
        solid::ExplicitState st;
        st.a = vec("a");
        st.fint = vec("fint");
        st.fext = vec("fext");
        st.fhg = vec("fhg");
        st.dt = d.get<scalar>("dt");
        st.stableDt = d.get<scalar>("stableDt");
        st.steps = d.get<label>("steps");
        const scalarList en(d.get<scalarList>("energy"));
        st.energy.kinetic = en[0];
        st.energy.internal = en[1];
        st.energy.dissipated = en[2];
        st.energy.shockHeat = en[3];
        st.energy.viscousHeat = en[4];
        st.energy.externalWork = en[5];
        st.energy.internalWork = en[6];
        st.energy.hourglass = en[7];
        st.energy.initial = en[8];
        guarded("solid restart", [&] { solver_->setState(st); });
        const scalarList ps(d.get<scalarList>("probeStrain"));
        if (ps.size() != probeStrain_.size())
        {
            FatalIOErrorInFunction(d)
                << "probeStrain has " << ps.size() << " values, the probes "
                << probeStrain_.size() << " (probes changed?)"
                << exit(FatalIOError);
        }
        probeStrain_ = ps;
        // The interface forces of the step that ended at this time: the
        // start of the next step's load
        const scalarList f0(d.get<scalarList>("interfaceForce"));
        guarded(d, "solid restart: interfaceForce", [&]
        {
            force_->setForces(std::vector<double>(f0.begin(), f0.end()));
        });
        Info<< "Solid: restarted from " << h5 << " step " << k
            << " (t = " << model_->time << " s) and " << stateFile << endl;
    }
    else
    {
        // The same inputs give the same identity (restarts compare bitwise
        // with uninterrupted runs): the files and the water's boundary
        // conditions (the pulse); the master's record (its rank's mesh)
        const word region(polyMesh::defaultRegion);
        runId_ = foamTools::inputRecord::sha1
        (
            foamTools::inputRecord::format
            (
                runTime_.foundObject<fvMesh>(region)
              ? foamTools::inputRecord
                (
                    runTime_, runTime_.lookupObject<fvMesh>(region)
                ).digests()
              : foamTools::inputRecord(runTime_).digests()
            )
        );
        Pstream::scatter(runId_);
    }
    // Every rank has read the file before the master opens it for writing
    // (a reduction as the barrier)
    label readDone = 1;
    reduce(readDone, sumOp<label>());
    if (Pstream::master())
    {
        mkDir(dir);
        guarded("solid output", [&]
        {
            writer_.reset
            (
                new solid::ResultWriter
                (
                    dir/"solid", *model_, restart, runId_
                )
            );
        });
    }
    save();
}


Foam::label Foam::solidDomain::restartStep(const Time& runTime)
{
    const fileName stateFile
    (
        runTime.timePath()/"uniform"/foamTools::uniformState::solidState()
    );
    const fileName h5(runTime.globalPath()/"solid"/"solid.h5");
    IFstream is(stateFile);
    const dictionary d(is);
    const label k = foamTools::readInRange<label>
    (
        d, "h5Step", "", 0, labelMax, true
    );
    const scalar tState = d.get<scalar>("time");
    std::vector<std::pair<int, double>> steps;
    guarded("solid restart", [&]
    {
        steps = solid::ResultWriter::steps(h5);
    });
    const auto it = std::find_if
    (
        steps.begin(), steps.end(),
        [k](const std::pair<int, double>& s) { return s.first == k; }
    );
    const scalar t = runTime.value();
    // The state's time is the one written for the step (17 digits: the
    // same double); the fluid's restart time agrees to round-off (the
    // solid sums its substeps)
    const scalar tol = 1e-9*max(mag(t), mag(tState));
    if
    (
        it == steps.end()
     || mag(it->second - tState) > 1e-12*mag(tState)
     || mag(it->second - t) > tol
    )
    {
        FatalIOErrorInFunction(d)
            << "Restart from t = " << runTime.timeName() << " s: entry"
            << " 'h5Step' = " << k << " (state time "
            << foamTools::numberText(tState).c_str() << " s)";
        if (it == steps.end())
        {
            FatalIOError
                << " is not a step of " << h5 << " (" << label(steps.size())
                << " steps";
            if (steps.size())
            {
                FatalIOError
                    << ", " << steps.front().first << " to "
                    << steps.back().first;
            }
            FatalIOError << "): the solid's state cannot be restored.";
        }
        else if (mag(it->second - t) <= tol)
        {
            // the step is the restart time's; the state's own time is not
            // (adv49a j09 (h): "names the step ... at t = 2e-09 s, not the
            // restart time 2e-09 s", two equal times contrasted)
            FatalIOError
                << ": its entry 'time' = "
                << foamTools::numberText(tState).c_str() << " s is not the "
                << "restart time " << foamTools::numberText(t).c_str()
                << " s, which is the time of its "
                << "h5Step " << k << " in " << h5 << ": the state was "
                << "edited.";
        }
        else
        {
            FatalIOError
                << " names the step of " << h5 << " at t = "
                << foamTools::numberText(it->second).c_str()
                << " s, not the restart time "
                << foamTools::numberText(t).c_str() << " s: the solid"
                << " would restart at another time than the fluid.";
        }
        FatalIOError
            << " The file was edited or comes from another run: restart"
            << " from another time, or start anew (startFrom startTime,"
            << " -overwrite)" << exit(FatalIOError);
    }
    return k;
}


void Foam::solidDomain::writeState(const label k) const
{
    const fileName dir(runTime_.timePath()/"uniform");
    mkDir(dir);
    // Written to a temporary name and renamed: the file is there complete
    // or not at all (a run killed while writing)
    const fileName file(dir/foamTools::uniformState::solidState());
    {
        OFstream os(file + ".tmp");
        os.precision(17);
        const solid::ExplicitState st(solver_->state());
        auto list = [](const Eigen::VectorXd& v)
        {
            return scalarList(SubList<scalar>(UList<scalar>
            (
                const_cast<scalar*>(v.data()), label(v.size())
            )));
        };
        os.writeEntry("h5Step", k);
        os.writeEntry("runId", runId_);
        os.writeEntry("time", model_->time);
        os.writeEntry("dt", st.dt);
        os.writeEntry("stableDt", st.stableDt);
        os.writeEntry("steps", label(st.steps));
        const solid::EnergyReport& e = st.energy;
        os.writeEntry
        (
            "energy",
            scalarList
            ({
                e.kinetic, e.internal, e.dissipated, e.shockHeat,
                e.viscousHeat, e.externalWork, e.internalWork, e.hourglass,
                e.initial
            })
        );
        os.writeEntry("probeStrain", probeStrain_);
        os.writeEntry
        (
            "interfaceForce",
            scalarList(UList<scalar>
            (
                const_cast<scalar*>(force_->forces().data()),
                label(force_->forces().size())
            ))
        );
        os.writeEntry("a", list(st.a));
        os.writeEntry("fint", list(st.fint));
        os.writeEntry("fext", list(st.fext));
        os.writeEntry("fhg", list(st.fhg));
    }
    mv(file + ".tmp", file);
}


Foam::labelList Foam::solidDomain::interfaceElements
(
    const word& a,
    const word& b
) const
{
    const solid::Mesh& m = mesh();
    int ra = -1, rb = -1;
    guarded(dict_, "solid interfaces", [&]
    {
        ra = m.regionId(a);
        rb = m.regionId(b);
    });
    std::vector<char> inA(m.nNodes(), 0), inB(m.nNodes(), 0);
    for (int e = 0; e < m.nElements(); ++e)
    {
        for (int k = 0; k < m.nen(); ++k)
        {
            if (m.region[e] == ra) inA[m.element(e)[k]] = 1;
            if (m.region[e] == rb) inB[m.element(e)[k]] = 1;
        }
    }
    DynamicList<label> elems;
    for (int e = 0; e < m.nElements(); ++e)
    {
        if (m.region[e] != ra && m.region[e] != rb) continue;
        const std::vector<char>& other = m.region[e] == ra ? inB : inA;
        for (int k = 0; k < m.nen(); ++k)
        {
            if (other[m.element(e)[k]])
            {
                elems.append(e);
                break;
            }
        }
    }
    if (elems.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "interfaces: regions " << a << " and " << b
            << " share no node" << exit(FatalIOError);
    }
    return labelList(elems);
}


Foam::point Foam::solidDomain::interfacePoint
(
    const word& outer,
    const word& inner,
    const scalar fraction
) const
{
    const solid::Mesh& m = mesh();
    const int dim = m.dim();
    const int axial = dim - 1;
    int ro = -1, ri = -1;
    guarded(dict_, "interfaceProbe", [&]
    {
        ro = m.regionId(outer);
        ri = m.regionId(inner);
    });
    std::vector<char> inO(m.nNodes(), 0), inI(m.nNodes(), 0);
    for (int e = 0; e < m.nElements(); ++e)
    {
        for (int k = 0; k < m.nen(); ++k)
        {
            if (m.region[e] == ro) inO[m.element(e)[k]] = 1;
            if (m.region[e] == ri) inI[m.element(e)[k]] = 1;
        }
    }
    // Height of the inner region along the axial (shock) direction
    scalar zMin = GREAT, zMax = -GREAT;
    for (int a = 0; a < m.nNodes(); ++a)
    {
        if (!inI[a]) continue;
        zMin = min(zMin, m.X[a](axial));
        zMax = max(zMax, m.X[a](axial));
    }
    const scalar z = zMin + fraction*(zMax - zMin);

    // The interface edges (element edges with both nodes on both regions)
    // in the plane x >= 0, y = 0 (r-z: the section itself) crossing z: the
    // crossing farthest from the axis
    scalar bestR = -GREAT;
    point P(Zero);
    const scalar tol = 1e-9*(zMax - zMin);
    for (int e = 0; e < m.nElements(); ++e)
    {
        if (m.region[e] != ri) continue;
        const int* en = m.element(e);
        static const int quadEdges[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
        static const int hexEdges[12][2] =
        {
            {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4},
            {0, 4}, {1, 5}, {2, 6}, {3, 7}
        };
        const int nEdges = dim == 2 ? 4 : 12;
        {
            for (int j = 0; j < nEdges; ++j)
            {
                const int* ed = dim == 2 ? quadEdges[j] : hexEdges[j];
                const int a = en[ed[0]], b = en[ed[1]];
                if (!(inO[a] && inI[a] && inO[b] && inI[b])) continue;
                const solid::Vec3& A = m.X[a];
                const solid::Vec3& B = m.X[b];
                if (dim == 3 && (std::abs(A(1)) > tol || std::abs(B(1)) > tol))
                {
                    continue;
                }
                const scalar za = A(axial), zb = B(axial);
                if ((za - z)*(zb - z) > 0 || za == zb) continue;
                const scalar t = (z - za)/(zb - za);
                const solid::Vec3 X = A + t*(B - A);
                if (X(0) > bestR)
                {
                    bestR = X(0);
                    P = point(X(0), X(1), dim == 3 ? X(2) : 0);
                }
            }
        }
    }
    if (bestR < 0)
    {
        // The outer region's height: inside the inner one's, the two were
        // given the other way round (adv33 bi19: the message did not say
        // that regions is (outer inner))
        scalar oMin = GREAT, oMax = -GREAT;
        for (int a = 0; a < m.nNodes(); ++a)
        {
            if (!inO[a]) continue;
            oMin = min(oMin, m.X[a](axial));
            oMax = max(oMax, m.X[a](axial));
        }
        FatalIOErrorInFunction(dict_)
            << "interfaceProbe: no edge of the " << outer << "-" << inner
            << " interface crosses z = " << z << " m at x >= 0"
            << (dim == 3 ? ", y = 0" : "") << " (entry 'regions' is"
            << " (outer inner); z is the fraction " << fraction << " of the"
            << " inner region " << inner << "'s height, " << zMin << " to "
            << zMax << " m)";
        if (oMin > zMin + tol || oMax < zMax - tol)
        {
            FatalIOError
                << ": " << outer << " (" << oMin << " to " << oMax << " m)"
                << " lies inside " << inner << ", the regions are given the"
                << " other way round: regions (" << inner << " " << outer
                << ")";
        }
        FatalIOError << exit(FatalIOError);
    }
    return P;
}


void Foam::solidDomain::addProbe
(
    const word& name,
    const point& X,
    const word& region,
    const dictionary& dict,
    const word& entry,
    const scalar radius,
    const word& across
)
{
    const std::string context(entry + ": probe '" + name + "'");
    if (!across.empty() && (region.empty() || radius > 0))
    {
        FatalIOErrorInFunction(dict)
            << context.c_str() << ": 'across " << across << "' needs "
            << (
                   region.empty()
                 ? "the probe's region (the side of its von Mises, strain_z"
                   " and dT): add 'region <name>;'"
                 : "a point probe: a ball probe (radius > 0) averages its"
                   " region only; remove 'radius' or 'across'"
               )
            << exit(FatalIOError);
    }
    guarded(dict, context.c_str(), [&]
    {
        const int r = region.empty() ? -1 : mesh().regionId(region);
        const solid::Vec3 P(X.x(), X.y(), X.z());
        if (across.empty())
        {
            probes_.emplace_back(mesh(), P, r, radius);
        }
        else
        {
            probes_.emplace_back
            (
                mesh(), P, r, solid::AcrossRegion{mesh().regionId(across)}
            );
        }
    });
    probeNames_.append(name);
}


void Foam::solidDomain::setupProbes()
{
    // A dictionary of named probes or a list of points
    if (dict_.isDict("probes"))
    {
        const dictionary& pd = dict_.subDict("probes");
        foamTools::checkDuplicates(pd);
        for (const entry& e : pd)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(pd)
                    << "probes: entry " << e.keyword() << " is not a "
                    << "dictionary { point (x y z); region <name>; } (point"
                    << " [m] in the reference configuration, r-z: (r z 0);"
                    << " region optional; radius <R>; [m] optional: the"
                    << " mean over the region within R of the point;"
                    << " across <region>; optional: the pressure and ln J"
                    << " read across the interface with that region)"
                    << exit(FatalIOError);
            }
            const dictionary& d = e.dict();
            foamTools::checkKeywords
            (
                d, {"point", "region", "radius", "across"}
            );
            // A ball probe's radius: the mean over the region within it
            // (0, the default: the point's recovered value)
            const scalar radius = fsiRanges::readOrDefault<scalar>
            (
                d, "solidProperties/probes", "radius", 0
            );
            addProbe
            (
                e.keyword(),
                readPoint
                (
                    d, "point", "probes: probe '" + e.keyword() + "'"
                ),
                d.getOrDefault<word>("region", word::null),
                d,
                "probes",
                radius,
                d.getOrDefault<word>("across", word::null)
            );
        }
    }
    else if (dict_.found("probes"))
    {
        const pointField points(dict_.get<pointField>("probes"));
        forAll(points, i)
        {
            addProbe
            (
                "probe" + Foam::name(i), points[i], word::null, dict_, "probes"
            );
        }
    }
    if (dict_.found("interfaceProbe"))
    {
        const dictionary& ip = foamTools::subDict(dict_, "interfaceProbe");
        foamTools::checkKeywords
        (
            ip, {"regions", "heightFraction", "side", "reading"}
        );
        const Pair<word> regions(ip.get<Pair<word>>("regions"));
        // The fraction of the inner region's height, in (0, 1); nan, inf
        // named with the range (adv42 g25: OpenFOAM's "Wrong token type")
        const scalar f = fsiRanges::read<scalar>
        (
            ip, "solidProperties/interfaceProbe", "heightFraction"
        );
        // outer (the first of regions) or inner (the second), named with
        // the file, the line and the closest word (adv48b g39)
        const word side
        (
            foamTools::readOneOfOrDefault
            (
                ip, "side", {"outer", "inner"}, "outer"
            )
        );
        // Two regions (adv48b g37: (nucleus nucleus) accepted, probe 0 on
        // the nucleus and two probes of one name), as entry 'interfaces'
        if (regions.first() == regions.second())
        {
            FatalIOErrorInFunction(ip)
                << "interfaceProbe: entry 'regions' = (" << regions.first()
                << ' ' << regions.second() << "): a region paired with "
                << "itself; give the two regions of the interface, outer "
                << "first (e.g. (cytoplasm nucleus))" << exit(FatalIOError);
        }
        // oneSided: each probe's quantities from its side alone; interface:
        // the pressure and ln J across the interface (solid::PointProbe's
        // interface probe: convex between the two containing elements)
        const word reading
        (
            foamTools::readOneOfOrDefault
            (
                ip, "reading", {"oneSided", "interface"}, "oneSided"
            )
        );
        const bool acrossInterface = reading == "interface";
        const point P(interfacePoint(regions.first(), regions.second(), f));
        Info<< "Solid: interface probe " << regions << " at "
            << 100*f << " % of the " << regions.second() << " height: "
            << P << " m" << endl;
        const bool outer = side == "outer";
        addProbe
        (
            "interfaceProbe",
            P,
            outer ? regions.first() : regions.second(),
            ip,
            "interfaceProbe",
            0,
            acrossInterface
          ? (outer ? regions.second() : regions.first())
          : word::null
        );
        for (const word& r : {regions.second(), regions.first()})
        {
            const word& other =
                r == regions.first() ? regions.second() : regions.first();
            addProbe
            (
                "interfaceProbe." + r, P, r, ip, "interfaceProbe", 0,
                acrossInterface ? other : word::null
            );
        }
    }
}


void Foam::solidDomain::setupOutputElements()
{
    setupProbes();
    for (const solid::PointProbe& p : probes_)
    {
        probeElements_.insert
        (
            probeElements_.end(), p.patch().begin(), p.patch().end()
        );
    }
    std::sort(probeElements_.begin(), probeElements_.end());
    probeElements_.erase
    (
        std::unique(probeElements_.begin(), probeElements_.end()),
        probeElements_.end()
    );

    const List<Pair<word>> pairs
    (
        dict_.getOrDefault<List<Pair<word>>>("interfaces", {})
    );
    // Each pair two regions, each interface once: a region paired with
    // itself (all its elements, as if an interface) and a pair given twice
    // (columns twice, in either order) were accepted silently (adv pass
    // y07, y08)
    forAll(pairs, i)
    {
        if (pairs[i].first() == pairs[i].second())
        {
            FatalIOErrorInFunction(dict_)
                << "entry 'interfaces', pair " << i + 1 << " ("
                << pairs[i].first() << ' ' << pairs[i].second() << "): a "
                << "region paired with itself; an interface is a pair of "
                << "two different regions that share nodes"
                << exit(FatalIOError);
        }
        for (label j = 0; j < i; ++j)
        {
            if (Pair<word>::compare(pairs[i], pairs[j]) != 0)
            {
                FatalIOErrorInFunction(dict_)
                    << "entry 'interfaces', pair " << i + 1 << " ("
                    << pairs[i].first() << ' ' << pairs[i].second()
                    << ") is the interface of pair " << j + 1 << " ("
                    << pairs[j].first() << ' ' << pairs[j].second()
                    << "): give each interface once" << exit(FatalIOError);
            }
        }
    }
    interfaceElements_.setSize(pairs.size());
    forAll(pairs, i)
    {
        interfaceElements_[i] = interfaceElements(pairs[i].first(),
            pairs[i].second());
    }
    setupPatches(pairs);
}


void Foam::solidDomain::setupOutput()
{
    const solid::Mesh& m = mesh();
    const label nProbes = label(probes_.size());
    probeStrain_.setSize(2*nProbes, 0);
    if (nProbes && Pstream::master())
    {
        probeFile_ = foamTools::runLogFiles::openLog
        (
            runTime_,
            "solidProbes",
            foamTools::runLogFiles::solidProbesName(),
            foamTools::runLogFiles::solidProbesHeader()
        );
        OFstream& os = probeFile_();
        os  << " of the reference configuration (each follows its material"
            << " point), recovered from the elements of the probe's region around it"
            << " (a probe 'across' an interface: its pressure and ln J between"
            << " the two elements containing the point, one per side): per "
            << "probe pressure (+ compression), von Mises, volumetric strain"
            << " ln J and its rate, temperature rise; then per probe the "
            << "longitudinal strain ln|F e_z| (shock direction) and its rate"
            << nl << "# time [s]";
        for (label i = 0; i < nProbes; ++i)
        {
            os  << "  p" << i << "[Pa] vonMises" << i << "[Pa] strain" << i
                << "[-] strainRate" << i << "[1/s] dT" << i << "[K]";
        }
        for (label i = 0; i < nProbes; ++i)
        {
            os  << "  strainZ" << i << "[-] strainRateZ" << i << "[1/s]";
        }
        os  << nl;
        for (label i = 0; i < nProbes; ++i)
        {
            const solid::PointProbe& p = probes_[i];
            os  << "# probe " << i << " " << probeNames_[i] << " at ("
                << p.point()(0) << ' ' << p.point()(1) << ' '
                << p.point()(2) << ") m in "
                << word(m.regionNames[p.region()]) << ": element "
                << p.element()
                << ", patch of "
                << p.patch().size() - (p.across() < 0 ? 0 : 1)
                << " elements";
            if (p.across() >= 0)
            {
                // The two hosts and their weights (the last of the patch
                // is the other side's)
                const std::vector<double>& wc = p.continuousWeights();
                const std::size_t host = std::find
                (
                    p.patch().begin(), p.patch().end(), p.element()
                ) - p.patch().begin();
                os  << "; pressure and ln J across the interface with "
                    << word(m.regionNames[p.across()]) << ": element "
                    << p.acrossElement() << ", weights " << wc[host]
                    << ' ' << wc.back();
            }
            if (p.radius() > 0)
            {
                os  << ": the mean over the region within radius "
                    << p.radius() << " m of the point (" << p.volume()
                    << " m^3)";
            }
            os  << nl;
        }
    }

    const List<Pair<word>> pairs
    (
        dict_.getOrDefault<List<Pair<word>>>("interfaces", {})
    );
    openPatchFile();
    // The output elements this rank owns, each evaluated once per step
    {
        const solid::Partition& part = model_->partition();
        const int ne = m.nElements();
        std::vector<int>& owned = ownedOutputElements_;
        for (const int e : probeElements_)
        {
            if (part.owner(e, ne) == part.part()) owned.push_back(e);
        }
        for (const labelList& elems : interfaceElements_)
        {
            for (const label e : elems)
            {
                if (part.owner(e, ne) == part.part()) owned.push_back(e);
            }
        }
        for (const int e : patchElements_)
        {
            if (part.owner(e, ne) == part.part()) owned.push_back(e);
        }
        std::sort(owned.begin(), owned.end());
        owned.erase(std::unique(owned.begin(), owned.end()), owned.end());
        outputSamples_.resize(owned.size());
        outputSlot_.assign(m.nElements(), -1);
        for (std::size_t k = 0; k < owned.size(); ++k)
        {
            outputSlot_[owned[k]] = int(k);
        }
    }
    if (pairs.size() && Pstream::master())
    {
        interfaceFile_ = foamTools::runLogFiles::openLog
        (
            runTime_,
            "solidInterfaces",
            foamTools::runLogFiles::interfaceMaximaName(),
            foamTools::runLogFiles::interfaceMaximaHeader()
        );
        OFstream& os = interfaceFile_();
        os  << " along each region interface"
            << " (either side): pressure (+ compression) and von Mises"
            << nl << "# time [s]";
        forAll(pairs, i)
        {
            const word n(pairs[i].first() + "-" + pairs[i].second());
            os  << "  pMax:" << n << "[Pa] vonMisesMax:" << n << "[Pa]";
        }
        os  << nl;
        forAll(pairs, i)
        {
            os  << "# " << pairs[i].first() << "-" << pairs[i].second()
                << ": " << interfaceElements_[i].size() << " elements" << nl;
        }
    }
}


void Foam::solidDomain::setupPatches(const List<Pair<word>>& pairs)
{
    const solid::Mesh& m = mesh();
    patchLength_ = fsiRanges::readOrDefault<scalar>
    (
        dict_, "solidProperties", "interfacePatchLength", 1e-6
    );
    const scalar L = patchLength_;
    const wordList fluid
    (
        dict_.getOrDefault<wordList>("fluidInterfaces", wordList())
    );
    forAll(fluid, i)
    {
        for (label j = 0; j < i; ++j)
        {
            if (fluid[j] == fluid[i])
            {
                FatalIOErrorInFunction(dict_)
                    << "entry 'fluidInterfaces': region " << fluid[i]
                    << " given twice: give each region once"
                    << exit(FatalIOError);
            }
        }
    }
    forAll(pairs, i)
    {
        guarded(dict_, "entry 'interfaces'", [&]
        {
            patches_.emplace_back
            (
                m, m.regionId(pairs[i].first()),
                m.regionId(pairs[i].second()), L
            );
        });
        patchNames_.append(pairs[i].first() + "-" + pairs[i].second());
    }
    std::vector<char> onFluid(m.nNodes(), 0);
    for (const int n : interfaceNodes_) onFluid[n] = 1;
    for (const word& r : fluid)
    {
        guarded(dict_, "entry 'fluidInterfaces'", [&]
        {
            patches_.emplace_back(m, m.regionId(r), onFluid, L);
        });
        patchNames_.append(r + "-fluid");
    }
    // Fixed places of the means: the same points on every interface
    if (dict_.found("interfacePlaces"))
    {
        if (!dict_.isDict("interfacePlaces"))
        {
            FatalIOErrorInFunction(dict_)
                << "entry 'interfacePlaces' is not a dictionary { NAME (x y"
                << " z); ... } (points [m] of the reference configuration,"
                << " r-z: (r z 0))" << exit(FatalIOError);
        }
        const dictionary& pd = dict_.subDict("interfacePlaces");
        foamTools::checkDuplicates(pd);
        if (patches_.empty())
        {
            FatalIOErrorInFunction(dict_)
                << "entry 'interfacePlaces': no interface to place them on"
                << " (entries 'interfaces' and 'fluidInterfaces' are empty)"
                << exit(FatalIOError);
        }
        for (const entry& e : pd)
        {
            if (e.isDict())
            {
                FatalIOErrorInFunction(pd)
                    << "interfacePlaces: entry " << e.keyword() << " is a "
                    << "dictionary, not a point (x y z) [m]"
                    << exit(FatalIOError);
            }
            const vector X(readPoint(pd, e.keyword(), "interfacePlaces"));
            for (solid::InterfacePatch& ip : patches_)
            {
                guarded(pd, "entry 'interfacePlaces'", [&]
                {
                    ip.addPlace(solid::Vec3(X.x(), X.y(), X.z()));
                });
            }
            placeNames_.append(e.keyword());
        }
    }
    for (const solid::InterfacePatch& ip : patches_)
    {
        patchElements_.insert
        (
            patchElements_.end(), ip.elements().begin(), ip.elements().end()
        );
    }
    std::sort(patchElements_.begin(), patchElements_.end());
    patchElements_.erase
    (
        std::unique(patchElements_.begin(), patchElements_.end()),
        patchElements_.end()
    );
}


void Foam::solidDomain::openPatchFile()
{
    const solid::Mesh& m = mesh();
    const scalar L = patchLength_;
    if (patches_.size() && Pstream::master())
    {
        patchFile_ = foamTools::runLogFiles::openLog
        (
            runTime_,
            "solidInterfaces",
            foamTools::runLogFiles::interfacePatchesName(),
            foamTools::runLogFiles::interfacePatchesHeader()
        );
        OFstream& os = patchFile_();
        os  << " over a patch of fixed size (r-z: " << L << " m of arc along the interface;"
            << " 3D: a disc of diameter " << L << " m) of pressure (+ "
            << "compression), von Mises and shear traction (each side's "
            << "elements, the larger side), the von Mises patch's centre,"
            << " then the element maxima of the same (mesh-dependent: "
            << "pressure and von Mises over the elements with a node on the"
            << " other side, as interfaceMaxima.dat; shear over the faces)"
            << nl << "# time [s]";
        for (const word& n : patchNames_)
        {
            os  << "  pPatch:" << n << "[Pa] vonMisesPatch:" << n
                << "[Pa] shearPatch:" << n << "[Pa] vonMisesPatchX:" << n
                << "[m] vonMisesPatchY:" << n << "[m] vonMisesPatchZ:" << n
                << "[m] pMax:" << n << "[Pa] vonMisesMax:" << n
                << "[Pa] shearMax:" << n << "[Pa]";
        }
        os  << nl;
        forAll(patchNames_, i)
        {
            const solid::InterfacePatch& ip = patches_[i];
            os  << "# " << patchNames_[i] << ": " << ip.facets().size()
                << " faces, " << ip.band().size() << " band elements, "
                << (m.axisymmetric() ? ip.nChains() : ip.nPatches())
                << (m.axisymmetric() ? " curves" : " patches") << nl;
        }
    }
    if (placeNames_.size() && Pstream::master())
    {
        placeFile_ = foamTools::runLogFiles::openLog
        (
            runTime_,
            "solidInterfaces",
            foamTools::runLogFiles::interfacePlacesName(),
            foamTools::runLogFiles::interfacePlacesHeader()
        );
        OFstream& os = placeFile_();
        os  << " over a patch of fixed size (r-z: " << L << " m of arc along"
            << " the interface; 3D: a disc of diameter " << L << " m) around "
            << "the interface's point nearest the place's point, of pressure"
            << " (+ compression), von Mises and shear traction (each side's"
            << " elements, the larger side)" << nl << "# time [s]";
        forAll(patchNames_, i)
        {
            for (const word& q : placeNames_)
            {
                const word n(q + ":" + patchNames_[i]);
                os  << "  pAt_" << n << "[Pa] vonMisesAt_" << n
                    << "[Pa] shearAt_" << n << "[Pa]";
            }
        }
        os  << nl;
        const dictionary& pd = dict_.subDict("interfacePlaces");
        forAll(patchNames_, i)
        {
            forAll(placeNames_, k)
            {
                const vector X(pd.get<vector>(placeNames_[k]));
                const solid::Vec3& c = patches_[i].placeCentre(k);
                os  << "# " << placeNames_[k] << ":" << patchNames_[i]
                    << ": point (" << X.x() << ' ' << X.y() << ' ' << X.z()
                    << ") m, patch centre (" << c(0) << ' ' << c(1) << ' '
                    << c(2) << ") m" << nl;
            }
        }
    }
}


void Foam::solidDomain::save()
{
    // The histories of this rank's own elements only (the only ones it
    // writes; the others are stale copies until shareStates at a write
    // time, after the step), into the storage of the last save
    saved_.model.take(*model_, solid::ModelSnapshot::Histories::owned);
    saved_.solver = solver_->state();
    startForces_ = force_->forces();
    startTime_ = model_->time;
}


void Foam::solidDomain::restore()
{
    saved_.model.restore(*model_);
    solver_->setState(saved_.solver);
}


void Foam::solidDomain::advance
(
    const scalarField& interfaceForces,
    const scalar t
)
{
    guarded("solid step", [&]
    {
        force_->setForces
        (
            startForces_,
            startTime_,
            std::vector<double>(interfaceForces.begin(), interfaceForces.end()),
            t
        );
        substeps_ = solver_->advanceTo(t, true);
    });
}


Foam::scalarField Foam::solidDomain::startForces() const
{
    return scalarField(UList<scalar>
    (
        const_cast<scalar*>(startForces_.data()), label(startForces_.size())
    ));
}


Foam::scalarField Foam::solidDomain::interfaceForces() const
{
    const std::vector<double>& f = force_->forces();
    return scalarField(UList<scalar>
    (
        const_cast<scalar*>(f.data()), label(f.size())
    ));
}


namespace
{

//- A probe sample packed: p, sigma, F, theta, temperature rise
constexpr std::size_t sampleSize = 21;

void packSample(const solid::ProbeValues& v, double* x)
{
    x[0] = v.p;
    std::copy(v.sigma.data(), v.sigma.data() + 9, x + 1);
    std::copy(v.F.data(), v.F.data() + 9, x + 10);
    x[19] = v.theta;
    x[20] = v.temperatureRise;
}

solid::ProbeValues unpackSample(const double* x)
{
    solid::ProbeValues v;
    v.p = x[0];
    std::copy(x + 1, x + 10, v.sigma.data());
    std::copy(x + 10, x + 19, v.F.data());
    v.theta = x[19];
    v.temperatureRise = x[20];
    return v;
}

} // End anonymous namespace


void Foam::solidDomain::packOutput(solid::PackedValues& values)
{
    // The output elements this rank owns (whose histories it holds),
    // each once
    for (std::size_t k = 0; k < ownedOutputElements_.size(); ++k)
    {
        outputSamples_[k] = solid::PointProbe::sample
        (
            model_->evaluateElement(ownedOutputElements_[k], 0)
        );
    }
    // The probes' samples from their elements' owners
    const solid::Partition& part = model_->partition();
    const int ne = mesh().nElements();
    probeOffset_ = values.size();
    double x[sampleSize];
    for (const int e : probeElements_)
    {
        const int slot = outputSlot_[e];
        if (slot >= 0)
        {
            packSample(outputSamples_[slot], x);
        }
        values.owned(part.owner(e, ne), slot >= 0 ? x : nullptr, sampleSize);
    }
    // The interface maxima over this rank's elements, then over the ranks
    maximaOffset_ = values.size();
    for (const labelList& elems : interfaceElements_)
    {
        scalar pMax = -GREAT, vmMax = 0;
        for (const label e : elems)
        {
            const int slot = outputSlot_[e];
            if (slot < 0) continue;
            const solid::ProbeValues& o = outputSamples_[slot];
            pMax = max(pMax, o.p);
            vmMax = max(vmMax, solid::tensor::vonMises(o.sigma));
        }
        const double m[2] = {pMax, vmMax};
        values.max(m, 2);
    }
    // The stresses of the elements the patch measures read, each from its
    // owner: pressure, then the Cauchy stress
    patchOffset_ = values.size();
    for (const int e : patchElements_)
    {
        const int slot = outputSlot_[e];
        if (slot >= 0)
        {
            const solid::ProbeValues& o = outputSamples_[slot];
            x[0] = o.p;
            std::copy(o.sigma.data(), o.sigma.data() + 9, x + 1);
        }
        values.owned(part.owner(e, ne), slot >= 0 ? x : nullptr, 10);
    }
    packed_ = true;
}


void Foam::solidDomain::write
(
    const solid::PackedValues& values,
    const scalar dt
)
{
    if (!packed_)
    {
        FatalErrorInFunction
            << "the solid's step output written before it was packed"
            << " (packOutput)" << abort(FatalError);
    }
    packed_ = false;
    if (probeFile_.valid())
    {
        OFstream& os = probeFile_();
        os  << runTime_.value();
        const int axial = mesh().dim() - 1;
        scalarField ez(probes_.size());
        std::vector<solid::ProbeValues> samples;
        for (label i = 0; i < label(probes_.size()); ++i)
        {
            // The patch's samples by their elements' places among the
            // packed probe elements (sorted)
            const std::vector<int>& patch = probes_[i].patch();
            samples.resize(patch.size());
            for (std::size_t j = 0; j < patch.size(); ++j)
            {
                const std::size_t k = std::lower_bound
                (
                    probeElements_.begin(), probeElements_.end(), patch[j]
                ) - probeElements_.begin();
                samples[j] = unpackSample
                (
                    values.data() + probeOffset_ + k*sampleSize
                );
            }
            const solid::ProbeValues v = probes_[i].recover(samples);
            const scalar logJ = std::log(v.theta);
            os  << ' ' << v.p << ' ' << solid::tensor::vonMises(v.sigma)
                << ' ' << logJ
                << ' ' << (logJ - probeStrain_[2*i])/dt << ' '
                << v.temperatureRise;
            probeStrain_[2*i] = logJ;
            ez[i] = std::log(v.F.col(axial).norm());
        }
        forAll(ez, i)
        {
            os  << ' ' << ez[i] << ' ' << (ez[i] - probeStrain_[2*i + 1])/dt;
            probeStrain_[2*i + 1] = ez[i];
        }
        // Flushed per row: a run stopped by a FatalError (MPI_Abort runs
        // no destructor) leaves complete rows up to its last step
        os  << nl;
        os.flush();
        foamTools::runLogFiles::checkWritten(os);
    }
    if (interfaceFile_.valid())
    {
        OFstream& os = interfaceFile_();
        os  << runTime_.value();
        for (label i = 0; i < 2*interfaceElements_.size(); ++i)
        {
            os  << ' ' << values[maximaOffset_ + i];
        }
        os  << nl;
        os.flush();
        foamTools::runLogFiles::checkWritten(os);
    }
    if (patchFile_.valid())
    {
        std::vector<solid::ElementStress> stress(patchElements_.size());
        for (std::size_t k = 0; k < patchElements_.size(); ++k)
        {
            const double* x = values.data() + patchOffset_ + 10*k;
            stress[k].p = x[0];
            std::copy(x + 1, x + 10, stress[k].sigma.data());
        }
        const auto of = [&](int e) -> const solid::ElementStress&
        {
            return stress
            [
                std::lower_bound
                (
                    patchElements_.begin(), patchElements_.end(), e
                ) - patchElements_.begin()
            ];
        };
        OFstream& os = patchFile_();
        os  << runTime_.value();
        std::vector<solid::InterfaceMeasures> measures;
        for (const solid::InterfacePatch& ip : patches_)
        {
            measures.push_back(ip.evaluate(of));
            const solid::InterfaceMeasures& r = measures.back();
            os  << ' ' << r.pPatch << ' ' << r.vonMisesPatch << ' '
                << r.shearPatch << ' ' << r.vonMisesPatchAt(0) << ' '
                << r.vonMisesPatchAt(1) << ' ' << r.vonMisesPatchAt(2) << ' '
                << r.pMax << ' ' << r.vonMisesMax << ' ' << r.shearMax;
        }
        os  << nl;
        os.flush();
        foamTools::runLogFiles::checkWritten(os);
        if (placeFile_.valid())
        {
            OFstream& ps = placeFile_();
            ps  << runTime_.value();
            for (const solid::InterfaceMeasures& r : measures)
            {
                for (std::size_t k = 0; k < r.pAt.size(); ++k)
                {
                    ps  << ' ' << r.pAt[k] << ' ' << r.vonMisesAt[k] << ' '
                        << r.shearAt[k];
                }
            }
            ps  << nl;
            ps.flush();
            foamTools::runLogFiles::checkWritten(ps);
        }
    }
    if (runTime_.writeTime())
    {
        // The logs complete up to this write time before it is committed:
        // a run killed later restarts here and loses no row
        for
        (
            autoPtr<OFstream>* f :
                {&probeFile_, &interfaceFile_, &patchFile_, &placeFile_}
        )
        {
            if (f->valid())
            {
                (*f)().flush();
                foamTools::runLogFiles::checkWritten((*f)());
            }
        }
        // The whole solid's histories on the master for the result file
        // (stresses) and the restart state
        model_->shareStates();
        label k = -1;
        if (writer_)
        {
            guarded("solid output", [&] { k = writer_->write(*model_); });
        }
        Pstream::scatter(k);
        writeState(k);
        const solid::EnergyReport& e = solver_->energy();
        Info<< "Solid: energy balance " << e.balance() << " J of "
            << e.externalWork << " J external work, " << solver_->steps()
            << " steps" << endl;
        // The probes are material points: where they have moved to
        for (label i = 0; i < label(probes_.size()); ++i)
        {
            const solid::Vec3 u(probes_[i].interpolate(model_->u));
            Info<< "Solid: probe " << probeNames_[i] << " displaced by ("
                << u(0) << ' ' << u(1) << ' ' << u(2) << ") m" << endl;
        }
    }
}
