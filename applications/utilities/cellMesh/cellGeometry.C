#include "cellGeometry.H"
#include "IFstream.H"
#include "mathematicalConstants.H"
#include "inputChecks.H"
#include "subDict.H"
#include "keywordCheck.H"

#include <cfenv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

using Foam::constant::mathematical::pi;

namespace
{

// A FatalIOError at the file and line entry key of dict is written in (an
// included cellMeshDict.allrun's line; was the dictionary's lines "from
// line 17 to line 43" of cellMeshDict: adv50b k01, k02)
Foam::OSstream& entryError
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const char* function
)
{
    Foam::fileName file;
    Foam::label line = 0;
    if
    (
        !Foam::foamTools::keywordCheckDetail::entryPlace(dict, key, file, line)
    )
    {
        return Foam::FatalIOError(function, __FILE__, __LINE__, dict);
    }
    return Foam::FatalIOError(function, __FILE__, __LINE__, file, line);
}

// Upper bound of cellDiameter and cellHeight, 1 mm: a larger cell is a
// length given in um, not m
const Foam::scalar maxCellLength = 1e-3;

// Lower bound, 0.1 um (open): a smaller cell is a length given in another
// unit, and its curvature leaves no room for the membrane (adv50a: a
// cellDiameter of 1e-200 m was refused as "membraneThickness ... outside
// the valid range (0, 0) m", the entry given not named)
const Foam::scalar minCellLength = 1e-7;

// The valid ranges of the numbers of system/cellMeshDict, as the readers
// of cellGeometry, fluidBox and hexFluidMesh check them (a bound that is
// another entry named by it), for the scan of the numbers
// (foamTools::checkNumbers), which names an entry's range and unit for a
// value OpenFOAM's reader would not take as written (1e-320, 1e400; was:
// the reader's limits only, fix19f's list). scope: the sub-dictionaries
// ({}, {"fluid"}, {"fluid", "hexCoeffs"})
std::string cellMeshDictRange
(
    const std::string& dictName,
    const std::vector<std::string>& scope,
    const std::string& key
)
{
    if (dictName != "cellMeshDict" || scope.size() > 2)
    {
        return std::string();
    }
    std::string where;
    for (const std::string& s : scope)
    {
        where += (where.empty() ? "" : "/") + s;
    }
    const std::string length
    (
        "(" + Foam::foamTools::numberText(minCellLength) + ", "
      + Foam::foamTools::numberText(maxCellLength) + "] m"
    );
    const std::string size("(0, cellHeight] m");
    static const std::vector<std::pair<std::string, std::string>> none;
    const std::vector<std::pair<std::string, std::string>> rows
    (
        where.empty()
      ? std::vector<std::pair<std::string, std::string>>
        {
            {"cellDiameter", length}, {"cellHeight", length},
            {"nucleusVolumeFraction", "[0.001, 1)"},
            {
                "membraneThickness",
                "(0, the smallest radius of curvature of the cell surface) m"
            },
            {"membraneLayers", "[1, 20]"},
            {"nucleusSize", size}, {"cytoplasmSize", size},
            {"membraneSize", size}, {"azimuthSize", size},
            {"contactRadius", "[0, cellDiameter/2] m"},
            {"contactSize", size}, {"contactDepth", size},
            {"maxElements", "[1, 1000000000]"}
        }
      : where == "fluid"
      ? std::vector<std::pair<std::string, std::string>>
        {
            {
                "boxSize",
                "(the larger of cellDiameter and cellHeight, 0.01) m"
            },
            {"nearSize", size},
            {"farSize", "[nearSize, boxSize/4] m"},
            {"growthDistance", "[nearSize, boxSize] m"},
            {"wedgeAngle", "[0.01, 10] deg"},
            {"columnSize", "(0, farSize] m"},
            {"columnRadius", "(0, boxSize/2] m"},
            {"maxCells", "[1, 1000000000]"},
            {"height", "(the top of the cell or the inner box, boxSize] m"}
        }
      : where == "fluid/hexCoeffs"
      ? std::vector<std::pair<std::string, std::string>>
        {
            {"axialSize", "(0, farSize] m"},
            {"lateralSize", "(0, farSize] m"},
            {"innerMargin", "[nearSize, the gap beside and above the cell) m"},
            {"topRounding", "[5, 100]"},
            {"maxCells", "[1, 1000000000]"}
        }
      : none
    );
    for (const auto& row : rows)
    {
        if (row.first == key)
        {
            return row.second;
        }
    }
    return std::string();
}

