#include "cellMesher.H"
#include "meshQuality.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include <gmsh.h>
#include <algorithm>
#include <set>
#include <sstream>

using Foam::constant::mathematical::pi;

namespace
{

namespace geo = gmsh::model::geo;

//- The entities of dimension dim and of all their boundaries, by dimension
std::vector<std::vector<int>> closure(int dim, const std::vector<int>& tags)
{
    std::vector<std::vector<int>> byDim(dim + 1);
    byDim[dim] = tags;
    for (int d = dim; d > 0; --d)
    {
        gmsh::vectorpair in, out;
        for (const int t : byDim[d]) in.push_back({d, t});
        gmsh::model::getBoundary(in, out, false, false, false);
        std::set<int> lower;
        for (const auto& dt : out) lower.insert(std::abs(dt.second));
        byDim[d - 1].assign(lower.begin(), lower.end());
    }
    return byDim;
}

//- A field of constant size h on the given entities (and their closure)
int restrictedSize(int dim, const std::vector<int>& tags, double h)
{
    namespace field = gmsh::model::mesh::field;
    const int c = field::add("MathEval");
    std::ostringstream os;
    os.precision(17);
    os << h;
    field::setString(c, "F", os.str());
    const int f = field::add("Restrict");
    field::setNumber(f, "InField", c);
    const auto byDim = closure(dim, tags);
    const char* names[] = {"PointsList", "CurvesList", "SurfacesList",
                           "VolumesList"};
    for (int d = 1; d <= dim; ++d)
    {
        field::setNumbers
        (
            f, names[d], std::vector<double>(byDim[d].begin(), byDim[d].end())
        );
    }
    return f;
}

Foam::label nEdges(int curve)
{
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> etags, ntags;
    gmsh::model::mesh::getElements(types, etags, ntags, 1, curve);
    Foam::label n = 0;
    for (const auto& e : etags) n += Foam::label(e.size());
    return n;
}

//- Number of 2D elements that are not quadrilaterals
Foam::label nonQuadrilaterals()
{
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> etags, ntags;
    gmsh::model::mesh::getElements(types, etags, ntags, 2, -1);
    Foam::label n = 0;
    for (std::size_t t = 0; t < types.size(); ++t)
    {
        if (types[t] != 3) n += Foam::label(etags[t].size());
    }
    return n;
}

std::vector<int> boundaryCurves(int surface)
{
    gmsh::vectorpair out;
    gmsh::model::getBoundary({{2, surface}}, out, false, false, false);
    std::vector<int> c;
    for (const auto& dt : out) c.push_back(std::abs(dt.second));
    return c;
}

void addGroup(int dim, const std::vector<int>& tags, const std::string& name)
{
    if (tags.empty())
    {
        FatalErrorInFunction
            << "Physical group " << name << " (dimension " << dim
            << ") is empty" << Foam::exit(Foam::FatalError);
    }
    const int g = gmsh::model::addPhysicalGroup(dim, tags);
    gmsh::model::setPhysicalName(dim, g, name);
}

}


int Foam::cellMesher::point(const cellGeometry::rz& p) const
{
    const scalar r = p.first()/L_, z = p.second()/L_;
    return geom_.axisymmetric()
        ? geo::addPoint(r, z, 0)
        : gmsh::model::occ::addPoint(r, 0, z);
}


int Foam::cellMesher::line(int p, int q) const
{
    return geom_.axisymmetric()
        ? geo::addLine(p, q)
        : gmsh::model::occ::addLine(p, q);
}


int Foam::cellMesher::spline(const std::vector<int>& pts) const
{
    return geom_.axisymmetric()
        ? geo::addSpline(pts)
        : gmsh::model::occ::addSpline(pts);
}


int Foam::cellMesher::ellipseArc
(
    int start,
    int centre,
    int major,
    int end,
    const std::function<cellGeometry::rz(scalar)>& X,
    scalar s0,
    scalar s1
) const
{
    if (geom_.axisymmetric())
    {
        return geo::addEllipseArc(start, centre, major, end);
    }
    // OpenCASCADE: a spline through 200 points of the exact curve
    std::vector<int> pts{start};
    const label n = 200;
    for (label i = 1; i < n; ++i)
    {
        pts.push_back(point(X(s0 + (s1 - s0)*i/n)));
    }
    pts.push_back(end);
    return spline(pts);
}


