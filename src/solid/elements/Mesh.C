#include "Mesh.H"
#include "SolidError.H"

#include <algorithm>
#include <set>
#include <sstream>

namespace
{

template<class Map>
std::string names(const Map& m)
{
    std::string s;
    for (const auto& kv : m) s += " " + kv.first;
    return s;
}

//- Throw a parameter SolidError unless a structured mesh of counts n[0..dims)
//  between lo and hi is buildable: each count at least 1 (0 divided by
//  zero: adv32 f11), at most maxStructuredElements in all (counted in
//  doubles: 2e15 overflowed int and allocated without end, f12), hi above
//  lo in every component (an inverted box failed later, f15)
void checkStructured
(
    const char* what,
    int dims,
    const int* n,
    const double* lo,
    const double* hi
)
{
    const auto list = [dims](const auto* v, const char* unit)
    {
        std::ostringstream os;
        os << "(";
        for (int d = 0; d < dims; ++d) os << (d ? " " : "") << v[d];
        os << ")" << unit;
        return os.str();
    };
    const std::string cells(list(n, ""));
    double total = 1;
    for (int d = 0; d < dims; ++d)
    {
        if (n[d] < 1)
        {
            throw solid::SolidError
            (
                solid::SolidError::Kind::parameter, std::string(what)
              + ": entry 'cells' = " + cells + ": each count must be a"
                " whole number of at least 1 (valid range [1, "
              + std::to_string(solid::Mesh::maxStructuredElements)
              + "] elements in all)"
            );
        }
        total *= n[d];
    }
    if (total > double(solid::Mesh::maxStructuredElements))
    {
        std::ostringstream os;
        os << what << ": entry 'cells' = " << cells << " makes " << total
           << " elements, more than the limit "
           << solid::Mesh::maxStructuredElements << " (valid range [1, "
           << solid::Mesh::maxStructuredElements << "] elements in all:"
           << " a model needs about " << solid::Mesh::bytesPerElement/1000
           << " kB per element, " << total*solid::Mesh::bytesPerElement/1e9
           << " GB for this mesh)";
        throw solid::SolidError(solid::SolidError::Kind::parameter, os.str());
    }
    for (int d = 0; d < dims; ++d)
    {
        if (!(hi[d] > lo[d]))
        {
            std::ostringstream os;
            os << what << ": entries 'min' = " << list(lo, " m")
               << " and 'max' = " << list(hi, " m") << ": max must be"
               << " above min in every component (component " << d
               << ": " << hi[d] << " m is not above " << lo[d] << " m)";
            throw solid::SolidError
            (
                solid::SolidError::Kind::parameter, os.str()
            );
        }
    }
}

} // namespace


int solid::Mesh::regionId(const std::string& name) const
{
    for (std::size_t i = 0; i < regionNames.size(); ++i)
    {
        if (regionNames[i] == name) return int(i);
    }
    std::string valid;
    for (const auto& n : regionNames) valid += " " + n;
    throw SolidError
    (
        SolidError::Kind::mesh,
        "mesh has no region '" + name + "'; regions:" + valid
    );
}


const std::vector<int>& solid::Mesh::nodeSet(const std::string& name) const
{
    const auto it = nodeSets.find(name);
    if (it == nodeSets.end())
    {
        throw SolidError
        (
            SolidError::Kind::mesh,
            "mesh has no node set '" + name + "'; node sets:"
          + names(nodeSets)
        );
    }
    return it->second;
}


const std::vector<std::vector<int>>& solid::Mesh::faceSet
(
    const std::string& name
) const
{
    const auto it = faceSets.find(name);
    if (it == faceSets.end())
    {
        throw SolidError
        (
            SolidError::Kind::mesh,
            "mesh has no face set '" + name + "'; face sets:"
          + names(faceSets)
        );
    }
    return it->second;
}


void solid::Mesh::map(const std::function<Vec3(const Vec3&)>& f)
{
    for (auto& x : X) x = f(x);
}


void solid::Mesh::orientFaces()
{
    // Element face lookup by sorted node list
    std::map<std::vector<int>, std::pair<int, int>> faceOf;
    const auto& lf = elementFaces(type);
    for (int e = 0; e < nElements(); ++e)
    {
        for (std::size_t f = 0; f < lf.size(); ++f)
        {
            std::vector<int> key;
            for (int a : lf[f]) key.push_back(element(e)[a]);
            std::sort(key.begin(), key.end());
            faceOf[key] = {e, int(f)};
        }
    }
    for (auto& fs : faceSets)
    {
        for (auto& face : fs.second)
        {
            std::vector<int> key = face;
            std::sort(key.begin(), key.end());
            const auto it = faceOf.find(key);
            if (it == faceOf.end())
            {
                std::ostringstream os;
                os  << "face set '" << fs.first << "': face with nodes";
                for (int n : face) os << " " << n;
                os  << " is not a face of any element";
                throw SolidError(SolidError::Kind::mesh, os.str());
            }
            const int e = it->second.first;
            face.clear();
            for (int a : lf[it->second.second]) face.push_back(element(e)[a]);
        }
    }
}


