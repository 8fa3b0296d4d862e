#include "solidDomain.H"
#include "GmshReader.H"
#include "Material.H"
#include "SolidError.H"
#include "primitiveEntry.H"
#include "OStringStream.H"
#include "IOobject.H"
#include "labelVector.H"
#include "pointField.H"
#include "vector2D.H"

#include <cmath>

namespace
{

//- Run f; a solid::SolidError becomes a FatalError naming the context
template<class F>
void guarded(const char* context, F&& f)
{
    try
    {
        f();
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << context << ": " << e.what() << Foam::exit(Foam::FatalError);
    }
}

} // namespace


solid::Mesh Foam::solidDomain::readMesh
(
    const dictionary& dict,
    const Time& runTime
)
{
    const word type(dict.get<word>("type"));
    solid::Mesh m;
    if (type == "box")
    {
        const labelVector n(dict.get<labelVector>("cells"));
        const vector lo(dict.get<vector>("min")), hi(dict.get<vector>("max"));
        guarded("solid mesh box", [&]
        {
            m = solid::Mesh::box
            (
                n.x(), n.y(), n.z(),
                solid::Vec3(lo.x(), lo.y(), lo.z()),
                solid::Vec3(hi.x(), hi.y(), hi.z())
            );
        });
    }
    else if (type == "rectangle")
    {
        const Vector2D<label> n(dict.get<Vector2D<label>>("cells"));
        const vector2D lo(dict.get<vector2D>("min"));
        const vector2D hi(dict.get<vector2D>("max"));
        guarded("solid mesh rectangle", [&]
        {
            m = solid::Mesh::rectangle
            (
                n.x(), n.y(), lo.x(), hi.x(), lo.y(), hi.y()
            );
        });
    }
    else if (type == "gmsh")
    {
        fileName file(dict.get<fileName>("file"));
        file.expand();
        if (!file.isAbsolute()) file = runTime.path()/file;
        const scalar scale = dict.getOrDefault<scalar>("scale", 1);
        guarded("solid mesh gmsh", [&] { m = solid::readGmsh(file, scale); });
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Unknown solid mesh type " << type
            << "; valid types: (box rectangle gmsh)" << exit(FatalIOError);
    }
    return m;
}


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
    )
{
    model_.reset(new solid::Model(readMesh(dict_.subDict("mesh"), runTime)));

    const dictionary& mats = dict_.subDict("materials");
    for (const std::string& region : model_->mesh().regionNames)
    {
        if (!mats.isDict(region))
        {
            FatalIOErrorInFunction(mats)
                << "No material for solid region " << region
                << "; regions: "
                << wordList(model_->mesh().regionNames.begin(),
                            model_->mesh().regionNames.end())
                << exit(FatalIOError);
        }
        std::map<std::string, std::string> entries;
        for (const entry& e : mats.subDict(region))
        {
            OStringStream os;
            for (const token& t : e.stream()) os << t;
            entries[e.keyword()] = os.str();
        }
        guarded("solid material", [&]
        {
            model_->setMaterial
            (
                region,
                solid::Material::create
                (
                    solid::MaterialParameters::fromEntries(region, entries)
                )
            );
        });
    }

    const List<Tuple2<word, label>> fixed
    (
        dict_.get<List<Tuple2<word, label>>>("fixed")
    );
    for (const auto& f : fixed)
    {
        guarded("solid fixed", [&] { model_->fix(f.first(), f.second()); });
    }
}


