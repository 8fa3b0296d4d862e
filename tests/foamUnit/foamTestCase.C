#include "foamTestCase.H"
#include "cellModel.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "mathematicalConstants.H"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

namespace
{

const char* fvSolutionText =
    "FoamFile { version 2.0; format ascii; class dictionary;"
    " object fvSolution; }\n"
    "riemann { riemannSolver HLLC; }\n";

} // End anonymous namespace


Foam::foamUnit::testCase::testCase(const word& name, const scalar deltaT)
{
    const char* tmp = std::getenv("TMPDIR");
    std::string templ =
        std::string(tmp && *tmp ? tmp : "/tmp") + "/foamUnit-" + name
      + "-XXXXXX";
    if (!mkdtemp(&templ[0]))
    {
        FatalErrorInFunction
            << "Cannot make a temporary directory " << templ.c_str()
            << exit(FatalError);
    }
    root_ = templ;
    mkDir(dir()/"system");
    mkDir(dir()/"constant");
    mkDir(dir()/"0");
    writeReconstruction("upwind", "upwind");
    writeFile("system/fvSolution", fvSolutionText);

    dictionary controlDict;
    controlDict.add("application", word("foamUnitTests"));
    controlDict.add("startFrom", word("startTime"));
    controlDict.add("startTime", 0);
    controlDict.add("stopAt", word("endTime"));
    controlDict.add("endTime", 1);
    controlDict.add("deltaT", deltaT);
    controlDict.add("writeControl", word("timeStep"));
    controlDict.add("writeInterval", 1);
    controlDict.add("writeFormat", word("ascii"));
    controlDict.add("writePrecision", 17);
    controlDict.add("runTimeModifiable", word("false"));
    runTime_.reset
    (
        new Time(controlDict, root_, "case", "system", "constant", true, false)
    );
}


Foam::foamUnit::testCase::~testCase()
{
    runTime_.clear();
    // (OpenFOAM's rmDir leaves dot files, e.g. the markers of writeGuard,
    // and then the directory)
    std::error_code ec;
    std::filesystem::remove_all(std::string(root_), ec);
}


Foam::fileName Foam::foamUnit::testCase::dir() const
{
    return root_/"case";
}


void Foam::foamUnit::testCase::writeFile
(
    const fileName& relPath,
    const std::string& text
) const
{
    const fileName file(dir()/relPath);
    mkDir(file.path());
    std::ofstream os(file);
    os << text;
    if (!os)
    {
        FatalErrorInFunction
            << "Cannot write " << file << exit(FatalError);
    }
}


void Foam::foamUnit::testCase::writeReconstruction
(
    const word& scalarScheme,
    const word& vectorScheme
) const
{
    writeFile
    (
        "system/fvSchemes",
        "FoamFile { version 2.0; format ascii; class dictionary;"
        " object fvSchemes; }\n"
        "ddtSchemes { default Euler; }\n"
        "gradSchemes { default Gauss linear; }\n"
        "divSchemes { default none; }\n"
        "laplacianSchemes { default Gauss linear corrected; }\n"
        "interpolationSchemes\n{\n    default linear;\n"
        "    reconstruct(rho) " + scalarScheme + ";\n"
        "    reconstruct(U) " + vectorScheme + ";\n"
        "    reconstruct(p) " + scalarScheme + ";\n}\n"
        "snGradSchemes { default corrected; }\n"
    );
}


void Foam::foamUnit::testCase::writeThermophysicalProperties
(
    const word& equationOfState
) const
{
    IStringStream is
    (
        usageExample
        (
            "src/thermophysicalModels/rhoEThermo/rhoEThermo/rhoEThermo.H"
        )
    );
    dictionary d(is);
    d.set("equationOfState", equationOfState);
    OStringStream os;
    os.precision(17);
    os  << "FoamFile { version 2.0; format ascii; class dictionary;"
        << " object thermophysicalProperties; }" << nl;
    d.write(os, false);
    writeFile("constant/thermophysicalProperties", os.str());
}


void Foam::foamUnit::testCase::writeUniformField
(
    const word& name,
    const dimensionSet& dims,
    const scalar value,
    const word& patchType
) const
{
    OFstream os(dir()/"0"/name);
    os.precision(17);
    os  << "FoamFile { version 2.0; format ascii; class volScalarField;"
        << " object " << name << "; }" << nl
        << "dimensions " << dims << ";" << nl
        << "internalField uniform " << value << ";" << nl
        << "boundaryField { \".*\" { type " << patchType
        << "; value uniform " << value << "; } }" << nl;
}


