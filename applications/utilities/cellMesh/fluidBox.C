#include "fluidBox.H"
#include "inputChecks.H"
#include "keywordCheck.H"
#include "meshQuality.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include "mshFile.H"
#include "vector.H"
#include <gmsh.h>
#include <cfenv>
#include <cmath>
#include <map>
#include <sstream>

using Foam::constant::mathematical::pi;

Foam::fluidBox::fluidBox(const cellGeometry& geom)
:
    g_(geom)
{
    const dictionary& d = g_.fluidDict();
    // The hexahedral water's entries given outside hexCoeffs: said so
    // before the keyword check would call them unknown (maxCells, an entry
    // of fluid for the tetrahedra and the wedge, is checked below)
    for (const word key : {"axialSize", "lateralSize", "innerMargin"})
    {
        if (d.found(key))
        {
            FatalIOErrorInEntry(d, key)
                << "entry '" << key << "' belongs in the sub-dictionary "
                << "hexCoeffs (type hex)" << exit(FatalIOError);
        }
    }
    // hexCoeffs is read with type hex only, and kept with tetrahedra: the
    // 3D tutorial's Allrun -tet switches the type alone
    foamTools::checkKeywords
    (
        d,
        {
            "boxSize", "height", "nearSize", "farSize", "growthDistance",
            "wedgeAngle", "type", "columnSize", "columnRadius", "hexCoeffs",
            "maxCells"
        }
    );
    L_ = foamTools::readInRangeOrDefault<scalar>
    (
        d, "boxSize", "m", max(2*g_.a(), g_.H()), 1e-2, false, 1e-4
    );
    nearSize_ = foamTools::readInRange<scalar>
    (
        d, "nearSize", "m", 0, g_.H(), false
    );
    farSize_ = foamTools::readInRange<scalar>
    (
        d, "farSize", "m", nearSize_, 0.25*L_, true
    );
    // At least one near cell (1e-250 m was accepted; adv pass cm18)
    growth_ = foamTools::readInRange<scalar>
    (
        d, "growthDistance", "m", nearSize_, L_, true
    );
    // The wedge's angle is the axisymmetric mode's: in 3D it was accepted
    // and ignored without a word (adv30 cm09)
    if (d.found("wedgeAngle") && !g_.axisymmetric())
    {
        FatalIOErrorInEntry(d, "wedgeAngle")
            << "entry 'wedgeAngle' is available in the axisymmetric mode "
            << "only: the 3D modes (quarter3D, full3D) mesh no wedge"
            << exit(FatalIOError);
    }
    // [0.01, 10] deg: 1e-250 deg was accepted, a wedge of cells of no
    // volume (adv pass cm18); OpenFOAM's wedge is meant for a few degrees
    wedge_ = foamTools::readInRangeOrDefault<scalar>
    (
        d, "wedgeAngle", "deg", 0.01, 10, true, 5
    )*pi/180;

    // Cell type (3D): tetrahedra (the default) or hex, whose entries are
    // in the sub-dictionary hexCoeffs (ignored with tetrahedra, as
    // OpenFOAM's <type>Coeffs: a case can switch the type alone)
    const word type = d.getOrDefault<word>("type", "tetrahedra");
    if (d.found("type") && g_.axisymmetric())
    {
        FatalIOErrorInFunction(d)
            << "type " << type << ": the cell type is chosen in the 3D "
            << "modes (quarter3D, full3D) only; the axisymmetric wedge is "
            << "a structured grid" << exit(FatalIOError);
    }
    if (type != "tetrahedra" && type != "hex")
    {
        FatalIOErrorInEntry(d, "type")
            << "entry 'type' = " << type << " is not a water cell type; "
            << "valid: tetrahedra hex" << exit(FatalIOError);
    }
    for (const word key : {"axialSize", "lateralSize", "innerMargin",
                           "maxCells"})
    {
        // maxCells of the tetrahedra and the wedge is an entry of fluid
        if (d.found(key) && (key != "maxCells" || type == "hex"))
        {
            FatalIOErrorInEntry(d, key)
                << "entry '" << key << "' belongs in the sub-dictionary "
                << "hexCoeffs (type hex)" << exit(FatalIOError);
        }
    }

    // Optional column: both entries or neither
    columnSize_ = 0;
    columnRadius_ = 0;
    const bool hasSize = d.found("columnSize");
    const bool hasRadius = d.found("columnRadius");
    if ((hasSize || hasRadius) && type == "hex")
    {
        FatalIOErrorInFunction(d)
            << (hasSize ? "columnSize" : "columnRadius")
            << " belongs to type tetrahedra: the hexahedral water has "
            << "axialSize along the whole column" << exit(FatalIOError);
    }
    if (hasSize || hasRadius)
    {
        if (g_.axisymmetric())
        {
            FatalIOErrorInFunction(d)
                << (hasSize ? "columnSize" : "columnRadius")
                << " is available in the 3D modes (quarter3D, full3D) only: "
                << "the axisymmetric wedge is a structured grid"
                << exit(FatalIOError);
        }
        if (!hasSize || !hasRadius)
        {
            FatalIOErrorInFunction(d)
                << (hasSize ? "columnRadius" : "columnSize")
                << " is missing: columnSize and columnRadius define the "
                << "refined column together (give both, or neither for no "
                << "column)" << exit(FatalIOError);
        }
        columnSize_ = foamTools::readInRange<scalar>
        (
            d, "columnSize", "m", 0, farSize_, false
        );
        columnRadius_ = foamTools::readInRange<scalar>
        (
            d, "columnRadius", "m", 0, 0.5*L_, false
        );
    }
    // The top of the water: boxSize, or lower for a column shortened by
    // an inflow top (3D only; the hexahedral water checks it against its
    // inner box in readHex)
    height_ = L_;
    if (d.found("height") && g_.axisymmetric())
    {
        FatalIOErrorInEntry(d, "height")
            << "entry 'height' is available in the 3D modes (quarter3D, "
            << "full3D) only: the axisymmetric wedge fills the box"
            << exit(FatalIOError);
    }
    if (type == "hex")
    {
        readHex(d.subOrEmptyDict("hexCoeffs"));
    }
    else
    {
        // kept by design (a case switches the type alone), but said: its
        // entries do not shape these tetrahedra (adv50b k10 (a): oGrid
        // orthogonal meshed as tetrahedra without a word)
        if (const dictionary* h = d.findDict("hexCoeffs", keyType::LITERAL))
        {
            std::string keys;
            for (const entry& e : *h)
            {
                keys += (keys.empty() ? "" : " ") + std::string(e.keyword());
            }
            Info<< "Note: fluid type " << type << ": the sub-dictionary "
                << "hexCoeffs (" << keys.c_str() << ") is not used; it "
                << "shapes the water of type hex only" << nl << endl;
        }
        if (d.found("height"))
        {
            // The tetrahedra: at least one farSize of water above the cell
            height_ = readHeight(g_.H() + farSize_, "the cell's top "
                "(cellHeight) plus one farSize");
        }
        // The tetrahedra and the wedge: their cell count estimated from
        // the sizes before gmsh allocates anything (issue 19, class 6)
        const label maxCells = foamTools::readInRangeOrDefault<label>
        (
            d, "maxCells", "", 1, 1000000000, true, 1000000
        );
        const bool tets = !g_.axisymmetric();
        const scalar estimate = tets ? tetCells() : wedgeCells();
        Info<< "Water: " << (tets ? "about " : "at least ") << estimate
            << (tets ? " tetrahedra" : " cells") << " estimated from the "
            << "sizes (maxCells " << maxCells << ")" << nl << endl;
        if (estimate > maxCells)
        {
            FatalIOErrorInFunction(d)
                << "the " << (tets ? "tetrahedral" : "wedge") << " water "
                << "would have " << (tets ? "about " : "at least ")
                << estimate << " cells" << (tets ? " (estimated from the "
                   "sizes)" : "") << ", more "
                << "than maxCells " << maxCells << " (coarser nearSize, "
                << "farSize" << (tets ? ", columnSize" : "") << " or a "
                << "longer growthDistance, or a larger maxCells)"
                << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::fluidBox::sizeAt(scalar r, scalar z) const
{
    const scalar a = g_.a(), H = g_.H();
    const scalar level = std::sqrt(sqr(r/a) + sqr(z/H)) - 1;
    scalar h = nearSize_ + (farSize_ - nearSize_)
        *min(1.0, max(0.0, level*min(a, H)/growth_));
    if (columnRadius_ > 0)
    {
        h = min
        (
            h,
            columnSize_ + (farSize_ - columnSize_)
           *min(1.0, max(0.0, r - columnRadius_)/growth_)
        );
    }
    return h;
}


Foam::scalar Foam::fluidBox::tetCells() const
{
    // The water's volume over that of a regular tetrahedron of the local
    // size, h^3/(6 sqrt 2), summed on a grid over the quarter box, or the
    // layer on the cell alone if that is more (below)
    // [0, L/2]^2 x [0, L] (midpoints; at least 8 points per growth
    // distance and column radius, at most 200 x 200 x 400). An estimate,
    // not a bound: gmsh made 0.6 to 1.7 times as many on the quarter
    // (docs/reliability.md, class 6)
    const scalar a = g_.a(), H = g_.H(), half = 0.5*L_;
    scalar resolve = min(growth_, min(a, H));
    if (columnRadius_ > 0) resolve = min(resolve, columnRadius_);
    const label n = min(label(200), max(label(32),
        label(std::ceil(8*half/resolve))));
    const scalar dx = half/n, dz = height_/(2*n);
    scalar sum = 0;
    for (label i = 0; i < n; ++i)
    for (label j = 0; j < n; ++j)
    {
        const scalar r = std::hypot((i + 0.5)*dx, (j + 0.5)*dx);
        for (label k = 0; k < 2*n; ++k)
        {
            const scalar z = (k + 0.5)*dz;
            if (sqr(r/a) + sqr(z/H) < 1) continue;
            sum += 1/pow3(sizeAt(r, z));
        }
    }
    const bool quarter = g_.mode() == cellGeometry::meshMode::quarter3D;
    const scalar tet = 6*std::sqrt(2.0);
    const scalar grid = (quarter ? 1 : 4)*tet*sum*dx*dx*dz;

    // The layer on the cell, where the size grows from nearSize: thinner
    // than the grid for a small nearSize, summed across it exactly, on
    // the cell's surface (upper half spheroid, a quarter of it in the
    // quarter mode): integral of 1/h^3 over the growth distance
    scalar area = 0;
    for (label i = 0; i < 1000; ++i)
    {
        const scalar phi = 0.5*pi*(i + 0.5)/1000;
        area += 2*pi*a*std::sin(phi)
           *std::hypot(a*std::cos(phi), H*std::sin(phi))*0.5*pi/1000;
    }
    const scalar n0 = nearSize_, n1 = farSize_;
    const scalar layer = n1 > n0*(1 + 1e-12)
        ? growth_/(n1 - n0)*0.5*(1/sqr(n0) - 1/sqr(n1))
        : growth_/pow3(n0);
    const scalar shell = (quarter ? 0.25 : 1)*tet*area*layer;
    return max(grid, shell);
}


Foam::scalar Foam::fluidBox::wedgeCells() const
{
    // wedge(): nTh rays (nearSize along the cell surface, at most farSize
    // at the box), each with at least (longest ray)/farSize cells
    const scalar L = L_, a = g_.a(), H = g_.H();
    const scalar thc = std::atan2(0.5*L, L);
    scalar Dmax = 0;
    for (label i = 0; i <= 1000; ++i)
    {
        const scalar th = 0.5*pi*i/1000;
        const scalar rhoE =
            1/std::sqrt(sqr(std::sin(th)/a) + sqr(std::cos(th)/H));
        const scalar rhoB =
            th <= thc ? L/std::cos(th) : 0.5*L/std::max(std::sin(th), 1e-300);
        Dmax = max(Dmax, rhoB - rhoE);
    }
    const scalar nTh = max
    (
        std::ceil(g_.arcLength(0, 0.5*pi, false)/nearSize_),
        std::ceil(0.5*pi*std::hypot(0.5*L, L)/farSize_)
    );
    return nTh*std::floor(Dmax/farSize_);
}


void Foam::fluidBox::readHex(const dictionary& d)
{
    if (d.empty())
    {
        FatalIOErrorInFunction(g_.fluidDict())
            << "type hex needs the sub-dictionary hexCoeffs (axialSize and "
            << "the optional lateralSize, innerMargin, topRounding, oGrid, "
            << "maxCells)"
            << exit(FatalIOError);
    }
    foamTools::checkKeywords
    (
        d, {"axialSize", "lateralSize", "innerMargin", "topRounding",
            "oGrid", "maxCells"}
    );
    const scalar a = g_.a(), H = g_.H();
    hexFluidMesh::sizes s;
    s.a = a;
    s.H = H;
    s.L = L_;
    s.quarter = g_.mode() == cellGeometry::meshMode::quarter3D;
    s.nearSize = nearSize_;
    s.farSize = farSize_;
    s.growth = growth_;
    s.axialSize = foamTools::readInRange<scalar>
    (
        d, "axialSize", "m", 0, farSize_, false
    );
    s.lateralSize = foamTools::readInRangeOrDefault<scalar>
    (
        d, "lateralSize", "m", 0, farSize_, false, nearSize_
    );
    // The first layer at the cell (nearSize thick) against the grid along
    // the cell (lateralSize, axialSize): at most maxAspectRatio times
    // thinner. A thinner one is a layer of needles whose time step is that
    // much shorter (issue 19, adv28 m12: nearSize 1e-15 m meshed with an
    // aspect ratio of 1.2e9, exit 0)
    const scalar maxAspectRatio = 1000;
    const scalar nearMin = min(s.lateralSize, s.axialSize)/maxAspectRatio;
    if (!(nearSize_ >= nearMin))
    {
        FatalIOErrorInEntry(g_.fluidDict(), "nearSize")
            << "entry 'nearSize' = " << nearSize_ << " m is outside the"
            << " valid range [" << nearMin << ", " << H << "] m with type"
            << " hex: the first layer at the cell would be "
            << min(s.lateralSize, s.axialSize)/nearSize_ << " times thinner"
            << " than the grid along the cell (lateralSize "
            << s.lateralSize << " m, axialSize " << s.axialSize << " m; at"
            << " most " << maxAspectRatio << "), and the fluid's time step"
            << " as much shorter" << exit(FatalIOError);
    }
    // The inner box holds the cell with at least one first layer around
    // it and leaves water between it and the side walls and the box's top
    // (the water's top, height, is checked against the inner box below)
    const scalar gap = min(0.5*L_ - a, L_ - H);
    if (gap <= nearSize_)
    {
        FatalIOErrorInEntry(d, "boxSize")
            << "boxSize " << L_ << " m leaves " << gap << " m between the "
            << "cell and the box, not more than nearSize " << nearSize_
            << " m: no room for the inner box of the hexahedral water"
            << exit(FatalIOError);
    }
    s.margin = foamTools::readInRangeOrDefault<scalar>
    (
        d, "innerMargin", "m", nearSize_, gap*(1 - 1e-12), true,
        0.5*min(a, H)
    );
    if (g_.fluidDict().found("height"))
    {
        // At least one axialSize of tensor grid above the inner box
        height_ = readHeight(H + s.margin + s.axialSize, "the top of the "
            "inner box (cellHeight + innerMargin) plus one axialSize");
    }
    s.height = height_;
    // The inner box's top edges rounded (hexFluidMesh): the superellipse's
    // exponent; without the entry the sharp box. Below 5 the grid beyond
    // the box's corner folds (docs/results/blast3D.md, "An O-grid without
    // the kink")
    if (d.found("topRounding"))
    {
        s.topRounding = foamTools::readInRange<scalar>
        (
            d, "topRounding", "", 5, 100, true
        );
    }
    // The O-grid's rays straight (default), or the O-grid and the tensor
    // grid around it moved for face orthogonality (hexFluidMesh::
    // orthogonalise; docs/results/blast3D.md, "An orthogonal O-grid")
    {
        enum class oGridType { straight, orthogonal };
        static const Enum<oGridType> oGridNames
        ({
            {oGridType::straight, "straight"},
            {oGridType::orthogonal, "orthogonal"}
        });
        s.orthogonal = foamTools::readEnumOrDefault
        (
            oGridNames, d, "oGrid", oGridType::straight
        ) == oGridType::orthogonal;
    }
    const label maxCells = foamTools::readInRangeOrDefault<label>
    (
        d, "maxCells", "", 1, 1000000000, true, 1000000
    );
    // A lower bound first, the column above the inner box alone: a tiny
    // size must be refused before its grid lines are allocated
    // (with the traps held: sizes of 1e-200 m overflow it, adv50a k11's
    // class; beyond a double it is any count above maxCells)
    scalar lower = 0;
    {
        std::fenv_t env;
        std::feholdexcept(&env);
        lower = (s.quarter ? 1 : 4)*sqr((a + s.margin)/s.lateralSize)
            *(height_ - H - s.margin)/s.axialSize;
        std::feclearexcept(FE_ALL_EXCEPT);
        std::fesetenv(&env);
        if (!std::isfinite(lower))
        {
            lower = 1e300;
        }
    }
    if (lower > maxCells)
    {
        // the least whole count, placed at maxCells' own file and line
        // when given (adv50b k46: "at least 11073.1 cells", placed at
        // cellMeshDict.fluid.hexCoeffs)
        fileName file;
        label line = 0;
        const bool placed =
            foamTools::keywordCheckDetail::entryPlace
            (
                d, "maxCells", file, line
            );
        (
            placed
          ? FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file, line)
          : FatalIOErrorInEntry(d, "axialSize")
        )
            << "the hexahedral water would have at least "
            << foamTools::countAboveText(std::ceil(lower), maxCells).c_str()
            << " cells, more than maxCells " << maxCells << " (coarser "
            << "axialSize, lateralSize or farSize, or a larger maxCells)"
            << exit(FatalIOError);
    }
    hex_.reset(new hexFluidMesh(s));
    if (hex_->nCells() > maxCells)
    {
        FatalIOErrorInEntry(d, word(d.found("maxCells") ? "maxCells" : "axialSize"))
            << "the hexahedral water would have "
            << scalar(hex_->nCells())
            << " cells, more than maxCells " << maxCells << " (coarser "
            << "axialSize, lateralSize or farSize, or a larger maxCells)"
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::fluidBox::readHeight
(
    const scalar lo,
    const char* lowerBound
) const
{
    const dictionary& d = g_.fluidDict();
    // One finite number first (a word, a list, nan: readInRange's
    // message), then the range with its meaning
    const scalar inf = foamTools::noUpperBound<scalar>();
    const scalar Z = foamTools::readInRange<scalar>
    (
        d, "height", "m", -inf, inf, true
    );
    if (!(Z > lo && Z <= L_))
    {
        FatalIOErrorInEntry(d, "height")
            << "entry 'height' = " << foamTools::numberText(Z).c_str()
            << " m is outside the valid range "
            << foamTools::rangeText(lo, L_, false, foamTools::numberText(Z))
               .c_str()
            << " m: above " << lowerBound << " ("
            << lo << " m), at most boxSize (" << L_ << " m)"
            << exit(FatalIOError);
    }
    return Z;
}


void Foam::fluidBox::sizeField() const
{
    namespace field = gmsh::model::mesh::field;
    // Distance from the spheroid through its level function
    // (sqrt((r/a)^2 + (z/H)^2) - 1) min(a, H): exact on the axes, smaller
    // elsewhere (finer, never coarser)
    const scalar a = g_.a()/unit_, H = g_.H()/unit_;
    std::ostringstream os;
    os.precision(17);
    os  << nearSize_/unit_ << " + " << (farSize_ - nearSize_)/unit_
        << "*min(1, max(0, (sqrt((x*x + y*y)/" << a*a << " + z*z/" << H*H
        << ") - 1)*" << min(a, H) << "/" << growth_/unit_ << "))";
    const int f = field::add("MathEval");
    field::setString(f, "F", os.str());
    if (columnRadius_ > 0)
    {
        // The column: columnSize within columnRadius of the axis
        // x = y = 0, growing linearly to farSize over growthDistance
        // outside it; the size is the smaller of the two fields
        std::ostringstream oc;
        oc.precision(17);
        oc  << columnSize_/unit_ << " + " << (farSize_ - columnSize_)/unit_
            << "*min(1, max(0, sqrt(x*x + y*y) - " << columnRadius_/unit_
            << ")/" << growth_/unit_ << ")";
        const int c = field::add("MathEval");
        field::setString(c, "F", oc.str());
        const int m = field::add("Min");
        field::setNumbers(m, "FieldsList", {double(f), double(c)});
        field::setAsBackgroundMesh(m);
    }
    else
    {
        field::setAsBackgroundMesh(f);
    }
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.RecombineAll", 0);
    gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 0);
}


void Foam::fluidBox::addGroup
(
    int dim,
    const std::vector<int>& tags,
    const std::string& name
) const
{
    if (tags.empty())
    {
        FatalErrorInFunction
            << "Fluid patch " << name << " is empty" << exit(FatalError);
    }
    const int g = gmsh::model::addPhysicalGroup(dim, tags);
    gmsh::model::setPhysicalName(dim, g, name);
}


void Foam::fluidBox::box3D()
{
    namespace occ = gmsh::model::occ;
    const bool quarter = g_.mode() == cellGeometry::meshMode::quarter3D;
    const scalar L = L_/unit_, x0 = quarter ? 0 : -0.5*L;
    const scalar Z = height_/unit_;
    const int box = occ::addBox(x0, x0, 0, 0.5*L - x0, 0.5*L - x0, Z);
    const int cell = occ::addSphere(0, 0, 0, 1);
    occ::dilate({{3, cell}}, 0, 0, 0, g_.a()/unit_, g_.a()/unit_, g_.H()/unit_);
    gmsh::vectorpair out;
    std::vector<gmsh::vectorpair> map;
    occ::cut({{3, box}}, {{3, cell}}, out, map);
    occ::synchronize();
    if (out.size() != 1 || out[0].first != 3)
    {
        FatalErrorInFunction
            << "The box minus the cell is not one volume" << exit(FatalError);
    }
    addGroup(3, {out[0].second}, "water");

    gmsh::vectorpair bnd;
    gmsh::model::getBoundary(out, bnd, true, false, false);
    const scalar tol = 1e-6*L;
    std::map<std::string, std::vector<int>> patches;
    for (const auto& dt : bnd)
    {
        // Classified by the centre of mass: OCC's bounding boxes of the
        // cut faces are loose (the bottom of the full box, with the cell's
        // footprint cut out, spans z = -+7e-5 um)
        const int s = std::abs(dt.second);
        double xc, yc, zc;
        occ::getCenterOfMass(2, s, xc, yc, zc);
        const auto on = [&](double c, double v)
        {
            return std::abs(c - v) < tol;
        };
        const char* name =
            on(zc, Z) ? "top"
          : on(zc, 0) ? "bottom"
          : on(xc, 0.5*L) || on(yc, 0.5*L) || on(xc, -0.5*L)
         || on(yc, -0.5*L) ? "sides"
          : quarter && on(xc, 0) ? "symmetryX"
          : quarter && on(yc, 0) ? "symmetryY"
          : "cellInterface";
        patches[name].push_back(s);
    }
    for (const auto& p : patches) addGroup(2, p.second, p.first);
    if (patches.size() != (quarter ? 6u : 4u))
    {
        FatalErrorInFunction
            << "The fluid box has " << patches.size() << " kinds of boundary "
            << "surfaces, expected " << (quarter ? 6 : 4) << exit(FatalError);
    }
    sizeField();
    gmsh::option::setNumber("Mesh.Algorithm", 6);
    gmsh::option::setNumber("Mesh.Algorithm3D", 1);
    gmsh::model::mesh::generate(3);
}


void Foam::fluidBox::wedge()
{
    // Structured r-z section on rays from the origin (angle th from the z
    // axis): from the cell surface rho_e(th) to the box rho_b(th), the
    // box corner ray a grid line; radial node spacing from nearSize
    // growing to farSize (sizes of the longest ray, scaled on each ray)
    const scalar L = L_/unit_, a = g_.a()/unit_, H = g_.H()/unit_;
    const scalar hn = nearSize_/unit_, hf = farSize_/unit_;
    const scalar grow = growth_/unit_;
    const scalar thc = std::atan2(0.5*L, L);
    const auto rhoE = [&](scalar th)
    {
        return 1/std::sqrt(sqr(std::sin(th)/a) + sqr(std::cos(th)/H));
    };
    const auto rhoB = [&](scalar th)
    {
        return th <= thc ? L/std::cos(th) : 0.5*L/std::sin(th);
    };
    // Angles: nearSize along the cell surface, at most farSize at the box
    const label nTh = max
    (
        label(std::ceil(g_.arcLength(0, 0.5*pi, false)/unit_/hn)),
        label(std::ceil(0.5*pi*rhoB(thc)/hf))
    );
    const label n1 = max(label(1), label(std::round(nTh*thc/(0.5*pi))));
    const label n2 = max(label(1), nTh - n1);
    std::vector<scalar> th;
    for (label i = 0; i <= n1; ++i) th.push_back(thc*i/n1);
    for (label i = 1; i <= n2; ++i) th.push_back(thc + (0.5*pi - thc)*i/n2);
    scalar Dmax = 0;
    for (const scalar t : th) Dmax = max(Dmax, rhoB(t) - rhoE(t));
    std::vector<scalar> f{0};
    while (f.back() < Dmax)
    {
        f.push_back(f.back() + hn + (hf - hn)*min(1.0, f.back()/grow));
    }
    if (f.size() > 2 && f.back() - Dmax > 0.5*(f.back() - f[f.size() - 2]))
    {
        f.pop_back();
    }
    const label N = label(f.size()) - 1;
    const scalar fN = f.back();
    for (scalar& x : f) x /= fN;

    // Nodes: one on the axis, else two at -+ wedge/2 about the y axis
    // (x = r, y = z as in the axisymmetric cell.msh)
    const label nI = label(th.size());
    const scalar c = std::cos(0.5*wedge_), s = std::sin(0.5*wedge_);
    std::vector<std::size_t> minus(nI*(N + 1)), plus(nI*(N + 1));
    std::vector<double> xyz;
    std::size_t next = 0;
    for (label i = 0; i < nI; ++i)
    for (label k = 0; k <= N; ++k)
    {
        const scalar re = rhoE(th[i]);
        const scalar rho = re + f[k]*(rhoB(th[i]) - re);
        const scalar r = i == 0 ? 0 : rho*std::sin(th[i]);
        const scalar z = i == nI - 1 ? 0 : rho*std::cos(th[i]);
        const label n = i*(N + 1) + k;
        minus[n] = ++next;
        xyz.insert(xyz.end(), {r*c, z, -r*s});
        if (i == 0)
        {
            plus[n] = minus[n];
        }
        else
        {
            plus[n] = ++next;
            xyz.insert(xyz.end(), {r*c, z, r*s});
        }
    }
    const auto id = [&](label i, label k) { return i*(N + 1) + k; };

    gmsh::model::addDiscreteEntity(3, 1);
    std::vector<std::size_t> tags(next);
    for (std::size_t n = 0; n < next; ++n) tags[n] = n + 1;
    gmsh::model::mesh::addNodes(3, 1, tags, xyz);
    const auto X = [&](std::size_t n)
    {
        return vector(xyz[3*n - 3], xyz[3*n - 2], xyz[3*n - 1]);
    };

    // Cells: hexahedra, prisms on the axis (quads with an axis edge); the
    // gmsh orientation is checked on the first cell of each kind (all
    // cells of a kind have the same handedness in a structured grid)
    std::vector<std::size_t> hexNodes, prismNodes;
    for (label i = 0; i + 1 < nI; ++i)
    for (label k = 0; k < N; ++k)
    {
        const label q[4] = {id(i, k), id(i + 1, k), id(i + 1, k + 1),
                            id(i, k + 1)};
        if (i == 0)
        {
            prismNodes.insert
            (
                prismNodes.end(),
                {minus[q[0]], minus[q[1]], plus[q[1]],
                 minus[q[3]], minus[q[2]], plus[q[2]]}
            );
        }
        else
        {
            hexNodes.insert
            (
                hexNodes.end(),
                {minus[q[0]], minus[q[1]], minus[q[2]], minus[q[3]],
                 plus[q[0]], plus[q[1]], plus[q[2]], plus[q[3]]}
            );
        }
    }
    const auto flipIfNegative =
        [&](std::vector<std::size_t>& nodes, int nen, const int (&perm)[8],
            const std::vector<int>& a0, const std::vector<int>& a1,
            const std::vector<int>& a2, int origin)
    {
        const std::size_t* e = nodes.data();
        const vector o = X(e[origin]);
        const auto mean = [&](const std::vector<int>& idx)
        {
            vector m(Zero);
            for (const int k : idx) m += X(e[k]);
            return m/scalar(idx.size()) - o;
        };
        if (((mean(a0) ^ mean(a1)) & mean(a2)) < 0)
        {
            for (std::size_t b = 0; b < nodes.size(); b += nen)
            {
                std::vector<std::size_t> old(&nodes[b], &nodes[b] + nen);
                for (int k = 0; k < nen; ++k) nodes[b + k] = old[perm[k]];
            }
        }
    };
    flipIfNegative(hexNodes, 8, {4, 5, 6, 7, 0, 1, 2, 3}, {1}, {3}, {4}, 0);
    flipIfNegative(prismNodes, 6, {0, 2, 1, 3, 5, 4, 0, 0}, {1}, {2}, {3}, 0);
    std::size_t eTag = 0;
    const auto add = [&](int dim, int ent, int type,
                         const std::vector<std::size_t>& nodes, int nen)
    {
        if (nodes.empty()) return;
        std::vector<std::size_t> et(nodes.size()/nen);
        for (auto& t : et) t = ++eTag;
        gmsh::model::mesh::addElementsByType(ent, type, et, nodes);
    };
    add(3, 1, 5, hexNodes, 8);
    add(3, 1, 6, prismNodes, 6);
    addGroup(3, {1}, "water");

    // Boundary faces: a 2D boundary edge becomes a quadrilateral, or a
    // triangle if one end is on the axis
    std::map<std::string, std::pair<std::vector<std::size_t>,
        std::vector<std::size_t>>> faces;
    const auto edge = [&](const std::string& name, label p, label q)
    {
        auto& fq = faces[name];
        if (plus[p] == minus[p])
        {
            fq.second.insert(fq.second.end(), {minus[p], minus[q], plus[q]});
        }
        else
        {
            fq.first.insert
            (
                fq.first.end(), {minus[p], minus[q], plus[q], plus[p]}
            );
        }
    };
    for (label i = 0; i + 1 < nI; ++i)
    {
        edge("cellInterface", id(i, 0), id(i + 1, 0));
        edge(i < n1 ? "top" : "sides", id(i, N), id(i + 1, N));
    }
    for (label k = 0; k < N; ++k)
    {
        edge("bottom", id(nI - 1, k), id(nI - 1, k + 1));
    }
    for (label i = 0; i + 1 < nI; ++i)
    for (label k = 0; k < N; ++k)
    {
        const label q[4] = {id(i, k), id(i + 1, k), id(i + 1, k + 1),
                            id(i, k + 1)};
        for (const bool front : {false, true})
        {
            auto& fq = faces[front ? "front" : "back"].first;
            for (const label n : q) fq.push_back(front ? plus[n] : minus[n]);
        }
    }
    int surface = 0;
    for (const auto& kv : faces)
    {
        gmsh::model::addDiscreteEntity(2, ++surface);
        add(2, surface, 3, kv.second.first, 4);
        add(2, surface, 2, kv.second.second, 3);
        addGroup(2, {surface}, kv.first);
    }
}


void Foam::fluidBox::hexBox()
{
    hex_->build();
    hex_->toGmsh(unit_);
    const meshQuality q(3, unit_);
    const meshQuality::regionStats w = q.total();
    Info<< "Hexahedral water: segments from the cell to the inner box "
        << hex_->minRay() << " to "
        << hex_->maxRay() << " m in " << hex_->nLayers() << " layers "
        << "(growth ratio at most " << hexFluidMesh::maxRatio_ << ")" << nl;
    if (hex_->input().orthogonal)
    {
        Info<< "Hexahedral water, oGrid orthogonal: largest face "
            << "non-orthogonality " << hex_->nonOrthoBefore() << " deg with"
            << " straight rays, " << hex_->nonOrthoAfter() << " deg after "
            << hex_->sweeps() << " sweeps (cell centres the means of their"
            << " nodes)" << nl;
    }
    q.write(Info);
    if (!(w.minScaledJacobian > 0))
    {
        FatalErrorInFunction
            << "The hexahedral water has an inverted cell (smallest scaled "
            << "Jacobian " << w.minScaledJacobian << ")" << exit(FatalError);
    }
}


void Foam::fluidBox::generate()
{
    gmsh::model::add("fluid");
    if (g_.axisymmetric())
    {
        wedge();
    }
    else if (hex_)
    {
        hexBox();
    }
    else
    {
        box3D();
    }

    // Element counts by type in the water and by patch
    const std::map<int, std::string> typeNames
    {
        {4, "tetrahedra"}, {5, "hexahedra"}, {6, "prisms"}, {7, "pyramids"},
        {2, "triangles"}, {3, "quadrilaterals"}
    };
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    Info<< "Fluid box: side " << L_ << " m";
    if (height_ < L_)
    {
        Info<< ", water to height " << height_ << " m";
    }
    Info<< ", element size " << nearSize_
        << " m at the cell to " << farSize_ << " m at " << growth_
        << " m from it";
    if (g_.axisymmetric())
    {
        Info<< ", wedge " << wedge_*180/pi << " deg";
    }
    if (hex_)
    {
        Info<< "; hexahedra " << hex_->input().axialSize << " m along z, "
            << hex_->input().lateralSize << " m across near the cell";
        if (hex_->input().topRounding > 0)
        {
            Info<< ", inner box's top edges rounded (superellipse exponent "
                << hex_->input().topRounding << ")";
        }
        if (hex_->input().orthogonal)
        {
            Info<< ", O-grid moved for orthogonality";
        }
    }
    if (columnRadius_ > 0)
    {
        Info<< "; column of radius " << columnRadius_ << " m about the axis "
            << "at " << columnSize_ << " m, growing to " << farSize_
            << " m over " << growth_ << " m outside it";
    }
    Info<< nl;
    for (const auto& g : groups)
    {
        std::string name;
        gmsh::model::getPhysicalName(g.first, g.second, name);
        std::vector<int> ents;
        gmsh::model::getEntitiesForPhysicalGroup(g.first, g.second, ents);
        std::map<int, std::size_t> count;
        for (const int e : ents)
        {
            std::vector<int> types;
            std::vector<std::vector<std::size_t>> et, nt;
            gmsh::model::mesh::getElements(types, et, nt, g.first, e);
            for (std::size_t t = 0; t < types.size(); ++t)
            {
                count[types[t]] += et[t].size();
            }
        }
        Info<< "    " << name.c_str() << ":";
        for (const auto& c : count)
        {
            const auto it = typeNames.find(c.first);
            Info<< " " << label(c.second) << " "
                << (it == typeNames.end() ? "other" : it->second.c_str());
        }
        Info<< nl;
    }
    Info<< endl;
}


Foam::fileName Foam::fluidBox::writeTemporary(const fileName& file) const
{
    gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    gmsh::option::setNumber("Mesh.ScalingFactor", unit_);
    return mshFile::writeTemporary(file);
}