int Foam::cellMesher::surface(const std::vector<int>& curves) const
{
    return geom_.axisymmetric()
        ? geo::addPlaneSurface({geo::addCurveLoop(curves)})
        : gmsh::model::occ::addPlaneSurface
          (
              {gmsh::model::occ::addCurveLoop(curves)}
          );
}


void Foam::cellMesher::buildSection()
{
    typedef cellGeometry::rz rz;
    const scalar a = geom_.a(), H = geom_.H(), t = geom_.t();

    // Angles from the top of the membrane patches and their tangential
    // element sizes
    std::vector<scalar> theta{0};
    std::vector<scalar> size;
    const bool contact = geom_.contactRadius() > 0;
    const scalar thetaC = geom_.thetaContact();
    if (contact && thetaC < 0.5*pi*(1 - 1e-9))
    {
        theta.push_back(thetaC);
        size = {geom_.contactSize(), geom_.membraneSize()};
    }
    else
    {
        size = {contact ? geom_.contactSize() : geom_.membraneSize()};
    }
    theta.push_back(0.5*pi);
    const label N = label(theta.size()) - 1;

    const int origin = point(rz(0, 0));
    std::vector<int> outerPt(N + 1), innerPt(N + 1), radial(N + 1);
    for (label k = 0; k <= N; ++k)
    {
        if (k == 0)
        {
            outerPt[k] = point(rz(0, H));
            innerPt[k] = point(rz(0, H - t));
        }
        else if (k == N)
        {
            outerPt[k] = point(rz(a, 0));
            innerPt[k] = point(rz(a - t, 0));
        }
        else
        {
            outerPt[k] = point(geom_.outer(theta[k]));
            innerPt[k] = point(geom_.inner(theta[k]));
        }
        radial[k] = line(outerPt[k], innerPt[k]);
    }
    const int major = a >= H ? outerPt[N] : outerPt[0];

    // Membrane patches: outer ellipse arc, inner parallel curve (spline
    // through 100 exact points per patch), radial lines
    std::vector<int> innerCurve(N);
    std::vector<label> nTangential(N);
    for (label k = 0; k < N; ++k)
    {
        outer_.push_back
        (
            ellipseArc
            (
                outerPt[k], origin, major, outerPt[k + 1],
                [this](scalar th) { return geom_.outer(th); },
                theta[k], theta[k + 1]
            )
        );
        std::vector<int> pts{innerPt[k]};
        const label nSpline = 100;
        for (label i = 1; i < nSpline; ++i)
        {
            pts.push_back
            (
                point
                (
                    geom_.inner(theta[k] + (theta[k + 1] - theta[k])*i/nSpline)
                )
            );
        }
        pts.push_back(innerPt[k + 1]);
        innerCurve[k] = spline(pts);
        membrane_.push_back
        (
            surface({-outer_[k], radial[k], innerCurve[k], -radial[k + 1]})
        );
        nTangential[k] = max
        (
            label(1),
            label(std::ceil(geom_.arcLength(theta[k], theta[k + 1], false)
                           /size[k]))
        );
    }

    // Nucleus: half ellipse on the axis
    const scalar an = geom_.an(), cn = geom_.cn(), zn = geom_.zn();
    const int n0 = point(rz(0, zn - cn));
    const int n1 = point(rz(an, zn));
    const int n2 = point(rz(0, zn + cn));
    const int nc = point(rz(0, zn));
    const int nMajor = an >= cn ? n1 : n2;
    const auto nucleusCurve = [=](scalar phi)
    {
        return rz(an*sin(phi), zn - cn*cos(phi));
    };
    const int arc1 =
        ellipseArc(n0, nc, nMajor, n1, nucleusCurve, 0, 0.5*pi);
    const int arc2 =
        ellipseArc(n1, nc, nMajor, n2, nucleusCurve, 0.5*pi, pi);
    nucleusAxis_ = line(n2, n0);
    nucleus_.push_back(surface({arc1, arc2, nucleusAxis_}));

    // Cytoplasm: between substrate, membrane, axis and nucleus
    cytoplasmBottom_ = line(origin, innerPt[N]);
    const int axisTop = line(innerPt[0], n2);
    const int axisBottom = line(n0, origin);
    std::vector<int> loop{cytoplasmBottom_};
    for (label k = N - 1; k >= 0; --k) loop.push_back(-innerCurve[k]);
    loop.insert(loop.end(), {axisTop, -arc2, -arc1, axisBottom});
    cytoplasm_.push_back(surface(loop));

    bottom_ = {cytoplasmBottom_, radial[N]};
    axis_ = {axisBottom, nucleusAxis_, axisTop, radial[0]};

    if (geom_.axisymmetric())
    {
        geo::synchronize();
        for (label k = 0; k <= N; ++k)
        {
            gmsh::model::mesh::setTransfiniteCurve
            (
                radial[k], geom_.layers() + 1
            );
        }
        for (label k = 0; k < N; ++k)
        {
            gmsh::model::mesh::setTransfiniteCurve
            (
                outer_[k], nTangential[k] + 1
            );
            gmsh::model::mesh::setTransfiniteCurve
            (
                innerCurve[k], nTangential[k] + 1
            );
            gmsh::model::mesh::setTransfiniteSurface(membrane_[k]);
            gmsh::model::mesh::setRecombine(2, membrane_[k]);
        }
    }
}