const bool cellMeshDictRangeAdded =
    Foam::foamTools::addScanRange(cellMeshDictRange);

} // End anonymous namespace

const Foam::Enum<Foam::cellGeometry::meshMode>
Foam::cellGeometry::meshModeNames
({
    { meshMode::axisymmetric, "axisymmetric" },
    { meshMode::full3D, "full3D" },
    { meshMode::quarter3D, "quarter3D" },
});


const Foam::Enum<Foam::cellGeometry::meshType>
Foam::cellGeometry::meshTypeNames
({
    { meshType::unstructured, "unstructured" },
    { meshType::structured, "structured" },
});


const Foam::Enum<Foam::cellGeometry::structuredSmoothing>
Foam::cellGeometry::structuredSmoothingNames
({
    { structuredSmoothing::none, "none" },
    { structuredSmoothing::elliptic, "elliptic" },
});


const Foam::Enum<Foam::cellGeometry::nucleusShape>
Foam::cellGeometry::nucleusShapeNames
({
    { nucleusShape::centredSpheroid, "centredSpheroid" },
    { nucleusShape::scaledCell, "scaledCell" },
});


Foam::cellGeometry::cellGeometry(const fileName& dictFile)
:
    file_(dictFile)
{
    foamTools::checkNumbers(file_);
    IFstream is(file_);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot read " << file_ << exit(FatalError);
    }
    const dictionary dict(is);
    // fluid{}: fluidBox
    foamTools::checkKeywords
    (
        dict,
        {
            "mode", "meshType", "structuredSmoothing", "nucleusShape",
            "cellDiameter", "cellHeight", "nucleusVolumeFraction",
            "membraneThickness", "membraneLayers", "nucleusSize",
            "cytoplasmSize", "membraneSize", "azimuthSize",
            "contactRadius", "contactSize", "contactDepth", "maxElements",
            "fluid"
        }
    );

    mode_ = foamTools::readEnum(meshModeNames, dict, "mode");
    // The 3D modes are structured only (structuredCell); the axisymmetric
    // section gmsh's unstructured quadrilaterals by default
    meshType_ = foamTools::readEnumOrDefault
    (
        meshTypeNames, dict, "meshType",
        mode_ == meshMode::axisymmetric
      ? meshType::unstructured : meshType::structured
    );
    if (mode_ != meshMode::axisymmetric && !structured())
    {
        // each entry's own file and line where another file gives it (an
        // Allrun's cellMeshDict.allrun: adv49b i01 named cellMeshDict's
        // lines only)
        FatalIOErrorInFunction(dict)
            << "entry 'meshType' = " << meshTypeNames[meshType_]
            << foamTools::givenIn(dict, "meshType").c_str() << " is not"
            << " available in mode " << meshModeNames[mode_]
            << foamTools::givenIn(dict, "mode").c_str() << ": the 3D "
            << "modes are structured only (valid value: structured; "
            << "unstructured is the axisymmetric mode's gmsh section)"
            << exit(FatalIOError);
    }
    smoothing_ = foamTools::readEnumOrDefault
    (
        structuredSmoothingNames, dict, "structuredSmoothing",
        structuredSmoothing::none
    );
    if (smoothing_ != structuredSmoothing::none && !structured())
    {
        entryError(dict, "structuredSmoothing", FUNCTION_NAME)
            << "entry 'structuredSmoothing' = "
            << structuredSmoothingNames[smoothing_]
            << foamTools::givenIn(dict, "structuredSmoothing").c_str()
            << " needs a structured mesh (meshType structured; here "
            << "unstructured"
            << foamTools::givenIn(dict, "meshType").c_str()
            << ": gmsh's section); valid value with meshType unstructured: "
            << "none" << exit(FatalIOError);
    }
    shape_ = foamTools::readEnumOrDefault
    (
        nucleusShapeNames, dict, "nucleusShape", nucleusShape::centredSpheroid
    );
    // The centred spheroid's cytoplasm is one C-shaped block around the
    // nucleus: smoothed, its nucleus-surface nodes slide away from the
    // equator (the smallest scaled Jacobian 0.09 at 0.25 um; branch
    // conv17, session 44)
    if
    (
        smoothing_ == structuredSmoothing::elliptic
     && shape_ != nucleusShape::scaledCell
    )
    {
        entryError(dict, "structuredSmoothing", FUNCTION_NAME)
            << "entry 'structuredSmoothing' = elliptic"
            << foamTools::givenIn(dict, "structuredSmoothing").c_str()
            << " is available for nucleusShape scaledCell only (here "
            << nucleusShapeNames[shape_]
            << foamTools::givenIn(dict, "nucleusShape").c_str()
            << ": its C-shaped cytoplasm block"
            << " distorts when smoothed); valid value here: none"
            << exit(FatalIOError);
    }
    // `fluid 5;` is an error, not "no fluid" (adv32 y01: no fluid.msh,
    // an older one left beside the new cell.msh)
    if (const dictionary* fluid = foamTools::findSubDict(dict, "fluid"))
    {
        fluidDict_ = *fluid;
    }

    // Upper bound 1 mm (maxCellLength: the scan's range too)
    const scalar maxLength = maxCellLength;
    a_ = 0.5*foamTools::readInRange<scalar>
    (
        dict, "cellDiameter", "m", minCellLength, maxLength, false
    );
    H_ = foamTools::readInRange<scalar>
    (
        dict, "cellHeight", "m", minCellLength, maxLength, false
    );
    // Lower bound 1e-3: a nucleus a tenth of the cell across at least
    // (1e-250 was gmsh's failure, "nothing written"; adv pass cm18)
    f_ = foamTools::readInRangeOrDefault<scalar>
    (
        dict, "nucleusVolumeFraction", "(-)", 1e-3, 1, true, 1.0/3.0
    );
    // below 1 (a range open at 1: adv32 cm05, 1 was refused with the
    // range [0.001, 1] printed for 1 - SMALL)
    if (!(f_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'nucleusVolumeFraction' = " << f_ << " (-) is outside"
            << " the valid range [0.001, 1) (-): a nucleus filling the cell "
            << "leaves no cytoplasm and no membrane" << exit(FatalIOError);
    }

    // The inner parallel surface exists below the smallest radius of
    // curvature of the outer ellipse (at the equator H^2/a, on the axis
    // a^2/H)
    const scalar rhoMin = min(sqr(H_)/a_, sqr(a_)/H_);
    // Not one number (a word, '0x1p-20' read as 2 tokens, a
    // sub-dictionary): the message every entry gives, with the valid range
    // (adv45 b33: OpenFOAM's "1 excess tokens in stream", no range); a
    // number outside the range: the reason of the bound below
    if (const entry* e = dict.findEntry("membraneThickness"))
    {
        if
        (
            e->isDict() || e->stream().size() != 1
         || !e->stream()[0].isNumber()
        )
        {
            foamTools::readInRange<scalar>
            (
                dict, "membraneThickness", "m", 0, rhoMin, false, false
            );
        }
    }
    t_ = dict.getOrDefault<scalar>("membraneThickness", 200e-9);
    if (!(t_ > 0 && t_ < rhoMin))
    {
        FatalIOErrorInFunction(dict)
            << "membraneThickness = " << t_ << " m is outside the valid "
            << "range (0, " << rhoMin << ") m: the membrane must be thinner "
            << "than the smallest radius of curvature of the cell surface "
            << "min(H^2/a, a^2/H) (cellHeight " << H_ << " m, cellDiameter "
            << 2*a_ << " m)" << exit(FatalIOError);
    }

    layers_ = foamTools::readInRangeOrDefault<label>
    (
        dict, "membraneLayers", "", 1, 20, true, 2
    );

    nucleusSize_ = foamTools::readInRange<scalar>
    (
        dict, "nucleusSize", "m", 0, H_, false
    );
    cytoplasmSize_ = foamTools::readInRange<scalar>
    (
        dict, "cytoplasmSize", "m", 0, H_, false
    );
    membraneSize_ = foamTools::readInRange<scalar>
    (
        dict, "membraneSize", "m", 0, H_, false
    );
    // The membrane's elements at most maxAspectRatio times thinner than
    // long (as the hex water's first layer): membraneThickness 1e-12 m
    // meshed needles, exit 0 (adv pass cm18)
    {
        const scalar maxAspectRatio = 1000;
        const scalar tMin = layers_*membraneSize_/maxAspectRatio;
        if (t_ < tMin)
        {
            FatalIOErrorInFunction(dict)
                << "entry 'membraneThickness' = " << t_ << " m is outside "
                << "the valid range [" << tMin << ", " << rhoMin << ") m: "
                << "its " << layers_ << " layers of elements would be "
                << layers_*membraneSize_/t_ << " times thinner than long "
                << "(membraneSize " << membraneSize_ << " m; at most "
                << maxAspectRatio << ")" << exit(FatalIOError);
        }
    }
    azimuthSize_ = min(cytoplasmSize_, membraneSize_);
    if (dict.found("azimuthSize"))
    {
        if (mode_ == meshMode::axisymmetric)
        {
            FatalIOErrorInFunction(dict)
                << "azimuthSize is available in the 3D modes (quarter3D, "
                << "full3D) only: the axisymmetric mesh has no azimuth"
                << exit(FatalIOError);
        }
        azimuthSize_ = foamTools::readInRange<scalar>
        (
            dict, "azimuthSize", "m", 0, H_, false
        );
    }
    contactRadius_ = foamTools::readInRange<scalar>
    (
        dict, "contactRadius", "m", 0, a_, true
    );
    contactSize_ = cytoplasmSize_;
    contactDepth_ = H_;
    if (contactRadius_ > 0)
    {
        contactSize_ = foamTools::readInRange<scalar>
        (
            dict, "contactSize", "m", 0, H_, false
        );
        contactDepth_ = foamTools::readInRange<scalar>
        (
            dict, "contactDepth", "m", 0, H_, false
        );
        // The refined zone at least one of its elements wide and deep
        // (1e-250 m was gmsh's failure or a zone of nothing, exit 0; adv
        // pass cm18)
        for
        (
            const auto& e
          : {
                std::make_pair("contactRadius", contactRadius_),
                std::make_pair("contactDepth", contactDepth_)
            }
        )
        {
            if (e.second < contactSize_)
            {
                FatalIOErrorInFunction(dict)
                    << "entry '" << e.first << "' = "
                    << foamTools::numberText(e.second).c_str() << " m is"
                    << " outside the valid range "
                    << foamTools::rangeText
                       (
                           contactSize_, e.first[7] == 'R' ? a_ : H_, true,
                           foamTools::numberText(e.second)
                       ).c_str()
                    << " m (0 for no "
                    << "refined zone): the zone under the contact is at "
                    << "least one of its elements (contactSize "
                    << contactSize_ << " m) wide and deep"
                    << exit(FatalIOError);
            }
        }
    }

    maxElements_ = foamTools::readInRangeOrDefault<label>
    (
        dict, "maxElements", "", 1, 1000000000, true, 1000000
    );
    const label maxElements = maxElements_;
    // The estimate with the floating-point traps held: sizes the reader
    // takes (1e-200 m) make it overflow or divide by an underflowed 0
    // (adv50a k11: sigFpe, exit 136, before any message); beyond a double
    // it is any count above maxElements
    scalar estimate = 0;
    {
        std::fenv_t env;
        std::feholdexcept(&env);
        estimate = minimumElements();
        std::feclearexcept(FE_ALL_EXCEPT);
        std::fesetenv(&env);
    }
    if (!std::isfinite(estimate) || estimate > maxElements)
    {
        // 3 digits, or the least whole count when those would not read
        // more than maxElements (adv47b f46: 183.4 printed "at least 183
        // elements, more than maxElements 183")
        const std::string count
        (
            std::isfinite(estimate)
          ? foamTools::countAboveText(std::ceil(estimate), maxElements, 3)
          : std::string("1e+300 (beyond any count)")
        );
        FatalIOErrorInFunction(dict)
            << "The element sizes ask for at least "
            << count.c_str() << " elements, more"
            << " than maxElements " << maxElements << " (nucleusSize "
            << nucleusSize_ << " m, cytoplasmSize " << cytoplasmSize_
            << " m, membraneSize " << membraneSize_ << " m, membraneLayers "
            << layers_;
        if (!axisymmetric())
        {
            FatalIOError << ", azimuthSize " << azimuthSize_ << " m";
        }
        if (contactRadius_ > 0)
        {
            FatalIOError
                << ", contactSize " << contactSize_ << " m over contactRadius "
                << contactRadius_ << " m and contactDepth " << contactDepth_
                << " m";
        }
        FatalIOError
            << "; cell " << 2*a_ << " x " << H_ << " m): larger"
            << " sizes (in metres), or a larger maxElements if that many is"
            << " meant" << exit(FatalIOError);
    }

    gap_ = nucleusGap();
    if (!(gap_ > 0))
    {
        entryError(dict, "nucleusVolumeFraction", FUNCTION_NAME)
            << "nucleusVolumeFraction = "
            << foamTools::numberText(f_).c_str() << ": the nucleus ("
            << nucleusShapeNames[shape_] << " of diameter " << 2*an()
            << " m and height " << nucleusHeight() << " m) is not inside "
            << "the cell: it reaches " << -gap_ << " m into the membrane "
            << "(membraneThickness " << t_ << " m)" << exit(FatalIOError);
    }
    if (gap_ < min(cytoplasmSize_, contactSize_))
    {
        WarningInFunction
            << "The cytoplasm between nucleus and membrane is only " << gap_
            << " m thick, less than one element (" << file_ << ")" << nl;
    }
}


