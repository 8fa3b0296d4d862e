// The solid library reads a cellMesh 3D mesh: readGmsh(file, 1) then
// Mesh::check() (throws on a non-positive Jacobian at a Gauss point); the
// regions nucleus/cytoplasm/membrane, the face sets fixedBottom and
// outerSurface (+ symmetryX/symmetryY for a quarter) exist and are not
// empty, and the Gauss-integrated volume is the semi-spheroid's
// (2/3) pi (D/2)^2 H (a quarter of it) within the given relative
// tolerance.
// Usage: cellMeshSolidCheck file.msh full|quarter D[m] H[m] tolerance

#include "GmshReader.H"
#include "Shape.H"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

int main(int argc, char* argv[])
{
    if (argc != 6)
    {
        std::cerr << "usage: " << argv[0]
                  << " file.msh full|quarter D[m] H[m] tolerance\n";
        return 2;
    }
    const std::string file = argv[1], kind = argv[2];
    const double D = std::atof(argv[3]), H = std::atof(argv[4]);
    const double tol = std::atof(argv[5]);
    int failures = 0;
    const auto check = [&](bool ok, const std::string& what)
    {
        std::cout << (ok ? "ok   " : "FAIL ") << what << "\n";
        if (!ok) ++failures;
    };
    try
    {
        const solid::Mesh mesh = solid::readGmsh(file, 1.0);
        mesh.check();
        check(true, "readGmsh + Mesh::check: " + std::to_string(
            mesh.nElements()) + " elements, " + std::to_string(
            mesh.nNodes()) + " nodes");
        check(mesh.type == solid::ElementType::hex8, "8-node hexahedra");
        for (const char* r : {"nucleus", "cytoplasm", "membrane"})
        {
            int n = 0;
            const int id = mesh.regionId(r);
            for (int e = 0; e < mesh.nElements(); ++e) n += mesh.region[e] == id;
            check(n > 0, std::string("region ") + r + ": "
                + std::to_string(n) + " elements");
        }
        std::vector<std::string> sets{"fixedBottom", "outerSurface"};
        if (kind == "quarter")
        {
            sets.push_back("symmetryX");
            sets.push_back("symmetryY");
        }
        for (const auto& s : sets)
        {
            check(!mesh.faceSet(s).empty(), "face set " + s + ": "
                + std::to_string(mesh.faceSet(s).size()) + " faces");
        }
        const solid::ShapeRule& rule = solid::volumeRule(mesh.type);
        double V = 0;
        for (int e = 0; e < mesh.nElements(); ++e)
        {
            const int* en = mesh.element(e);
            for (int q = 0; q < rule.nqp(); ++q)
            {
                Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
                for (int a = 0; a < mesh.nen(); ++a)
                {
                    J += mesh.X[en[a]]*rule.dNdxi[q].row(a);
                }
                V += rule.w[q]*J.determinant();
            }
        }
        const double pi = std::acos(-1.0);
        const double exact =
            2.0/3.0*pi*D*D/4*H*(kind == "quarter" ? 0.25 : 1.0);
        const double err = V/exact - 1;
        std::ostringstream os;
        os  << "volume " << V << " m^3, exact " << exact
            << " m^3, relative error " << err << " (< " << tol << ")";
        check(std::abs(err) < tol, os.str());
    }
    catch (const std::exception& e)
    {
        check(false, std::string("exception: ") + e.what());
    }
    std::cout << "cellMeshSolidCheck: " << failures << " failed\n";
    return failures ? 1 : 0;
}