void Foam::cellMesher::revolve()
{
    // Region of each revolved surface, in input order
    std::vector<std::vector<int>*> region;
    gmsh::vectorpair in;
    for (const int s : nucleus_) { in.push_back({2, s}); region.push_back(&nucleus3_); }
    for (const int s : cytoplasm_) { in.push_back({2, s}); region.push_back(&cytoplasm3_); }
    for (const int s : membrane_) { in.push_back({2, s}); region.push_back(&membrane3_); }

    // OpenCASCADE revolves surfaces touching the axis into proper
    // volumes (the built-in kernel leaves degenerate edges on the axis);
    // fragment makes the shared faces conformal
    namespace occ = gmsh::model::occ;
    const bool quarter = geom_.mode() == cellGeometry::meshMode::quarter3D;
    gmsh::vectorpair volumes;
    for (const auto& dt : in)
    {
        occ::synchronize();
        gmsh::vectorpair out;
        occ::revolve({dt}, 0, 0, 0, 0, 0, 1, quarter ? 0.5*pi : 2*pi, out);
        label n = 0;
        for (const auto& o : out)
        {
            if (o.first == 3)
            {
                volumes.push_back(o);
                ++n;
            }
        }
        if (n != 1)
        {
            FatalErrorInFunction
                << "Revolving surface " << dt.second << " gave " << n
                << " volumes" << exit(FatalError);
        }
    }
    occ::remove(in, true);
    gmsh::vectorpair fragments;
    std::vector<gmsh::vectorpair> map;
    occ::fragment(volumes, {}, fragments, map);
    for (std::size_t i = 0; i < volumes.size(); ++i)
    {
        for (const auto& dt : map[i])
        {
            if (dt.first == 3) region[i]->push_back(dt.second);
        }
    }
    occ::synchronize();
}


void Foam::cellMesher::sizeFields() const
{
    namespace field = gmsh::model::mesh::field;
    const bool axi = geom_.axisymmetric();
    const int dim = axi ? 2 : 3;

    // The tetrahedra of the 3D mesh are split into hexahedra of half their
    // edge length
    const scalar split = (axi ? 1 : 2)/L_;
    const scalar hLayer = geom_.t()/geom_.layers();
    std::vector<double> fields;
    fields.push_back
    (
        restrictedSize
        (
            dim, axi ? nucleus_ : nucleus3_, split*geom_.nucleusSize()
        )
    );
    fields.push_back
    (
        restrictedSize
        (
            dim, axi ? cytoplasm_ : cytoplasm3_, split*geom_.cytoplasmSize()
        )
    );
    if (!axi)
    {
        fields.push_back
        (
            restrictedSize
            (
                dim, membrane3_, split*min(geom_.membraneSize(), hLayer)
            )
        );
    }

    if (geom_.contactRadius() > 0)
    {
        // contactSize in r <= contactRadius, z >= z_s(contactRadius) -
        // contactDepth; growing linearly to the largest size over another
        // contactDepth
        const scalar hFar = split*max
        (
            geom_.membraneSize(),
            max(geom_.nucleusSize(), geom_.cytoplasmSize())
        );
        const scalar hc = split*
        (
            axi ? geom_.contactSize() : min(geom_.contactSize(), hLayer)
        );
        const scalar zLow =
            (geom_.outer(geom_.thetaContact()).second() - geom_.contactDepth())
           /L_;
        const std::string r = axi ? "x" : "sqrt(x*x + y*y)";
        const std::string z = axi ? "y" : "z";
        std::ostringstream os;
        os.precision(17);
        os  << hc << " + " << (hFar - hc) << "*min(1, max(0, max(" << r
            << " - " << geom_.contactRadius()/L_ << ", " << zLow << " - "
            << z << "))/" << geom_.contactDepth()/L_ << ")";
        const int f = field::add("MathEval");
        field::setString(f, "F", os.str());
        fields.push_back(f);
    }
    const int m = field::add("Min");
    field::setNumbers(m, "FieldsList", fields);
    field::setAsBackgroundMesh(m);

    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
}