void solid::Mesh::check() const
{
    if (int(conn.size()) != nen()*nElements())
    {
        throw SolidError
        (
            SolidError::Kind::mesh, "mesh connectivity size does not match "
            "the number of elements"
        );
    }
    const ShapeRule& rule = volumeRule(type);
    const int pdim = rule.pdim;
    for (int e = 0; e < nElements(); ++e)
    {
        const int* en = element(e);
        for (int a = 0; a < nen(); ++a)
        {
            if (en[a] < 0 || en[a] >= nNodes())
            {
                throw SolidError
                (
                    SolidError::Kind::mesh, "element " + std::to_string(e)
                  + " refers to node " + std::to_string(en[a])
                  + " which does not exist"
                );
            }
            if (axisymmetric() && X[en[a]](0) < -1e-14)
            {
                throw SolidError
                (
                    SolidError::Kind::mesh, "element " + std::to_string(e)
                  + ": node " + std::to_string(en[a])
                  + " has r < 0 in an axisymmetric mesh"
                );
            }
        }
        for (int q = 0; q < rule.nqp(); ++q)
        {
            Eigen::MatrixXd Jm = Eigen::MatrixXd::Zero(pdim, pdim);
            for (int a = 0; a < nen(); ++a)
            for (int i = 0; i < pdim; ++i)
            for (int j = 0; j < pdim; ++j)
            {
                Jm(i, j) += X[en[a]](i)*rule.dNdxi[q](a, j);
            }
            const double det = Jm.determinant();
            if (!(det > 0))
            {
                std::ostringstream os;
                os  << "element " << e << " (region '"
                    << (region[e] < int(regionNames.size())
                        ? regionNames[region[e]] : std::string("?"))
                    << "') is inverted or degenerate: reference Jacobian "
                    << det << " at Gauss point " << q;
                throw SolidError(SolidError::Kind::mesh, os.str());
            }
        }
    }
}


solid::Mesh solid::Mesh::rectangle
(
    int nr, int nz, double r0, double r1, double z0, double z1
)
{
    const int n[2] = {nr, nz};
    const double lo[2] = {r0, z0}, hi[2] = {r1, z1};
    checkStructured("rectangle", 2, n, lo, hi);
    Mesh m;
    m.type = ElementType::quad4Axi;
    auto id = [&](int i, int j) { return j*(nr + 1) + i; };
    for (int j = 0; j <= nz; ++j)
    for (int i = 0; i <= nr; ++i)
    {
        m.X.push_back
        (
            Vec3(r0 + (r1 - r0)*i/nr, z0 + (z1 - z0)*j/nz, 0)
        );
    }
    for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nr; ++i)
    {
        for (int n : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)})
        {
            m.conn.push_back(n);
        }
        m.region.push_back(0);
    }
    m.regionNames = {"solid"};
    for (int j = 0; j <= nz; ++j)
    {
        m.nodeSets["left"].push_back(id(0, j));
        m.nodeSets["right"].push_back(id(nr, j));
    }
    for (int i = 0; i <= nr; ++i)
    {
        m.nodeSets["bottom"].push_back(id(i, 0));
        m.nodeSets["top"].push_back(id(i, nz));
    }
    for (int j = 0; j < nz; ++j)
    {
        m.faceSets["left"].push_back({id(0, j + 1), id(0, j)});
        m.faceSets["right"].push_back({id(nr, j), id(nr, j + 1)});
    }
    for (int i = 0; i < nr; ++i)
    {
        m.faceSets["bottom"].push_back({id(i, 0), id(i + 1, 0)});
        m.faceSets["top"].push_back({id(i + 1, nz), id(i, nz)});
    }
    return m;
}


solid::Mesh solid::Mesh::box
(
    int nx, int ny, int nz, const Vec3& lo, const Vec3& hi
)
{
    {
        const int n[3] = {nx, ny, nz};
        const double l[3] = {lo(0), lo(1), lo(2)}, h[3] = {hi(0), hi(1), hi(2)};
        checkStructured("box", 3, n, l, h);
    }
    Mesh m;
    m.type = ElementType::hex8;
    auto id = [&](int i, int j, int k)
    {
        return (k*(ny + 1) + j)*(nx + 1) + i;
    };
    for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
    {
        m.X.push_back
        (
            Vec3
            (
                lo(0) + (hi(0) - lo(0))*i/nx,
                lo(1) + (hi(1) - lo(1))*j/ny,
                lo(2) + (hi(2) - lo(2))*k/nz
            )
        );
    }
    for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
    {
        for
        (
            int n :
            {
                id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
                id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1),
                id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)
            }
        )
        {
            m.conn.push_back(n);
        }
        m.region.push_back(0);
    }
    m.regionNames = {"solid"};
    const int n[3] = {nx, ny, nz};
    const char* nm[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"},
                            {"zmin", "zmax"}};
    for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
    {
        const int ijk[3] = {i, j, k};
        for (int d = 0; d < 3; ++d)
        {
            if (ijk[d] == 0) m.nodeSets[nm[d][0]].push_back(id(i, j, k));
            if (ijk[d] == n[d]) m.nodeSets[nm[d][1]].push_back(id(i, j, k));
        }
    }
    // Boundary faces (orientation fixed by orientFaces)
    for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
    {
        const int ijk[3] = {i, j, k};
        for (int d = 0; d < 3; ++d)
        for (int side = 0; side < 2; ++side)
        {
            if (ijk[d] != (side ? n[d] - 1 : 0)) continue;
            std::vector<int> f;
            const int a = (d + 1)%3, b = (d + 2)%3;
            for (int c = 0; c < 4; ++c)
            {
                int idx[3] = {i, j, k};
                idx[d] += side;
                idx[a] += (c == 1 || c == 2);
                idx[b] += (c >= 2);
                f.push_back(id(idx[0], idx[1], idx[2]));
            }
            m.faceSets[nm[d][side]].push_back(f);
        }
    }
    m.orientFaces();
    return m;
}