std::string Foam::foamUnit::testCase::usageExample(const fileName& header)
{
    const fileName file(getEnv("PROJECT_DIR")/header);
    std::ifstream is(file);
    const std::string text
    (
        (std::istreambuf_iterator<char>(is)),
        std::istreambuf_iterator<char>()
    );
    const auto usage = text.find("\nUsage\n");
    const auto begin = text.find("\\verbatim", usage);
    const auto end = text.find("\\endverbatim", begin);
    if (!is || usage == std::string::npos || end == std::string::npos)
    {
        FatalErrorInFunction
            << "No Usage example (\\verbatim ... \\endverbatim) in " << file
            << " (is PROJECT_DIR set?)" << exit(FatalError);
    }
    const auto start = begin + std::string("\\verbatim").size();
    return text.substr(start, end - start);
}


Foam::autoPtr<Foam::fvMesh> Foam::foamUnit::testCase::blockMesh
(
    const Vector<label>& n,
    const std::function<point(const vector&)>& map,
    const sideWords& patchNames,
    const sideWords& patchTypes
)
{
    const label ni = n.x(), nj = n.y(), nk = n.z();
    auto pointi = [&](label i, label j, label k)
    {
        return i + (ni + 1)*(j + (nj + 1)*k);
    };

    pointField points((ni + 1)*(nj + 1)*(nk + 1));
    for (label k = 0; k <= nk; ++k)
    for (label j = 0; j <= nj; ++j)
    for (label i = 0; i <= ni; ++i)
    {
        points[pointi(i, j, k)] =
            map(vector(scalar(i)/ni, scalar(j)/nj, scalar(k)/nk));
    }

    // Patches in the order of their first side; their faces
    wordList names, types;
    std::map<word, label> patchIndex;
    for (label side = 0; side < 6; ++side)
    {
        if (patchIndex.emplace(patchNames[side], names.size()).second)
        {
            names.append(patchNames[side]);
            types.append(patchTypes[side]);
        }
    }
    List<DynamicList<face>> patchFaces(names.size());

    const cellModel& hex = cellModel::ref(cellModel::HEX);
    cellShapeList shapes(ni*nj*nk);
    label celli = 0;
    for (label k = 0; k < nk; ++k)
    for (label j = 0; j < nj; ++j)
    for (label i = 0; i < ni; ++i)
    {
        const labelList verts
        ({
            pointi(i, j, k), pointi(i + 1, j, k),
            pointi(i + 1, j + 1, k), pointi(i, j + 1, k),
            pointi(i, j, k + 1), pointi(i + 1, j, k + 1),
            pointi(i + 1, j + 1, k + 1), pointi(i, j + 1, k + 1)
        });
        shapes[celli] = cellShape(hex, verts);
        const faceList cellFaces(shapes[celli].faces());
        const bool onSide[6] =
            {i == 0, i == ni - 1, j == 0, j == nj - 1, k == 0, k == nk - 1};
        for (label side = 0; side < 6; ++side)
        {
            if (onSide[side])
            {
                patchFaces[patchIndex[patchNames[side]]].append
                (
                    cellFaces[side]
                );
            }
        }
        ++celli;
    }

    faceListList boundaryFaces(names.size());
    forAll(boundaryFaces, patchi)
    {
        boundaryFaces[patchi].transfer(patchFaces[patchi]);
    }

    {
        polyMesh mesh
        (
            IOobject
            (
                polyMesh::defaultRegion,
                time().constant(),
                time(),
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            std::move(points),
            shapes,
            boundaryFaces,
            names,
            types,
            "defaultFaces",
            "empty",
            wordList(names.size(), word::null)
        );
        mesh.write();
    }

    return autoPtr<fvMesh>
    (
        new fvMesh
        (
            IOobject
            (
                polyMesh::defaultRegion,
                time().timeName(),
                time(),
                IOobject::MUST_READ
            )
        )
    );
}


Foam::autoPtr<Foam::fvMesh> Foam::foamUnit::testCase::wedgeMesh()
{
    const scalar tanHalf = std::tan(2.5*constant::mathematical::pi/180);
    return blockMesh
    (
        {7, 6, 1},
        [tanHalf](const vector& s)
        {
            const scalar r = 2e-6 + 10e-6*(s.x() + 0.6*s.x()*s.x());
            const scalar y =
                8e-6*(s.y() + 0.07*std::sin(3.1*s.y())*(1 + s.x()));
            return point(r, y, (2*s.z() - 1)*tanHalf*r);
        },
        {"inner", "outer", "bottom", "top", "front", "back"},
        {"patch", "wall", "symmetryPlane", "patch", "wedge", "wedge"}
    );
}