Foam::cellGeometry::rz Foam::cellGeometry::outer(scalar theta) const
{
    return rz(a_*sin(theta), H_*cos(theta));
}


Foam::cellGeometry::rz Foam::cellGeometry::inner(scalar theta) const
{
    const scalar nr = sin(theta)/a_;
    const scalar nz = cos(theta)/H_;
    const scalar n = sqrt(sqr(nr) + sqr(nz));
    const rz X = outer(theta);
    return rz(X.first() - t_*nr/n, X.second() - t_*nz/n);
}


Foam::scalar Foam::cellGeometry::thetaContact() const
{
    return asin(min(scalar(1), contactRadius_/a_));
}


Foam::scalar Foam::cellGeometry::arcLength
(
    scalar theta0,
    scalar theta1,
    bool innerCurve
) const
{
    const label n = 20000;
    scalar L = 0;
    rz p = innerCurve ? inner(theta0) : outer(theta0);
    for (label i = 1; i <= n; ++i)
    {
        const scalar th = theta0 + (theta1 - theta0)*i/n;
        const rz q = innerCurve ? inner(th) : outer(th);
        L += sqrt(sqr(q.first() - p.first()) + sqr(q.second() - p.second()));
        p = q;
    }
    return L;
}


Foam::scalar Foam::cellGeometry::nucleusGap() const
{
    // Distance of nucleus surface points to the outer surface minus t:
    // the inner surface is the set at distance t from the outer one
    const label nTheta = 8000;
    List<rz> X(nTheta + 1);
    forAll(X, i)
    {
        X[i] = outer(0.5*pi*i/nTheta);
    }
    // The centred spheroid must also clear the substrate; the scaled cell
    // stands on it (phi in [0, pi/2] only)
    scalar gap = scaledNucleus() ? GREAT : zn() - cn();
    const label nNuc = 800;
    const scalar phiMax = scaledNucleus() ? 0.5*pi : pi;
    for (label j = 0; j <= nNuc; ++j)
    {
        const scalar phi = phiMax*j/nNuc;
        const scalar r = an()*sin(phi);
        const scalar z = zn() + cn()*cos(phi);
        scalar d = GREAT;
        for (const rz& x : X)
        {
            d = min(d, sqr(r - x.first()) + sqr(z - x.second()));
        }
        d = sqrt(d);
        const bool inside = sqr(r/a_) + sqr(z/H_) < 1;
        gap = min(gap, (inside ? d : -d) - t_);
    }
    return gap;
}