void Foam::cellMesher::fixParity() const
{
    // A quadrilateral mesh of a surface has an even number of boundary
    // edges (4 n_quad = 2 n_interior + n_boundary): add one edge on a
    // free curve of each surface where the count is odd
    gmsh::model::mesh::generate(1);
    bool changed = false;
    for (const auto& sc : {std::make_pair(nucleus_[0], nucleusAxis_),
                           std::make_pair(cytoplasm_[0], cytoplasmBottom_)})
    {
        label n = 0;
        for (const int c : boundaryCurves(sc.first)) n += nEdges(c);
        if (n % 2)
        {
            gmsh::model::mesh::setTransfiniteCurve
            (
                sc.second, nEdges(sc.second) + 2
            );
            changed = true;
        }
    }
    if (changed)
    {
        gmsh::model::mesh::clear();
    }
}


void Foam::cellMesher::physicalGroups2D() const
{
    addGroup(2, nucleus_, "nucleus");
    addGroup(2, cytoplasm_, "cytoplasm");
    addGroup(2, membrane_, "membrane");
    addGroup(1, bottom_, "fixedBottom");
    addGroup(1, axis_, "axis");
    addGroup(1, outer_, "outerSurface");
}


void Foam::cellMesher::physicalGroups3D() const
{
    addGroup(3, nucleus3_, "nucleus");
    addGroup(3, cytoplasm3_, "cytoplasm");
    addGroup(3, membrane3_, "membrane");

    // Classify the boundary of the whole cell by its planes
    gmsh::vectorpair all, bnd;
    for (const auto* r : {&nucleus3_, &cytoplasm3_, &membrane3_})
    {
        for (const int v : *r) all.push_back({3, v});
    }
    gmsh::model::getBoundary(all, bnd, true, false, false);
    const scalar tol = 1e-6*geom_.t()/L_;
    std::vector<int> bottom, symX, symY, outer;
    for (const auto& dt : bnd)
    {
        const int s = std::abs(dt.second);
        double x0, y0, z0, x1, y1, z1;
        gmsh::model::getBoundingBox(2, s, x0, y0, z0, x1, y1, z1);
        if (mag(z1) < tol && mag(z0) < tol) bottom.push_back(s);
        else if (mag(x1) < tol && mag(x0) < tol) symX.push_back(s);
        else if (mag(y1) < tol && mag(y0) < tol) symY.push_back(s);
        else outer.push_back(s);
    }
    addGroup(2, bottom, "fixedBottom");
    addGroup(2, outer, "outerSurface");
    if (geom_.mode() == cellGeometry::meshMode::quarter3D)
    {
        addGroup(2, symX, "symmetryX");
        addGroup(2, symY, "symmetryY");
    }
    else if (symX.size() || symY.size())
    {
        FatalErrorInFunction
            << "The full 3D cell has " << symX.size() + symY.size()
            << " boundary surfaces on a coordinate plane" << exit(FatalError);
    }
}


Foam::cellMesher::cellMesher(const cellGeometry& geom)
:
    geom_(geom),
    nucleusAxis_(-1),
    cytoplasmBottom_(-1)
{
    gmsh::model::add("cell");
    buildSection();
    if (geom_.axisymmetric())
    {
        physicalGroups2D();
    }
    else
    {
        revolve();
        physicalGroups3D();
    }
    sizeFields();
}