void Foam::solidDomain::couple(const labelList& interfaceNodes)
{
    interfaceNodes_.assign(interfaceNodes.begin(), interfaceNodes.end());
    force_ =
        std::make_shared<interfaceForce>(interfaceNodes_, mesh().dim());
    model_->add(force_);

    solid::ExplicitSettings set;
    set.safety = dict_.getOrDefault<scalar>("explicitSafety", 0.8);
    guarded("solid initialise", [&]
    {
        model_->initialise();
        solver_.reset(new solid::ExplicitSolver(*model_, set));
    });

    // Probes: the element whose reference centroid is nearest
    const pointField probes(dict_.getOrDefault<pointField>("probes", {}));
    const solid::Mesh& m = mesh();
    probeElements_.setSize(probes.size());
    forAll(probes, i)
    {
        scalar best = GREAT;
        for (int e = 0; e < m.nElements(); ++e)
        {
            solid::Vec3 c(solid::Vec3::Zero());
            for (int a = 0; a < m.nen(); ++a) c += m.X[m.element(e)[a]];
            c /= m.nen();
            const scalar d =
                (c - solid::Vec3(probes[i].x(), probes[i].y(), probes[i].z()))
               .norm();
            if (d < best) { best = d; probeElements_[i] = e; }
        }
    }
    probeLogTheta_.setSize(probes.size(), 0);
    if (probes.size() && Pstream::master())
    {
        const fileName dir
        (
            runTime_.path()/"postProcessing"/"solidProbes"
           /runTime_.timeName()
        );
        mkDir(dir);
        probeFile_.reset(new OFstream(dir/"solidProbes.dat"));
        OFstream& os = probeFile_();
        os.precision(10);
        os  << "# solid probes (element average; strain = ln J, the"
            << " longitudinal strain in uniaxial strain)" << nl
            << "# time [s]";
        forAll(probes, i)
        {
            os  << "  p" << i << "[Pa] vonMises" << i << "[Pa] strain" << i
                << "[-] strainRate" << i << "[1/s] dT" << i << "[K]";
        }
        os  << nl;
        forAll(probes, i)
        {
            os  << "# probe " << i << " at " << probes[i] << " m: element "
                << probeElements_[i] << nl;
        }
    }

    const fileName dir(runTime_.path()/"solid");
    mkDir(dir);
    guarded("solid output", [&]
    {
        writer_.reset(new solid::ResultWriter(dir/"solid", *model_));
    });
    save();
}


void Foam::solidDomain::save()
{
    saved_.u = model_->u;
    saved_.v = model_->v;
    saved_.pressure = model_->pressure;
    saved_.time = model_->time;
    saved_.pointState = model_->pointState();
    saved_.elementState = model_->elementState();
    saved_.solver.reset(new solid::ExplicitSolver(*solver_));
}


void Foam::solidDomain::restore()
{
    model_->u = saved_.u;
    model_->v = saved_.v;
    model_->pressure = saved_.pressure;
    model_->time = saved_.time;
    model_->pointState() = saved_.pointState;
    model_->elementState() = saved_.elementState;
    solver_.reset(new solid::ExplicitSolver(*saved_.solver));
}


void Foam::solidDomain::advance
(
    const scalarField& interfaceForces,
    const scalar t
)
{
    force_->set
    (
        std::vector<double>(interfaceForces.begin(), interfaceForces.end())
    );
    guarded("solid step", [&] { solver_->advanceTo(t); });
}


void Foam::solidDomain::write()
{
    if (probeFile_.valid())
    {
        OFstream& os = probeFile_();
        os  << runTime_.value();
        forAll(probeElements_, i)
        {
            const solid::ElementOutput o =
                model_->evaluateElement(probeElements_[i], 0);
            const solid::Mat3 s = o.sigma;
            const solid::Mat3 dev =
                s - s.trace()/3*solid::Mat3::Identity();
            const scalar vm = std::sqrt(1.5*(dev.array()*dev.array()).sum());
            const scalar logJ = std::log(o.theta);
            const scalar dt = runTime_.deltaTValue();
            const scalar rate = (logJ - probeLogTheta_[i])/dt;
            probeLogTheta_[i] = logJ;
            os  << ' ' << o.p << ' ' << vm << ' ' << logJ << ' ' << rate
                << ' ' << o.temperatureRise;
        }
        os  << nl;
    }
    if (runTime_.writeTime())
    {
        guarded("solid output", [&] { writer_->write(*model_); });
        const solid::EnergyReport& e = solver_->energy();
        Info<< "Solid: energy balance " << e.balance() << " J of "
            << e.externalWork << " J external work, " << solver_->steps()
            << " steps" << endl;
    }
}