Foam::scalar Foam::cellGeometry::cellArea() const
{
    return 0.25*pi*a_*H_;
}


Foam::scalar Foam::cellGeometry::cellVolume() const
{
    return 2.0/3.0*pi*sqr(a_)*H_;
}


Foam::scalar Foam::cellGeometry::nucleusArea() const
{
    return (scaledNucleus() ? 0.25 : 0.5)*pi*an()*cn();
}


Foam::scalar Foam::cellGeometry::nucleusVolume() const
{
    return (scaledNucleus() ? 2.0/3.0 : 4.0/3.0)*pi*sqr(an())*cn();
}


Foam::scalar Foam::cellGeometry::innerArea() const
{
    // Green: A = 1/2 closed integral (r dz - z dr); axis and substrate
    // add nothing, the curve runs from the substrate to the axis
    const label n = 100000;
    scalar A = 0;
    for (label i = 0; i < n; ++i)
    {
        const rz p = inner(0.5*pi*(n - i)/n);
        const rz q = inner(0.5*pi*(n - i - 1)/n);
        A += 0.5*(p.first()*q.second() - q.first()*p.second());
    }
    return A;
}


Foam::scalar Foam::cellGeometry::innerVolume() const
{
    // Green: V = 2 pi int r dA = pi closed integral r^2 dz (trapezoidal
    // in r^2 on each chord is exact for the polygon)
    const label n = 100000;
    scalar V = 0;
    for (label i = 0; i < n; ++i)
    {
        const rz p = inner(0.5*pi*(n - i)/n);
        const rz q = inner(0.5*pi*(n - i - 1)/n);
        V += pi/3.0*(sqr(p.first()) + p.first()*q.first() + sqr(q.first()))
            *(q.second() - p.second());
    }
    return V;
}