void Foam::cellMesher::generate()
{
    const bool axi = geom_.axisymmetric();
    if (axi)
    {
        // Frontal-Delaunay for quads (algorithm 8) crashes in gmsh 4.8 with
        // a background size field; Blossom on the other triangulations
        // occasionally leaves a pair of triangles, so try them in turn
        gmsh::option::setNumber("Mesh.RecombineAll", 1);
        gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);
        fixParity();
        const std::vector<std::pair<int, int>> attempts
        {
            {6, 1}, {5, 1}, {1, 1}, {6, 0}, {5, 0}, {1, 0}
        };
        for (const auto& alg : attempts)
        {
            gmsh::option::setNumber("Mesh.Algorithm", alg.first);
            gmsh::option::setNumber
            (
                "Mesh.MeshSizeExtendFromBoundary", alg.second
            );
            gmsh::model::mesh::generate(2);
            if (nonQuadrilaterals() == 0)
            {
                Info<< "All quadrilaterals with gmsh 2D algorithm "
                    << alg.first << ", MeshSizeExtendFromBoundary "
                    << alg.second << nl << endl;
                break;
            }
            gmsh::vectorpair surfaces;
            gmsh::model::getEntities(surfaces, 2);
            gmsh::model::mesh::clear(surfaces);
        }
    }
    else
    {
        gmsh::option::setNumber("Mesh.Algorithm", 6);
        gmsh::option::setNumber("Mesh.Algorithm3D", 1);
        gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 2);
        gmsh::model::mesh::generate(3);
    }

    const int dim = axi ? 2 : 3;
    const meshQuality q(dim, L_);
    q.write(Info);
    for (const auto& s : q.regions())
    {
        if (s.nOtherType)
        {
            FatalErrorInFunction
                << s.nOtherType << " elements that are not "
                << (axi ? "quadrilaterals" : "hexahedra")
                << " remain in region " << s.name
                << " (nothing written)" << exit(FatalError);
        }
        if (!(s.minScaledJacobian > 0))
        {
            FatalErrorInFunction
                << "Inverted element in region " << s.name
                << " (minimum scaled Jacobian " << s.minScaledJacobian
                << ", nothing written)" << exit(FatalError);
        }
    }

    // Against the exact measures (the mesh is inscribed: polygonal
    // boundaries, so its area/volume is slightly smaller)
    const scalar share = geom_.mode() == cellGeometry::meshMode::quarter3D
        ? 0.25 : 1;
    const scalar exactNuc = axi ? geom_.nucleusArea() : geom_.nucleusVolume();
    const scalar exactIn = axi ? geom_.innerArea() : geom_.innerVolume();
    const scalar exactCell = axi ? geom_.cellArea() : geom_.cellVolume();
    Info<< nl << "Geometry against the exact " << (axi ? "section area [m^2]"
        : "volume [m^3]") << nl;
    for (const auto& s : q.regions())
    {
        const scalar exact = share*
        (
            s.name == "nucleus" ? exactNuc
          : s.name == "cytoplasm" ? exactIn - exactNuc
          : exactCell - exactIn
        );
        Info<< "    " << s.name << "  mesh " << s.measure << "  exact "
            << exact << "  relative error " << (s.measure - exact)/exact
            << nl;
    }
    const auto tot = q.total();
    Info<< "    cell  mesh " << tot.measure << "  exact " << share*exactCell
        << "  relative error "
        << (tot.measure - share*exactCell)/(share*exactCell) << nl;
    if (axi)
    {
        const scalar V = geom_.cellVolume();
        Info<< "    revolved cell volume [m^3]  mesh " << tot.revolved
            << "  exact " << V << "  relative error "
            << (tot.revolved - V)/V << nl;
    }
    scalar nucMesh = 0;
    for (const auto& s : q.regions())
    {
        if (s.name == "nucleus") nucMesh = axi ? s.revolved : s.measure;
    }
    Info<< "    nucleus volume fraction  mesh "
        << nucMesh/(axi ? tot.revolved : tot.measure)
        << "  requested " << geom_.nucleusFraction() << nl
        << "    nucleus diameter " << 2*geom_.an() << " m, height "
        << 2*geom_.cn() << " m, centre z " << geom_.zn()
        << " m, smallest gap to the membrane " << geom_.gap() << " m" << nl
        << "    membrane thickness " << geom_.t() << " m, "
        << geom_.layers() << " element layers (2D)" << nl << endl;
}


void Foam::cellMesher::write(const fileName& file) const
{
    mkDir(file.path());
    const fileName tmp(file.path()/"." + file.nameLessExt() + "-tmp.msh");
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    gmsh::option::setNumber("Mesh.ScalingFactor", L_);
    gmsh::write(tmp);
    if (!Foam::mv(tmp, file))
    {
        FatalErrorInFunction
            << "Cannot move " << tmp << " to " << file << exit(FatalError);
    }
    Info<< "Written " << file << " (gmsh 4.1, coordinates in m)" << endl;
}
