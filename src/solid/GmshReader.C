#include "GmshReader.H"
#include "SolidError.H"

#include <gmsh.h>

#include <fstream>
#include <map>
#include <set>

namespace
{

// gmsh element type codes
const int gmshLine2 = 1, gmshQuad4 = 3, gmshHex8 = 5;

std::string groupName(int dim, int tag)
{
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    return name.empty() ? "region" + std::to_string(tag) : name;
}

// gmsh is a process-wide singleton: initialise once, keep it quiet
struct GmshSession
{
    bool owner;
    static bool initialized()
    {
        // gmsh 4.8 has no isInitialized(); its API does not throw before
        // the first initialize() (but may after a finalize()), and
        // initialize() always creates a model: an empty model list or an
        // exception means not initialised
        try
        {
            std::vector<std::string> models;
            gmsh::model::list(models);
            return !models.empty();
        }
        catch (...)
        {
            return false;
        }
    }
    GmshSession()
    :
        owner(!initialized())
    {
        if (owner) gmsh::initialize();
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::model::add("solidReader");
    }
    ~GmshSession()
    {
        gmsh::model::remove();
        if (owner) gmsh::finalize();
    }
};

} // namespace


solid::Mesh solid::readGmsh(const std::string& fileName, double scale)
{
    if (!std::ifstream(fileName).good())
    {
        throw SolidError
        (
            SolidError::Kind::io, "cannot open gmsh file '" + fileName + "'"
        );
    }
    GmshSession session;
    try
    {
        gmsh::merge(fileName);
    }
    catch (const std::exception& e)
    {
        throw SolidError
        (
            SolidError::Kind::io,
            "gmsh could not read '" + fileName + "': " + e.what()
        );
    }
    catch (const std::string& e)
    {
        // gmsh 4.8's API throws its last error message as a std::string
        throw SolidError
        (
            SolidError::Kind::io,
            "gmsh could not read '" + fileName + "': " + e
        );
    }

    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    int dim = 0;
    for (const auto& g : groups) dim = std::max(dim, g.first);
    if (dim < 2)
    {
        throw SolidError
        (
            SolidError::Kind::mesh, "gmsh file '" + fileName + "' has no "
            "2D or 3D physical group (regions must be physical groups)"
        );
    }

    Mesh mesh;
    mesh.type = dim == 2 ? ElementType::quad4Axi : ElementType::hex8;
    const int wanted = dim == 2 ? gmshQuad4 : gmshHex8;
    const int nen = mesh.nen();

    std::vector<std::size_t> tags;
    std::vector<double> coord, par;
    gmsh::model::mesh::getNodes(tags, coord, par, -1, -1, true, false);
    std::map<std::size_t, int> index;
    for (std::size_t i = 0; i < tags.size(); ++i)
    {
        if (index.count(tags[i])) continue;
        index[tags[i]] = int(mesh.X.size());
        mesh.X.push_back
        (
            scale*Vec3(coord[3*i], coord[3*i + 1], dim == 2 ? 0.0
                       : coord[3*i + 2])
        );
    }
    auto node = [&](std::size_t tag)
    {
        const auto it = index.find(tag);
        if (it == index.end())
        {
            throw SolidError
            (
                SolidError::Kind::mesh, "gmsh file '" + fileName
              + "': element refers to unknown node " + std::to_string(tag)
            );
        }
        return it->second;
    };

    std::set<std::size_t> seen;
    for (const auto& g : groups)
    {
        const int gdim = g.first;
        const std::string name = groupName(gdim, g.second);
        std::vector<int> ents;
        gmsh::model::getEntitiesForPhysicalGroup(gdim, g.second, ents);
        std::set<int> nodes;
        int regionId = -1;
        if (gdim == dim)
        {
            regionId = int(mesh.regionNames.size());
            mesh.regionNames.push_back(name);
        }
        for (int ent : ents)
        {
            std::vector<int> types;
            std::vector<std::vector<std::size_t>> etags, ntags;
            gmsh::model::mesh::getElements(types, etags, ntags, gdim, ent);
            for (std::size_t t = 0; t < types.size(); ++t)
            {
                std::string tname;
                int d, order, nn, npr;
                std::vector<double> lc;
                gmsh::model::mesh::getElementProperties
                (
                    types[t], tname, d, order, nn, lc, npr
                );
                for (std::size_t k : ntags[t]) nodes.insert(node(k));
                if (gdim == dim)
                {
                    if (types[t] != wanted)
                    {
                        throw SolidError
                        (
                            SolidError::Kind::mesh, "gmsh file '" + fileName
                          + "': region '" + name + "' contains "
                          + std::to_string(etags[t].size()) + " elements of "
                            "type '" + tname + "'; the solid needs "
                          + (dim == 2 ? "4-node quadrilaterals (recombine)"
                                      : "8-node hexahedra")
                        );
                    }
                    for (std::size_t k = 0; k < etags[t].size(); ++k)
                    {
                        if (!seen.insert(etags[t][k]).second)
                        {
                            throw SolidError
                            (
                                SolidError::Kind::mesh, "gmsh file '"
                              + fileName + "': element "
                              + std::to_string(etags[t][k])
                              + " belongs to two regions (second: '"
                              + name + "')"
                            );
                        }
                        std::vector<int> c(nen);
                        for (int a = 0; a < nen; ++a)
                            c[a] = node(ntags[t][nen*k + a]);
                        mesh.conn.insert(mesh.conn.end(), c.begin(), c.end());
                        mesh.region.push_back(regionId);
                    }
                }
                else if
                (
                    gdim == dim - 1
                 && types[t] == (dim == 2 ? gmshLine2 : gmshQuad4)
                )
                {
                    const int nf = nodesPerFace(mesh.type);
                    for (std::size_t k = 0; k < etags[t].size(); ++k)
                    {
                        std::vector<int> f(nf);
                        for (int a = 0; a < nf; ++a)
                            f[a] = node(ntags[t][nf*k + a]);
                        mesh.faceSets[name].push_back(f);
                    }
                }
            }
        }
        mesh.nodeSets[name].assign(nodes.begin(), nodes.end());
    }

    // Keep only the nodes used by the elements (gmsh keeps geometry points)
    std::vector<int> newId(mesh.X.size(), -1);
    std::vector<Vec3> X;
    for (int& n : mesh.conn)
    {
        if (newId[n] < 0)
        {
            newId[n] = int(X.size());
            X.push_back(mesh.X[n]);
        }
        n = newId[n];
    }
    mesh.X = X;
    for (auto& s : mesh.nodeSets)
    {
        std::vector<int> kept;
        for (int n : s.second) if (newId[n] >= 0) kept.push_back(newId[n]);
        s.second = kept;
    }
    for (auto& s : mesh.faceSets)
        for (auto& f : s.second)
            for (int& n : f) n = newId[n];

    // Counter-clockwise quads in the r-z plane
    if (dim == 2)
    {
        for (int e = 0; e < mesh.nElements(); ++e)
        {
            int* c = mesh.conn.data() + 4*e;
            const Vec3 d1 = mesh.X[c[2]] - mesh.X[c[0]];
            const Vec3 d2 = mesh.X[c[3]] - mesh.X[c[1]];
            if (d1(0)*d2(1) - d1(1)*d2(0) < 0) std::swap(c[1], c[3]);
        }
    }
    mesh.orientFaces();
    mesh.check();
    return mesh;
}
