#include "cellMesher.H"
#include "meshQuality.H"
#include "structuredCell.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include "mshFile.H"
#include "OStringStream.H"
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
    return geo::addPoint(p.first()/L_, p.second()/L_, 0);
}


int Foam::cellMesher::surface(const std::vector<int>& curves) const
{
    return geo::addPlaneSurface({geo::addCurveLoop(curves)});
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
        radial[k] = geo::addLine(outerPt[k], innerPt[k]);
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
            geo::addEllipseArc(outerPt[k], origin, major, outerPt[k + 1])
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
        innerCurve[k] = geo::addSpline(pts);
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

    const scalar an = geom_.an(), cn = geom_.cn(), zn = geom_.zn();
    if (geom_.scaledNucleus())
    {
        // Nucleus: quarter ellipse on the substrate and the axis
        const int n1 = point(rz(an, 0));
        const int n2 = point(rz(0, cn));
        const int arc =
            geo::addEllipseArc(n1, origin, an >= cn ? n1 : n2, n2);
        const int nucleusBottom = geo::addLine(origin, n1);
        nucleusAxis_ = geo::addLine(n2, origin);
        nucleus_.push_back(surface({nucleusBottom, arc, nucleusAxis_}));

        // Cytoplasm: between substrate, membrane, axis and nucleus
        cytoplasmBottom_ = geo::addLine(n1, innerPt[N]);
        const int axisTop = geo::addLine(innerPt[0], n2);
        std::vector<int> loop{cytoplasmBottom_};
        for (label k = N - 1; k >= 0; --k) loop.push_back(-innerCurve[k]);
        loop.insert(loop.end(), {axisTop, -arc});
        cytoplasm_.push_back(surface(loop));

        bottom_ = {nucleusBottom, cytoplasmBottom_, radial[N]};
        axis_ = {nucleusAxis_, axisTop, radial[0]};
    }
    else
    {
        // Nucleus: half ellipse on the axis, centred at mid-height
        const int n0 = point(rz(0, zn - cn));
        const int n1 = point(rz(an, zn));
        const int n2 = point(rz(0, zn + cn));
        const int nc = point(rz(0, zn));
        const int nMajor = an >= cn ? n1 : n2;
        const int arc1 = geo::addEllipseArc(n0, nc, nMajor, n1);
        const int arc2 = geo::addEllipseArc(n1, nc, nMajor, n2);
        nucleusAxis_ = geo::addLine(n2, n0);
        nucleus_.push_back(surface({arc1, arc2, nucleusAxis_}));

        // Cytoplasm: between substrate, membrane, axis and nucleus
        cytoplasmBottom_ = geo::addLine(origin, innerPt[N]);
        const int axisTop = geo::addLine(innerPt[0], n2);
        const int axisBottom = geo::addLine(n0, origin);
        std::vector<int> loop{cytoplasmBottom_};
        for (label k = N - 1; k >= 0; --k) loop.push_back(-innerCurve[k]);
        loop.insert(loop.end(), {axisTop, -arc2, -arc1, axisBottom});
        cytoplasm_.push_back(surface(loop));

        bottom_ = {cytoplasmBottom_, radial[N]};
        axis_ = {axisBottom, nucleusAxis_, axisTop, radial[0]};
    }

    geo::synchronize();
    {
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


void Foam::cellMesher::sizeFields() const
{
    namespace field = gmsh::model::mesh::field;
    std::vector<double> fields
    {
        double(restrictedSize(2, nucleus_, geom_.nucleusSize()/L_)),
        double(restrictedSize(2, cytoplasm_, geom_.cytoplasmSize()/L_))
    };

    if (geom_.contactRadius() > 0)
    {
        // contactSize in r <= contactRadius, z >= z_s(contactRadius) -
        // contactDepth; growing linearly to the largest size over another
        // contactDepth
        const scalar hFar = max
        (
            geom_.membraneSize(),
            max(geom_.nucleusSize(), geom_.cytoplasmSize())
        )/L_;
        const scalar hc = geom_.contactSize()/L_;
        const scalar zLow =
            (geom_.outer(geom_.thetaContact()).second() - geom_.contactDepth())
           /L_;
        std::ostringstream os;
        os.precision(17);
        // the sign written out: a contactSize above the far size made
        // "+ -0.5*..." that gmsh's MathEval cannot parse, an exception
        // thrown where nothing catches it, SIGABRT (adv33 cm16)
        os  << hc << (hFar < hc ? " - " : " + ") << mag(hFar - hc)
            << "*min(1, max(0, max(x - "
            << geom_.contactRadius()/L_ << ", " << zLow << " - y))/"
            << geom_.contactDepth()/L_ << ")";
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


namespace
{

void smoothingInfo(const Foam::structuredCell& cell)
{
    using namespace Foam;
    if (cell.smoothSweeps() == 0) return;
    Info<< "structuredSmoothing elliptic: " << cell.smoothFree()
        << " interior nodes smoothed, " << cell.smoothSliding() << " of them"
        << " sliding on the nucleus surface, " << cell.smoothBoundary()
        << " along the substrate or the axis; " << cell.smoothSweeps() << " sweeps, the last "
        << "moving a node by at most " << cell.smoothLastMove() << " m" << nl;
}


// The structured mesh's element count against maxElements, before anything
// is written: its blocks' counts couple across the regions (a fine
// membrane refines the blocks beside it), so the bound checked from the
// sizes before meshing can be far below it (adv49b i55: 3931
// quadrilaterals written with maxElements 982, nothing said)
void checkStructuredCount
(
    const Foam::cellGeometry& geom,
    const std::size_t n,
    const char* what
)
{
    using namespace Foam;
    if (label(n) <= geom.maxElements())
    {
        return;
    }
    FatalErrorInFunction
        << "the structured mesh (meshType structured) has " << label(n)
        << " " << what << ", more than maxElements " << geom.maxElements()
        << " (" << geom.file().c_str() << ")"
        << ": its blocks' counts couple across the regions (a fine "
        << "membraneSize refines the blocks beside the membrane), so the "
        << "count from the sizes checked before meshing was lower "
        << "(nucleusSize "
        << geom.nucleusSize() << " m, cytoplasmSize " << geom.cytoplasmSize()
        << " m, membraneSize " << geom.membraneSize() << " m)." << nl
        << "    Nothing was written: larger sizes, or a larger maxElements "
        << "if that many is meant" << exit(FatalError);
}

} // End anonymous namespace


Foam::cellMesher::cellMesher(const cellGeometry& geom)
:
    geom_(geom),
    nucleusAxis_(-1),
    cytoplasmBottom_(-1)
{
    gmsh::model::add("cell");
    if (geom_.axisymmetric() && !geom_.structured())
    {
        buildSection();
        physicalGroups2D();
        sizeFields();
    }
    else if (geom_.axisymmetric())
    {
        const structuredCell cell(geom_);
        checkStructuredCount(geom_, cell.quads().size(), "quadrilaterals");
        cell.toGmsh(L_);
        Info<< "Structured r-z section (meshType structured): quadrilaterals "
            << cell.quads().size() << ", nodes " << cell.nodes().size()
            << ", column r <= " << 0.5*geom_.an() << " m in "
            << cell.nColumn() << " radial elements; boundary edges:";
        for (const auto& kv : cell.edges())
        {
            Info<< " " << kv.first.c_str() << " " << kv.second.size();
        }
        Info<< nl << "Interior nodes by elements sharing them:";
        for (const auto& kv : cell.interiorValences())
        {
            Info<< " " << kv.first << ": " << kv.second;
        }
        Info<< nl;
        smoothingInfo(cell);
        if (geom_.contactRadius() > 0)
        {
            Info<< "contactRadius, contactSize, contactDepth are not used by"
                << " the structured section (no local refinement; sizes "
                << "nucleusSize, cytoplasmSize, membraneSize)" << nl;
        }
        Info<< endl;
    }
    else
    {
        const structuredCell cell(geom_);
        checkStructuredCount(geom_, cell.hexes().size(), "hexahedra");
        cell.toGmsh(L_);
        Info<< "Structured hexahedra: " << cell.hexes().size() << ", nodes "
            << cell.nodes().size() << "; boundary faces:";
        for (const auto& kv : cell.faces())
        {
            Info<< " " << kv.first.c_str() << " " << kv.second.size();
        }
        Info<< nl;
        smoothingInfo(cell);
        Info<< endl;
    }
}


void Foam::cellMesher::generate()
{
    const bool axi = geom_.axisymmetric();
    if (axi && !geom_.structured())
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
        << "    nucleus (" << cellGeometry::nucleusShapeNames[geom_.shape()]
        << ") diameter " << 2*geom_.an() << " m, height "
        << geom_.nucleusHeight() << " m, centre z " << geom_.zn()
        << " m, smallest gap to the membrane " << geom_.gap() << " m" << nl
        << "    membrane thickness " << geom_.t() << " m, "
        << geom_.layers() << " element layers" << nl << endl;
}


Foam::fileName Foam::cellMesher::writeTemporary(const fileName& file) const
{
    // gmsh can end without error but without elements for some sizes:
    // never write (or replace a good mesh with) an empty one
    std::size_t nElements = 0;
    for (const int dim : {2, 3})
    {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, dim);
        for (const auto& t : tags) nElements += t.size();
    }
    if (nElements == 0)
    {
        // the entries named with their values (adv32 cm17: membraneSize
        // 1e-8 m, "these sizes" named none). gmsh's quadrilateral mesher
        // fails without a message for some neighbouring sizes: measured
        // (fix19k, tests/badInput/cellMeshDict) membraneSize 2e-7 m or less
        // next to contactSize 4e-7 m fails, 3e-7 m meshes, and 2e-7 m
        // meshes with contactSize 2e-7 m
        OStringStream contact;
        if (geom_.contactRadius() > 0)
        {
            contact << ", contactSize " << geom_.contactSize() << " m";
        }
        FatalErrorInFunction
            << "gmsh produced no elements for the sizes of "
            << "system/cellMeshDict: entries nucleusSize "
            << geom_.nucleusSize() << " m, cytoplasmSize "
            << geom_.cytoplasmSize() << " m, membraneSize "
            << geom_.membraneSize() << " m" << contact.str().c_str()
            << " (membraneThickness " << geom_.t() << " m, membraneLayers "
            << geom_.layers() << "); " << file << " is not written." << nl
            << "    gmsh fails so when neighbouring sizes differ much (a "
            << "membraneSize below the contactSize or far below the "
            << "cytoplasmSize): bring them closer" << exit(FatalError);
    }

    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    gmsh::option::setNumber("Mesh.ScalingFactor", L_);
    return mshFile::writeTemporary(file);
}
