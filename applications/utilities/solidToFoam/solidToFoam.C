/*---------------------------------------------------------------------------*\
Application
    solidToFoam

Description
    Converts the results of the solid library (the HDF5 file written by
    solid::ResultWriter: mesh, and per step displacement, velocity, Cauchy
    stress, pressure, von Mises, J, temperature rise, region) into an
    OpenFOAM mesh region (default "solid") with one time directory per step,
    so that foamToVTK -region solid and ParaView's OpenFOAM reader show the
    cell next to the fluid.

    3D meshes (hexahedra) are converted as they are. Axisymmetric meshes
    (quadrilaterals in the r-z plane) are revolved into a wedge of
    -wedgeAngle degrees (default 5) about the z axis; the cells on the axis
    become prisms, the displacement is rotated to each point's angle and
    the stress is written in (x = r, y = theta, z) components.

    Fields: pointVectorField D [m] and pointVectorField Ud [m/s] (nodal),
    volSymmTensorField sigma [Pa], volScalarFields pressure [Pa] (positive
    in compression), vonMises [Pa], J [-], temperatureRise [K], region [-].

Usage
    solidToFoam <file.h5> [-region solid] [-wedgeAngle 5] [-overwrite]

    The mesh constant/<region>/polyMesh is replaced only when solidToFoam
    wrote it (its marker constant/<region>/polyMesh/.solidToFoam), or with
    -overwrite: a user's mesh there is refused, named, nothing written
    (issue 19, adv52 p20).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "pointFields.H"
#include "cellModel.H"
#include "cellShapeList.H"
#include "Hdf5File.H"
#include "ResultWriter.H"
#include "uniformState.H"
#include "SolidError.H"
#include "inputChecks.H"

#include <dirent.h>
#include <memory>
#include <unistd.h>
#include "caseLock.H"
#include "solidToFoamFiles.H"

using namespace Foam;

namespace
{

//- An HDF5 result file read through the solid library's HDF5 layer; its
//  errors become FatalErrors naming the file and item
class h5File
{
    std::unique_ptr<solid::Hdf5File> file_;

    //- Run f; a SolidError (naming the file and item) is fatal
    template<class F>
    static void guarded(F&& f)
    {
        try
        {
            f();
        }
        catch (const solid::SolidError& e)
        {
            FatalErrorInFunction
                << e.what() << exit(FatalError);
        }
    }

public:

    explicit h5File(const fileName& name)
    {
        guarded([&]
        {
            file_.reset
            (
                new solid::Hdf5File(name, solid::Hdf5File::Mode::readOnly)
            );
        });
    }

    //- Read a dataset of doubles: its rows and columns (1 for a vector)
    List<scalar> read(const word& path, label& rows, label& cols) const
    {
        std::size_t r = 0, c = 0;
        std::vector<double> v;
        guarded([&] { v = file_->read(path, &r, &c); });
        rows = r;
        cols = c;
        List<scalar> data(v.size());
        std::copy(v.begin(), v.end(), data.begin());
        return data;
    }

    //- Whether the file holds item name (a group or dataset of the root)
    bool has(const std::string& name) const
    {
        bool found = false;
        guarded([&] { found = file_->has(name); });
        return found;
    }

    //- Step indices and times [s], in order
    List<Tuple2<label, scalar>> steps() const
    {
        List<Tuple2<label, scalar>> result;
        if (!file_->has("steps"))
        {
            return result;
        }
        guarded([&]
        {
            const solid::Hdf5Group g(*file_, "steps", false);
            for (const std::string& name : g.members())
            {
                const solid::Hdf5Group s(g, name, false);
                result.append
                (
                    Tuple2<label, scalar>
                    (
                        readLabel(name), s.readAttribute("time")
                    )
                );
            }
        });
        Foam::sort
        (
            result,
            [](const Tuple2<label, scalar>& a, const Tuple2<label, scalar>& b)
            {
                return a.first() < b.first();
            }
        );
        return result;
    }
};

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Convert the solid library's HDF5 results into an OpenFOAM mesh"
        " region with time directories (for foamToVTK / ParaView)"
    );
    argList::noParallel();
    argList::addArgument("file.h5");
    argList::addOption("region", "name", "region name (default: solid)");
    argList::addOption
    (
        "wedgeAngle", "deg", "axisymmetric revolution angle (default: 5)"
    );
    argList::addBoolOption
    (
        "overwrite",
        "replace a constant/<region>/polyMesh that solidToFoam did not write"
        " (its marker .solidToFoam missing: a user's mesh)"
    );

    // setRootCase.H with checkCasePath before OpenFOAM checks the case
    #include "setRootCaseChecked.H"
    // one writer per case: a solver running in it (or another utility)
    // is named and nothing is written (adv33 lk10: setRiemannProblem
    // -overwrite removed a running solver's time directories)
    const foamTools::caseLock lock(args);
    // -wedgeAngle's valid range, named also for a value OpenFOAM's reader
    // would take as 0 (4.9e-324, 1e-300: was checkOptions' reader limits
    // without the range, adv47b f62), before checkOptions
    const char* const wedgeRange = "(0, 180) degrees";
    if
    (
        args.found("wedgeAngle")
     && foamTools::outsideReaderRange(args.opt("wedgeAngle")) < 0
    )
    {
        FatalErrorInFunction
            << "option -wedgeAngle '" << args.opt("wedgeAngle").c_str()
            << "' " << foamTools::readerRangeText(-1).c_str()
            << "; its valid range is " << wedgeRange << ": give a value in "
            << "it" << nl << "    Nothing was read or written."
            << exit(FatalError);
    }
    foamTools::checkOptions(args);     // no nan, inf or 1e999 in options
    #include "createTime.H"

    const fileName h5Name(args[1]);
    // A plain name, not one of the case's own folders (issue 19; adv32
    // h07, h08: -region constant, polyMesh accepted)
    const word region
    (
        foamTools::regionOption(args, "solid", "constant/<region>, "
            "system/<region> and <time>/<region>")
    );
    // A mesh of the region that solidToFoam did not write (no marker in
    // it: a user's mesh, or a mesh of a build before the marker) is not
    // replaced without -overwrite (adv52 p20: a user's points and boundary
    // replaced without a word)
    {
        const fileName meshDir(runTime.path()/"constant"/region/"polyMesh");
        if
        (
            isDir(meshDir, false) && !args.found("overwrite")
         && !isFile
            (
                meshDir/foamTools::solidToFoamFiles::marker(), false, false
            )
         && !readDir(meshDir, fileName::FILE, false, false).empty()
        )
        {
            FatalErrorInFunction
                << meshDir.c_str() << " holds a mesh solidToFoam did not "
                << "write (no marker " << foamTools::solidToFoamFiles::marker()
                << " in it: a user's mesh, or one converted before the "
                << "marker existed): the conversion would replace it. Move "
                << "it away, give another -region, or give -overwrite to "
                << "replace it." << nl << "    Nothing was written."
                << exit(FatalError);
        }
    }
    const scalar angle =
        degToRad(args.opt<scalar>("wedgeAngle", 5.0));
    if (!(angle > 0 && angle < constant::mathematical::pi))
    {
        FatalErrorInFunction
            << "-wedgeAngle must be in " << wedgeRange << exit(FatalError);
    }

    const h5File h5(h5Name);
    // A checkpoint of cellIndentationFoam (restart.h5: the state to go on
    // from, no mesh nor steps) is no results file: said as such (adv48b
    // g52: "cannot open dataset /mesh/coordinates (missing?)")
    if (!h5.has("mesh") && h5.has("model"))
    {
        FatalErrorInFunction
            << h5Name.c_str() << " is a checkpoint (cellIndentationFoam's "
            << "restart.h5: the state a restart continues from, without "
            << "the mesh and the steps), not a results file of the solid "
            << "solvers. Give the run's results file, solid.h5 beside it"
            << " (postProcessing/indentation/solid.h5)." << nl
            << "    Nothing was written." << exit(FatalError);
    }
    const List<Tuple2<label, scalar>> steps = h5.steps();

    // The results of the run whose time directories they go into: a time
    // that records the run's solid state (uniform/solidState, cellBlastFoam)
    // names the run id solid.h5 must carry (adv53 l27: another run's
    // solid.h5, valid and checksummed, was converted into this case's
    // times without a word; a restart refuses it alike)
    for (const auto& step : steps)
    {
        const fileName state
        (
            runTime.path()/runTime.timeName(step.second())/"uniform"
           /foamTools::uniformState::solidState()
        );
        if (!isFile(state))
        {
            continue;
        }
        IFstream is(state);
        const dictionary d(is);
        const string runId(d.lookupOrDefault<string>("runId", string()));
        if (!runId.empty())
        {
            try
            {
                solid::ResultWriter::checkContinued(h5Name, runId);
            }
            catch (const solid::SolidError& err)
            {
                FatalErrorInFunction
                    << h5Name.c_str() << " is not the results of the run"
                    << " that wrote " << state.path().path() << ": "
                    << err.what() << nl << "    Converting it would put"
                    << " another run's solid fields into this case's time"
                    << " directories. Give the run's own solid.h5." << nl
                    << "    Nothing was written." << exit(FatalError);
            }
        }
        break;
    }

    // The region's time directories of an earlier conversion that this
    // solid.h5 no longer has (a new run with fewer steps): removed once
    // the new ones are written, so that the region's time series is one
    // run's. Only what solidToFoam wrote (its marker, <time>/<region>/
    // .solidToFoam) is removed; a region folder without it (a user's, or
    // of a build before the marker) stops the conversion, named, before
    // anything is written (issue 19, adv35 t45)
    // (its marker and fields: foamTools::solidToFoamFiles, the one list,
    // also read by the solvers' -overwrite, resultGuard)
    const word marker(foamTools::solidToFoamFiles::marker());
    // The cell fields a conversion writes into <time>/<region>/ with their
    // dimensions (dimensionSet assignment checks equality: no
    // List<dimensionSet>)
    const std::pair<word, const dimensionSet*> scalarFields[] =
    {
        {"pressure", &dimPressure},
        {"vonMises", &dimPressure},
        {"J", &dimless},
        {"temperatureRise", &dimTemperature},
        {"region", &dimless}
    };
    DynamicList<fileName> stale;
    {
        wordHashSet current;
        for (const auto& step : steps)
        {
            current.insert(runTime.timeName(step.second()));
        }
        DynamicList<fileName> foreign;
        for (const fileName& d : readDir(runTime.path(), fileName::DIRECTORY))
        {
            scalar t;
            const fileName r(runTime.path()/d/region);
            if (!readScalar(d, t) || current.found(d) || !isDir(r, false))
            {
                continue;
            }
            (isFile(r/marker, false, false) ? stale : foreign).append(d);
        }
        // A marked folder that holds more than the conversion wrote (a
        // user's file put there): removing the folder would remove it
        // too (adv36 v32: removed without a word, exit 0)
        DynamicList<fileName> foreignFiles;
        for (const fileName& d : stale)
        {
            DIR* dp = ::opendir((runTime.path()/d/region).c_str());
            for (const dirent* de; dp && (de = ::readdir(dp)) != nullptr;)
            {
                const std::string n(de->d_name);
                if
                (
                    n != "." && n != ".."
                 && !foamTools::solidToFoamFiles::written(n)
                )
                {
                    foreignFiles.append(runTime.path()/d/region/n);
                }
            }
            if (dp)
            {
                ::closedir(dp);
            }
        }
        if (foreignFiles.size())
        {
            FatalErrorInFunction
                << "the time directories";
            for (const fileName& d : stale)
            {
                FatalError << " " << d.c_str();
            }
            FatalError
                << " of " << runTime.path().c_str() << " hold a folder '"
                << region << "' of an earlier conversion that "
                << h5Name.c_str() << " has no step for (removed by a"
                << " conversion of this file), but it holds files"
                << " solidToFoam did not write:";
            for (const fileName& f : foreignFiles)
            {
                FatalError << nl << "    " << f.c_str();
            }
            FatalError
                << nl << "    Kept, and nothing written. Move those files"
                << " out of the folder (or remove them), or convert into"
                << " another -region" << exit(FatalError);
        }
        if (foreign.size())
        {
            FatalErrorInFunction
                << "the time directories";
            for (const fileName& d : foreign)
            {
                FatalError << " " << d.c_str();
            }
            FatalError
                << " of " << runTime.path().c_str() << " hold a folder '"
                << region << "' that " << h5Name.c_str() << " has no step for, and"
                << " that solidToFoam did not mark as its own (<time>/"
                << region << "/" << marker << "): an earlier conversion of"
                << " another run, or files of yours. Kept, and nothing"
                << " written: converted with the new file, the region's"
                << " time series would mix two runs. Remove those folders"
                << " (<time>/" << region << ") if they are an earlier"
                << " conversion, or convert into another -region"
                << exit(FatalError);
        }
    }

    label nNodes, nc, nElems, nen;
    const List<scalar> X = h5.read("/mesh/coordinates", nNodes, nc);
    const List<scalar> conn = h5.read("/mesh/connectivity", nElems, nen);
    if (nen != 4 && nen != 8)
    {
        FatalErrorInFunction
            << h5Name << ": elements with " << nen << " nodes; expected 4"
            << " (axisymmetric quadrilaterals) or 8 (hexahedra)"
            << exit(FatalError);
    }
    const bool axisymmetric = (nen == 4);

    // Points: as they are (3D) or the two sides of the wedge; a node on the
    // axis keeps a single point so that its cells collapse to prisms
    DynamicList<point> pts(2*nNodes);
    labelList minus(nNodes), plus(nNodes);
    List<scalar> phiMinus(nNodes, Zero), phiPlus(nNodes, Zero);
    const scalar ca = std::cos(angle/2), sa = std::sin(angle/2);
    scalar rMax = 0;
    for (label i = 0; i < nNodes; ++i) rMax = max(rMax, mag(X[3*i]));
    for (label i = 0; i < nNodes; ++i)
    {
        const scalar x = X[3*i], y = X[3*i + 1], z = X[3*i + 2];
        if (!axisymmetric)
        {
            minus[i] = plus[i] = pts.size();
            pts.append(point(x, y, z));
            continue;
        }
        // r = x, axial = y: revolve about the z axis of OpenFOAM
        if (x <= 1e-12*rMax)
        {
            minus[i] = plus[i] = pts.size();
            pts.append(point(0, 0, y));
        }
        else
        {
            minus[i] = pts.size();
            pts.append(point(x*ca, -x*sa, y));
            plus[i] = pts.size();
            pts.append(point(x*ca, x*sa, y));
            phiMinus[i] = -angle/2;
            phiPlus[i] = angle/2;
        }
    }

    const cellModel& hex = cellModel::ref(cellModel::HEX);
    cellShapeList shapes(nElems);
    forAll(shapes, e)
    {
        labelList v(8);
        if (axisymmetric)
        {
            for (label k = 0; k < 4; ++k)
            {
                const label n = label(conn[4*e + k]);
                v[k] = plus[n];
                v[k + 4] = minus[n];
            }
        }
        else
        {
            for (label k = 0; k < 8; ++k) v[k] = label(conn[8*e + k]);
        }
        shapes[e] = cellShape(hex, v, true);
    }

    Info<< "Solid mesh: " << nNodes << " nodes, " << nElems << " "
        << (axisymmetric ? "axisymmetric quadrilaterals revolved by "
            + Foam::name(radToDeg(angle)) + " deg" : word("hexahedra"))
        << endl;

    {
        polyMesh mesh
        (
            IOobject(region, runTime.constant(), runTime),
            pointField(pts),
            shapes,
            faceListList(),
            wordList(),
            PtrList<dictionary>(),
            "surface",
            "patch"
        );
        mesh.setInstance(runTime.constant());
        mesh.removeFiles();
        // its marker first: a later conversion may replace this mesh (adv52
        // p20), also one cut by a failed write (adv53's p08 on the merge:
        // a mesh cut by ulimit -f, its marker not yet written, was then
        // refused as a user's)
        mkDir(runTime.path()/"constant"/region/"polyMesh");
        OFstream marker
        (
            runTime.path()/"constant"/region/"polyMesh"
           /foamTools::solidToFoamFiles::marker()
        );
        marker
            << "written by solidToFoam from " << h5Name.c_str() << nl;
        if (!marker.good())
        {
            FatalErrorInFunction
                << "cannot write " << marker.name() << exit(FatalError);
        }
        mesh.write();
    }

    // fvSchemes and fvSolution of the region (needed to construct it, by
    // this utility and by foamToVTK): minimal ones unless present
    const HashTable<string> minimalDicts
    {
        {
            "fvSchemes",
            "ddtSchemes { default none; } gradSchemes { default none; }"
            " divSchemes { default none; } laplacianSchemes { default none; }"
            " interpolationSchemes { default linear; }"
            " snGradSchemes { default corrected; }"
        },
        {"fvSolution", ""}
    };
    forAllConstIters(minimalDicts, iter)
    {
        const word& dictName = iter.key();
        const fileName dictFile(runTime.system()/region/dictName);
        if (!isFile(runTime.path()/dictFile))
        {
            mkDir(runTime.path()/runTime.system()/region);
            IOdictionary
            (
                IOobject
                (
                    dictName, runTime.system(), region, runTime,
                    IOobject::NO_READ, IOobject::NO_WRITE, false
                ),
                dictionary(IStringStream(iter.val())())
            ).regIOobject::write();
        }
    }

    fvMesh mesh
    (
        IOobject
        (
            region, runTime.constant(), runTime, IOobject::MUST_READ
        )
    );
    const pointMesh& pMesh = pointMesh::New(mesh);

    for (const auto& step : steps)
    {
        runTime.setTime(step.second(), step.first());
        const word g("/steps/" + Foam::name(step.first()) + "/");
        Info<< "Step " << step.first() << ", time " << runTime.timeName()
            << " s" << endl;
        {
            // this folder is solidToFoam's (removed by a later conversion
            // that has no such step)
            const fileName dir(runTime.timePath()/region);
            mkDir(dir);
            OFstream(dir/marker)()
                << "written by solidToFoam from " << h5Name.c_str()
                << ", step " << step.first() << nl;
        }

        // Nodal vectors, rotated to the angle of each point
        for (const word& name : {word("displacement"), word("velocity")})
        {
            label r, c;
            const List<scalar> d = h5.read(g + name, r, c);
            pointVectorField f
            (
                IOobject
                (
                    name == "displacement" ? "D" : "Ud",
                    runTime.timeName(), mesh, IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                pMesh,
                dimensionedVector
                (
                    name == "displacement" ? dimLength : dimVelocity, Zero
                )
            );
            for (label i = 0; i < nNodes; ++i)
            {
                if (axisymmetric)
                {
                    const scalar ur = d[3*i], uz = d[3*i + 1];
                    f[minus[i]] = vector
                    (
                        ur*std::cos(phiMinus[i]), ur*std::sin(phiMinus[i]), uz
                    );
                    f[plus[i]] = vector
                    (
                        ur*std::cos(phiPlus[i]), ur*std::sin(phiPlus[i]), uz
                    );
                }
                else
                {
                    f[i] = vector(d[3*i], d[3*i + 1], d[3*i + 2]);
                }
            }
            f.write();
        }

        // Cell fields
        {
            label r, c;
            const List<scalar> s = h5.read(g + "cauchyStress", r, c);
            volSymmTensorField sigma
            (
                IOobject("sigma", runTime.timeName(), mesh),
                mesh,
                dimensionedSymmTensor(dimPressure, Zero)
            );
            forAll(sigma, e)
            {
                const scalar* S = &s[9*e];
                // axisymmetric storage (r, z, theta) -> (x, z, y)
                sigma[e] = axisymmetric
                  ? symmTensor(S[0], S[2], S[1], S[8], S[5], S[4])
                  : symmTensor(S[0], S[1], S[2], S[4], S[5], S[8]);
            }
            sigma.write();
        }
        // (scalarFields: above, with what a conversion writes)
        for (const auto& field : scalarFields)
        {
            label r, c;
            const List<scalar> v = h5.read(g + field.first, r, c);
            volScalarField f
            (
                IOobject(field.first, runTime.timeName(), mesh),
                mesh,
                dimensionedScalar(*field.second, Zero)
            );
            f.primitiveFieldRef() = scalarField(v);
            f.write();
        }
    }

    // the earlier conversion's times this file has not: removed (and a
    // time directory left empty by it)
    for (const fileName& d : stale)
    {
        rmDir(runTime.path()/d/region);
        // the time directory too if nothing else is in it (rmdir(2) removes
        // only an empty directory; hidden files count)
        ::rmdir((runTime.path()/d).c_str());
        Info<< "Removed " << (d/region).c_str() << ": a time of an earlier"
            << " conversion that " << h5Name.c_str() << " has no step for" << endl;
    }

    Info<< "Wrote region " << region << " with " << steps.size()
        << " time directories" << nl << "End" << endl;

    return 0;
}
