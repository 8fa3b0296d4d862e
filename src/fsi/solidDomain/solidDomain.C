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
#include "Pair.H"
#include "Shape.H"

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

    setupOutput();

    const fileName dir(runTime_.path()/"solid");
    mkDir(dir);
    guarded("solid output", [&]
    {
        writer_.reset(new solid::ResultWriter(dir/"solid", *model_));
    });
    save();
}


Foam::scalar Foam::solidDomain::longitudinalStrain(const label e) const
{
    const solid::Mesh& m = mesh();
    const int dim = m.dim();
    const int axial = dim - 1;
    const int* conn = m.element(e);
    const solid::ShapeRule& rule = solid::volumeRule(m.type);
    Eigen::MatrixXd F(Eigen::MatrixXd::Zero(dim, dim));
    for (int q = 0; q < rule.nqp(); ++q)
    {
        const Eigen::MatrixXd& dNdxi = rule.dNdxi[q];
        Eigen::MatrixXd J(Eigen::MatrixXd::Zero(dim, dim));
        for (int a = 0; a < rule.nen; ++a)
        {
            for (int i = 0; i < dim; ++i)
            {
                J.row(i) += m.X[conn[a]][i]*dNdxi.row(a);
            }
        }
        const Eigen::MatrixXd dNdX = dNdxi*J.inverse();
        Eigen::MatrixXd Fq(Eigen::MatrixXd::Identity(dim, dim));
        for (int a = 0; a < rule.nen; ++a)
        {
            for (int i = 0; i < dim; ++i)
            {
                Fq.row(i) += model_->u(dim*conn[a] + i)*dNdX.row(a);
            }
        }
        F += Fq/rule.nqp();
    }
    return std::log(F.col(axial).norm());
}


Foam::labelList Foam::solidDomain::interfaceElements
(
    const word& a,
    const word& b
) const
{
    const solid::Mesh& m = mesh();
    int ra = -1, rb = -1;
    guarded("solid interfaces", [&]
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


void Foam::solidDomain::setupOutput()
{
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
    probeStrain_.setSize(2*probes.size(), 0);
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
        os  << "# solid probes (element average): per probe pressure"
            << " (+ compression), von Mises, volumetric strain ln J and its"
            << " rate, temperature rise; then per probe the longitudinal"
            << " strain ln|F e_z| (shock direction) and its rate" << nl
            << "# time [s]";
        forAll(probes, i)
        {
            os  << "  p" << i << "[Pa] vonMises" << i << "[Pa] strain" << i
                << "[-] strainRate" << i << "[1/s] dT" << i << "[K]";
        }
        forAll(probes, i)
        {
            os  << "  strainZ" << i << "[-] strainRateZ" << i << "[1/s]";
        }
        os  << nl;
        forAll(probes, i)
        {
            solid::Vec3 c(solid::Vec3::Zero());
            for (int a = 0; a < m.nen(); ++a)
            {
                c += m.X[m.element(probeElements_[i])[a]];
            }
            c /= m.nen();
            os  << "# probe " << i << " at " << probes[i] << " m: element "
                << probeElements_[i] << " ("
                << m.regionNames[m.region[probeElements_[i]]]
                << ", centroid " << c[0] << ' ' << c[1] << ' ' << c[2]
                << " m)" << nl;
        }
    }

    const List<Pair<word>> pairs
    (
        dict_.getOrDefault<List<Pair<word>>>("interfaces", {})
    );
    interfaceElements_.setSize(pairs.size());
    forAll(pairs, i)
    {
        interfaceElements_[i] = interfaceElements(pairs[i].first(),
            pairs[i].second());
    }
    if (pairs.size() && Pstream::master())
    {
        const fileName dir
        (
            runTime_.path()/"postProcessing"/"solidInterfaces"
           /runTime_.timeName()
        );
        mkDir(dir);
        interfaceFile_.reset(new OFstream(dir/"interfaceMaxima.dat"));
        OFstream& os = interfaceFile_();
        os.precision(10);
        os  << "# maxima over the elements along each region interface"
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
    const auto vonMises = [](const solid::Mat3& s)
    {
        const solid::Mat3 dev = s - s.trace()/3*solid::Mat3::Identity();
        return std::sqrt(1.5*(dev.array()*dev.array()).sum());
    };
    const scalar dt = runTime_.deltaTValue();
    if (probeFile_.valid())
    {
        OFstream& os = probeFile_();
        os  << runTime_.value();
        forAll(probeElements_, i)
        {
            const solid::ElementOutput o =
                model_->evaluateElement(probeElements_[i], 0);
            const scalar logJ = std::log(o.theta);
            os  << ' ' << o.p << ' ' << vonMises(o.sigma) << ' ' << logJ
                << ' ' << (logJ - probeStrain_[2*i])/dt << ' '
                << o.temperatureRise;
            probeStrain_[2*i] = logJ;
        }
        forAll(probeElements_, i)
        {
            const scalar ez = longitudinalStrain(probeElements_[i]);
            os  << ' ' << ez << ' ' << (ez - probeStrain_[2*i + 1])/dt;
            probeStrain_[2*i + 1] = ez;
        }
        os  << nl;
    }
    if (interfaceFile_.valid())
    {
        OFstream& os = interfaceFile_();
        os  << runTime_.value();
        for (const labelList& elems : interfaceElements_)
        {
            scalar pMax = -GREAT, vmMax = 0;
            for (const label e : elems)
            {
                const solid::ElementOutput o = model_->evaluateElement(e, 0);
                pMax = max(pMax, o.p);
                vmMax = max(vmMax, vonMises(o.sigma));
            }
            os  << ' ' << pMax << ' ' << vmMax;
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