Foam::scalar Foam::cellGeometry::minimumElements() const
{
    const scalar quarter = mode_ == meshMode::quarter3D ? 0.25 : 1;
    // The contact patch (contactRadius > 0): elements of contactSize in
    // r <= contactRadius down to contactDepth below the surface there, and
    // along the membrane's contact patch (was not counted: contactSize
    // 1e-10 m meshed without end; issue 19, adversarial pass)
    scalar contact = 0;
    if (contactRadius_ > 0 && !(axisymmetric() && structured()))
    {
        const scalar rc = contactRadius_;
        const scalar depth = min(contactDepth_, outer(thetaContact()).second());
        contact = axisymmetric()
            ? rc*depth/sqr(contactSize_) + rc/contactSize_*layers_
            : quarter*constant::mathematical::pi*sqr(rc)
             *(depth/pow3(contactSize_) + layers_/sqr(contactSize_));
    }
    if (axisymmetric())
    {
        const scalar A = 0.25*constant::mathematical::pi*a_*H_;
        const scalar An = pow(f_, 2.0/3.0)*A;
        return max
        (
            contact,
            An/sqr(nucleusSize_) + (A - An)/sqr(cytoplasmSize_)
          + max(a_, H_)/membraneSize_*layers_
        );
    }
    const scalar V =
        quarter*2.0/3.0*constant::mathematical::pi*sqr(a_)*H_;
    const scalar S = quarter*constant::mathematical::pi*sqr(a_);
    // The azimuth (structuredCell): every ring of the section revolved in
    // nSq elements per quarter turn, nSq = 2 ceil(pi/4 (r_c + a)/2 /
    // azimuthSize), r_c = an/2 the column's radius, and the column's
    // butterfly disc of nSq x nSq elements (a full turn; a quarter of it
    // in the quarter) on every level of it (at least the membrane's layers,
    // the cytoplasm and the nucleus). Counted from the membrane alone
    // (its layers along the outer curve outside the column): a lower
    // bound. azimuthSize was not counted (issue 19, adv28 m13, q09:
    // azimuthSize 1e-9 m allocated GBs without output)
    const scalar rc = 0.5*an();
    const scalar nSq =
        2*std::ceil(0.25*constant::mathematical::pi*0.5*(rc + a_)/azimuthSize_);
    const scalar membraneRows = std::ceil
    (
        arcLength(asin(min(scalar(1), rc/a_)), 0.5*constant::mathematical::pi,
                  false)/membraneSize_
    );
    const scalar azimuthal =
        (mode_ == meshMode::quarter3D ? 1 : 4)*nSq*membraneRows*layers_
      + (mode_ == meshMode::quarter3D ? 0.25 : 1)*sqr(nSq)*(layers_ + 2);
    return max
    (
        max(contact, azimuthal),
        f_*V/pow3(nucleusSize_) + (1 - f_)*V/pow3(cytoplasmSize_)
      + S/sqr(membraneSize_)*layers_
    );
}


// ************************************************************************* //
