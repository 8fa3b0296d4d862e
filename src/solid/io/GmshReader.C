#include "GmshReader.H"
#include "fileKind.H"
#include "SolidError.H"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

using solid::SolidError;
using solid::Vec3;

namespace
{

// gmsh element type codes
const int gmshLine2 = 1, gmshQuad4 = 3, gmshHex8 = 5;

//- Name and dimension of the gmsh element types (gmsh's own names, as its
//  API's getElementProperties gives them); node counts are not needed:
//  every element is one line
struct ElementTypeInfo
{
    int type;
    int dim;
    const char* name;
};

const ElementTypeInfo elementTypes[] =
{
    {1, 1, "Line 2"}, {2, 2, "Triangle 3"}, {3, 2, "Quadrilateral 4"},
    {4, 3, "Tetrahedron 4"}, {5, 3, "Hexahedron 8"}, {6, 3, "Prism 6"},
    {7, 3, "Pyramid 5"}, {8, 1, "Line 3"}, {9, 2, "Triangle 6"},
    {10, 2, "Quadrilateral 9"}, {11, 3, "Tetrahedron 10"},
    {12, 3, "Hexahedron 27"}, {13, 3, "Prism 18"}, {14, 3, "Pyramid 14"},
    {15, 0, "Point"}, {16, 2, "Quadrilateral 8"}, {17, 3, "Hexahedron 20"},
    {18, 3, "Prism 15"}, {19, 3, "Pyramid 13"}, {20, 2, "Triangle 9"},
    {21, 2, "Triangle 10"}, {22, 2, "Triangle 12"}, {23, 2, "Triangle 15"},
    {24, 2, "Triangle 15"}, {25, 2, "Triangle 21"}, {26, 1, "Line 4"},
    {27, 1, "Line 5"}, {28, 1, "Line 6"}, {29, 3, "Tetrahedron 20"},
    {30, 3, "Tetrahedron 35"}, {31, 3, "Tetrahedron 56"},
    {36, 2, "Quadrilateral 16"}, {37, 2, "Quadrilateral 25"},
    {38, 2, "Quadrilateral 36"}, {92, 3, "Hexahedron 64"},
    {93, 3, "Hexahedron 125"}
};

const ElementTypeInfo* typeInfo(int type)
{
    for (const auto& t : elementTypes)
    {
        if (t.type == type) return &t;
    }
    return nullptr;
}

std::string typeName(int type)
{
    const ElementTypeInfo* t = typeInfo(type);
    return t ? t->name : "gmsh type " + std::to_string(type);
}


//- A block of elements of one type on one geometric entity, as gmsh's
//  API returns them (element tags, node tags flattened)
struct ElementBlock
{
    int type;
    std::vector<std::size_t> tags;
    std::vector<std::size_t> nodes;
};

//- What the solid reader needs of an MSH file: the model gmsh would hold
//  after reading it
struct MshModel
{
    std::map<std::pair<int, int>, std::string> physicalNames;
    //- Physical tags of each entity (dim, tag)
    std::map<std::pair<int, int>, std::set<int>> entityPhysicals;
    //- Nodes in file order
    std::vector<std::size_t> nodeTags;
    std::vector<Vec3> nodeX;
    //- Element blocks per entity (dim, tag), entities in ascending order
    std::map<std::pair<int, int>, std::vector<ElementBlock>> elements;
    //- Whether the file declares its entities ($Entities, MSH 4.1)
    bool entities = false;

    //- Physical groups (dim, tag) in gmsh's order: by dimension, then tag
    std::set<std::pair<int, int>> groups() const
    {
        std::set<std::pair<int, int>> g;
        for (const auto& e : entityPhysicals)
        {
            for (int p : e.second) g.insert({e.first.first, p});
        }
        return g;
    }
};


//- Line-oriented reader of an ASCII MSH file; every error names the file
//  and the line
class MshParser
{
    const std::string& file_;
    std::ifstream is_;
    long line_ = 0;

public:

    explicit MshParser(const std::string& file)
    :
        file_(file),
        is_(file)
    {}

    bool good() const { return is_.good(); }

    [[noreturn]] void fail(const std::string& msg) const
    {
        throw SolidError
        (
            SolidError::Kind::io, "gmsh file '" + file_ + "', line "
          + std::to_string(line_) + ": " + msg
        );
    }

    //- Next line (trailing CR removed); false at the end of the file
    bool next(std::string& s)
    {
        if (!std::getline(is_, s)) return false;
        ++line_;
        if (!s.empty() && s.back() == '\r') s.pop_back();
        return true;
    }

    //- Next line, which must exist (inside section 'section')
    std::string need(const std::string& section)
    {
        std::string s;
        if (!next(s))
        {
            fail("the file ends inside section $" + section
               + " (truncated?)");
        }
        return s;
    }

    //- Integers of a line: exactly n if n >= 0, else all of them
    std::vector<long long> integers
    (
        const std::string& s,
        const std::string& what,
        int n = -1
    )
    {
        std::vector<long long> v;
        const char* p = s.c_str();
        while (true)
        {
            while (*p == ' ' || *p == '\t') ++p;
            if (!*p) break;
            char* end;
            const long long x = std::strtoll(p, &end, 10);
            if (end == p || (*end && *end != ' ' && *end != '\t'))
            {
                fail("expected integers (" + what + "), read '" + s + "'");
            }
            v.push_back(x);
            p = end;
        }
        if (n >= 0 && int(v.size()) != n)
        {
            fail("expected " + std::to_string(n) + " integers (" + what
               + "), read '" + s + "'");
        }
        return v;
    }

    //- First three numbers of a line as finite coordinates
    Vec3 coordinates(const std::string& s, std::size_t tag)
    {
        Vec3 x;
        const char* p = s.c_str();
        for (int i = 0; i < 3; ++i)
        {
            char* end;
            x(i) = std::strtod(p, &end);
            if (end == p)
            {
                fail("expected the coordinates x y z of node "
                   + std::to_string(tag) + ", read '" + s + "'");
            }
            p = end;
        }
        if (!x.allFinite())
        {
            fail("node " + std::to_string(tag) + " has a non-finite "
                 "coordinate: '" + s + "'");
        }
        return x;
    }

    //- Skip to the line $End<section>
    void skip(const std::string& section)
    {
        const std::string end = "$End" + section;
        std::string s;
        do { s = need(section); } while (s != end);
    }

    //- The next line must be $End<section>
    void expectEnd(const std::string& section)
    {
        const std::string s = need(section);
        if (s != "$End" + section)
        {
            fail("expected $End" + section + " (more entries than its count"
                 " says?), read '" + s + "'");
        }
    }

    static std::size_t tag(long long x) { return std::size_t(x); }

    //- Count read from a header field: non-negative
    std::size_t count(long long x, const std::string& what)
    {
        if (x < 0) fail("negative " + what + " " + std::to_string(x));
        return std::size_t(x);
    }

    void physicalNames(MshModel& m)
    {
        const std::size_t n =
            count(integers(need("PhysicalNames"), "count", 1)[0], "count");
        for (std::size_t i = 0; i < n; ++i)
        {
            const std::string s = need("PhysicalNames");
            std::istringstream ls(s);
            int dim, tag;
            if (!(ls >> dim >> tag))
            {
                fail("expected 'dim tag \"name\"', read '" + s + "'");
            }
            const auto q0 = s.find('"'), q1 = s.rfind('"');
            if (q0 == std::string::npos || q1 == q0)
            {
                fail("expected a quoted physical name, read '" + s + "'");
            }
            m.physicalNames[{dim, tag}] = s.substr(q0 + 1, q1 - q0 - 1);
        }
        expectEnd("PhysicalNames");
    }

    // MSH 4.1: $Entities, $Nodes and $Elements in entity blocks

    void entities41(MshModel& m)
    {
        const auto n = integers(need("Entities"), "entity counts", 4);
        m.entities = true;
        for (int dim = 0; dim < 4; ++dim)
        {
            const std::size_t ne = count(n[dim], "entity count");
            for (std::size_t i = 0; i < ne; ++i)
            {
                const std::string s = need("Entities");
                std::istringstream ls(s);
                int tag;
                double x;
                long long np = -1;
                ls >> tag;
                for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) ls >> x;
                ls >> np;
                if (!ls || np < 0)
                {
                    fail("malformed entity of dimension "
                       + std::to_string(dim) + ": '" + s + "'");
                }
                auto& p = m.entityPhysicals[{dim, tag}];
                for (long long k = 0; k < np; ++k)
                {
                    int ptag;
                    if (!(ls >> ptag))
                    {
                        fail("entity " + std::to_string(tag) + " lists "
                           + std::to_string(np) + " physical tags, fewer "
                             "read: '" + s + "'");
                    }
                    p.insert(std::abs(ptag));
                }
            }
        }
        expectEnd("Entities");
    }

    void nodes41(MshModel& m)
    {
        const auto h = integers(need("Nodes"), "numEntityBlocks numNodes "
            "minNodeTag maxNodeTag", 4);
        std::size_t total = 0;
        for (std::size_t b = 0; b < count(h[0], "block count"); ++b)
        {
            const auto bh = integers(need("Nodes"), "entityDim entityTag "
                "parametric numNodesInBlock", 4);
            const std::size_t nb = count(bh[3], "node count");
            // Not preallocated: a count larger than the file ends at its end
            std::vector<std::size_t> tags;
            for (std::size_t i = 0; i < nb; ++i)
            {
                tags.push_back
                (
                    tag(integers(need("Nodes"), "node tag", 1)[0])
                );
            }
            for (std::size_t t : tags)
            {
                m.nodeTags.push_back(t);
                m.nodeX.push_back(coordinates(need("Nodes"), t));
            }
            total += nb;
        }
        if (total != count(h[1], "node count"))
        {
            fail("$Nodes announces " + std::to_string(h[1]) + " nodes, its "
                 "blocks hold " + std::to_string(total));
        }
        expectEnd("Nodes");
    }

    void elements41(MshModel& m)
    {
        const auto h = integers(need("Elements"), "numEntityBlocks "
            "numElements minElementTag maxElementTag", 4);
        std::size_t total = 0;
        for (std::size_t b = 0; b < count(h[0], "block count"); ++b)
        {
            const auto bh = integers(need("Elements"), "entityDim entityTag "
                "elementType numElementsInBlock", 4);
            ElementBlock blk;
            blk.type = int(bh[2]);
            // The block's entity as declared: an undeclared one, or one of
            // another dimension than its elements', made the elements
            // belong to no region, and the error blamed a boundary group
            // (adv32 g17, g18)
            const std::string entity
            (
                "(" + std::to_string(bh[0]) + ", " + std::to_string(bh[1])
              + ")"
            );
            const ElementTypeInfo* info = typeInfo(blk.type);
            if (info && info->dim != bh[0])
            {
                fail("element block of entity " + entity + " (dimension "
                   + std::to_string(bh[0]) + ") holds elements of type '"
                   + info->name + "', of dimension "
                   + std::to_string(info->dim) + ": a block's entity "
                     "dimension must be its elements' dimension");
            }
            if
            (
                m.entities
             && !m.entityPhysicals.count({int(bh[0]), int(bh[1])})
            )
            {
                fail("element block of entity " + entity + " not in "
                     "$Entities: every block's entity (dimension, tag) must "
                     "be declared there, with its physical groups");
            }
            const std::size_t ne = count(bh[3], "element count");
            int nn = -1;
            for (std::size_t k = 0; k < ne; ++k)
            {
                const auto v = integers(need("Elements"), "element tag and "
                    "node tags");
                if (v.size() < 2 || (nn >= 0 && int(v.size()) - 1 != nn))
                {
                    fail("element line with " + std::to_string(v.size())
                       + " numbers in a block of type "
                       + typeName(blk.type));
                }
                nn = int(v.size()) - 1;
                blk.tags.push_back(tag(v[0]));
                for (int a = 1; a <= nn; ++a) blk.nodes.push_back(tag(v[a]));
            }
            m.elements[{int(bh[0]), int(bh[1])}].push_back(std::move(blk));
            total += ne;
        }
        if (total != count(h[1], "element count"))
        {
            fail("$Elements announces " + std::to_string(h[1])
               + " elements, its blocks hold " + std::to_string(total));
        }
        expectEnd("Elements");
    }

    // MSH 2.2: one line per node and per element; the first element tag is
    // the physical group, the second the geometric entity

    void nodes22(MshModel& m)
    {
        const std::size_t n =
            count(integers(need("Nodes"), "count", 1)[0], "node count");
        for (std::size_t i = 0; i < n; ++i)
        {
            const std::string s = need("Nodes");
            const char* p = s.c_str();
            char* end;
            const long long t = std::strtoll(p, &end, 10);
            if (end == p) fail("expected 'tag x y z', read '" + s + "'");
            m.nodeTags.push_back(tag(t));
            m.nodeX.push_back(coordinates(end, tag(t)));
        }
        expectEnd("Nodes");
    }

    void elements22(MshModel& m)
    {
        const std::size_t n =
            count(integers(need("Elements"), "count", 1)[0], "element count");
        // An element of several physical groups is written once per group:
        // keep it once per entity
        std::map<std::pair<int, int>, std::set<std::size_t>> seen;
        for (std::size_t i = 0; i < n; ++i)
        {
            const auto v = integers(need("Elements"), "tag type numTags "
                "tags... nodes...");
            if (v.size() < 3 || v[2] < 0 || std::size_t(v[2]) >= v.size() - 3)
            {
                fail("malformed element line (tag type numTags tags... "
                     "nodes...)");
            }
            const int type = int(v[1]);
            const ElementTypeInfo* info = typeInfo(type);
            if (!info) fail("unsupported element type " + std::to_string(type));
            const int phys = v[2] > 0 ? int(v[3]) : 0;
            const int ent = v[2] > 1 ? int(v[4]) : 0;
            const std::pair<int, int> key{info->dim, ent};
            if (phys != 0) m.entityPhysicals[key].insert(std::abs(phys));
            if (!seen[key].insert(tag(v[0])).second) continue;
            auto& blocks = m.elements[key];
            const std::size_t nn = v.size() - 3 - v[2];
            if
            (
                blocks.empty() || blocks.back().type != type
             || blocks.back().nodes.size() != nn*blocks.back().tags.size()
            )
            {
                blocks.push_back(ElementBlock{type, {}, {}});
            }
            blocks.back().tags.push_back(tag(v[0]));
            for (std::size_t a = 3 + v[2]; a < v.size(); ++a)
            {
                blocks.back().nodes.push_back(tag(v[a]));
            }
        }
        expectEnd("Elements");
    }

    //- The whole file
    MshModel read()
    {
        MshModel m;
        std::string s;
        if (!next(s) || s != "$MeshFormat")
        {
            fail("not a gmsh MSH file (it must start with $MeshFormat)");
        }
        s = need("MeshFormat");
        std::istringstream fs(s);
        std::string version;
        int binary = -1, dsize = 0;
        fs >> version >> binary >> dsize;
        const bool v41 = version == "4.1";
        const bool v22 = version.size() >= 2 && version.substr(0, 2) == "2.";
        if (!fs || binary != 0 || !(v41 || v22))
        {
            fail("MSH '" + s + "' is not read: the solid reads ASCII MSH 4.1 "
                 "and 2.2 (convert with: gmsh " + file_ + " -0 -format msh41"
                 " -o other.msh)");
        }
        expectEnd("MeshFormat");
        bool haveNodes = false, haveElements = false;
        while (next(s))
        {
            if (s.empty()) continue;
            if (s[0] != '$') fail("expected a section ($Name), read '" + s + "'");
            const std::string section = s.substr(1);
            if (section == "PhysicalNames") physicalNames(m);
            else if (section == "Entities" && v41) entities41(m);
            else if (section == "Nodes")
            {
                v41 ? nodes41(m) : nodes22(m);
                haveNodes = true;
            }
            else if (section == "Elements")
            {
                v41 ? elements41(m) : elements22(m);
                haveElements = true;
            }
            else if (section == "PartitionedEntities")
            {
                fail("partitioned meshes are not read (save the mesh "
                     "unpartitioned)");
            }
            else skip(section);
        }
        if (!haveNodes || !haveElements)
        {
            fail(std::string("the file has no $")
               + (haveNodes ? "Elements" : "Nodes") + " section");
        }
        return m;
    }
};

} // namespace


solid::Mesh solid::readGmsh(const std::string& fileName, double scale)
{
    // A FIFO (or socket, device) would block the open; a directory opens
    // and reads as nothing; a file beyond any mesh's size is no mesh: said
    // as such (src/foamTools/fileKind.H, the project's one look)
    const std::string refusal
    (
        fileKind::readRefusal(fileName, fileKind::meshLimit, "gmsh mesh")
    );
    if (!refusal.empty())
    {
        throw SolidError
        (
            SolidError::Kind::io, "cannot open gmsh file: " + refusal
        );
    }
    MshParser parser(fileName);
    if (!parser.good())
    {
        throw SolidError
        (
            SolidError::Kind::io, "cannot open gmsh file '" + fileName + "'"
        );
    }
    const MshModel msh = parser.read();

    const auto groups = msh.groups();
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

    // One name per physical group: a face or node set named like a region
    // (names swapped or copied between groups) would otherwise share its
    // node set, which the later group replaced silently (issue 19, class
    // 4: 'fixed (cytoplasm 0)' fixed the whole cytoplasm)
    const auto kind = [dim](int d)
    {
        return std::to_string(d) + "D group ("
          + (d == dim ? "a region" : d == dim - 1 ? "boundary faces" : "nodes")
          + ")";
    };
    std::map<std::string, std::pair<int, int>> named;
    for (const auto& g : groups)
    {
        const auto nameIt = msh.physicalNames.find(g);
        if (nameIt == msh.physicalNames.end() || nameIt->second.empty())
        {
            continue;
        }
        const auto first = named.emplace(nameIt->second, g);
        if (!first.second)
        {
            const std::pair<int, int>& h = first.first->second;
            throw SolidError
            (
                SolidError::Kind::mesh, "gmsh file '" + fileName
              + "': the physical name '" + nameIt->second + "' is given to "
                "two physical groups, the " + kind(h.first) + " of tag "
              + std::to_string(h.second) + " and the " + kind(g.first)
              + " of tag " + std::to_string(g.second) + "; every physical "
                "group needs its own name (names swapped or copied between "
                "groups?)"
            );
        }
    }

    Mesh mesh;
    mesh.type = dim == 2 ? ElementType::quad4Axi : ElementType::hex8;
    const int wanted = dim == 2 ? gmshQuad4 : gmshHex8;
    const int nen = mesh.nen();

    // An axisymmetric (2D) mesh lies in the plane z = 0: a mesh in another
    // plane was projected onto it silently (adv32 g22: every node at
    // z = y/2 ran as the planar mesh). Round-off allowed: 1e-6 of the
    // mesh's extent in r and z (gmsh's geometric tolerance is below 1e-8
    // of a cell)
    if (dim == 2 && !msh.nodeX.empty())
    {
        Vec3 lo(msh.nodeX[0]), hi(msh.nodeX[0]);
        for (const Vec3& x : msh.nodeX)
        {
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
        }
        const double tol = 1e-6*std::max(hi(0) - lo(0), hi(1) - lo(1));
        for (std::size_t i = 0; i < msh.nodeX.size(); ++i)
        {
            const Vec3& x = msh.nodeX[i];
            if (std::abs(x(2)) > tol)
            {
                std::ostringstream os;
                os  << "gmsh file '" << fileName << "': node "
                    << msh.nodeTags[i] << " at (" << x.transpose()
                    << ") is not in the plane z = 0 of an axisymmetric (2D)"
                    << " mesh (r, z, 0): |z| must be at most " << tol
                    << " (1e-6 of the mesh's extent, in the file's units)";
                throw SolidError(SolidError::Kind::mesh, os.str());
            }
        }
    }

    std::map<std::size_t, int> index;
    for (std::size_t i = 0; i < msh.nodeTags.size(); ++i)
    {
        const Vec3& x = msh.nodeX[i];
        const auto it = index.find(msh.nodeTags[i]);
        if (it != index.end())
        {
            // Which of the two would the elements use? (was: the first,
            // silently; issue 19, adversarial pass 'dupNodeTag')
            std::ostringstream os;
            os  << "gmsh file '" << fileName << "': node "
                << msh.nodeTags[i] << " is defined twice (at ("
                << msh.nodeX[it->second].transpose() << ") and at ("
                << x.transpose() << ")); every node tag must be defined once";
            throw SolidError(SolidError::Kind::mesh, os.str());
        }
        index[msh.nodeTags[i]] = int(mesh.X.size());
        mesh.X.push_back(scale*Vec3(x(0), x(1), dim == 2 ? 0.0 : x(2)));
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
        const auto nameIt = msh.physicalNames.find(g);
        const std::string name =
            nameIt == msh.physicalNames.end() || nameIt->second.empty()
          ? "region" + std::to_string(g.second) : nameIt->second;
        std::set<int> nodes;
        int regionId = -1;
        if (gdim == dim)
        {
            regionId = int(mesh.regionNames.size());
            mesh.regionNames.push_back(name);
        }
        for (const auto& ent : msh.entityPhysicals)
        {
            if (ent.first.first != gdim || !ent.second.count(g.second))
            {
                continue;
            }
            const auto blocks = msh.elements.find(ent.first);
            if (blocks == msh.elements.end()) continue;
            for (const ElementBlock& b : blocks->second)
            {
                const std::size_t ne = b.tags.size();
                if (ne == 0) continue;
                const std::size_t nn = b.nodes.size()/ne;
                if (nn*ne != b.nodes.size())
                {
                    throw SolidError
                    (
                        SolidError::Kind::mesh, "gmsh file '" + fileName
                      + "': elements of type '" + typeName(b.type)
                      + "' with different node counts"
                    );
                }
                const auto needNodes = [&](std::size_t want)
                {
                    if (nn != want)
                    {
                        throw SolidError
                        (
                            SolidError::Kind::mesh, "gmsh file '" + fileName
                          + "': element " + std::to_string(b.tags[0])
                          + " of type '" + typeName(b.type) + "' has "
                          + std::to_string(nn) + " nodes, expected "
                          + std::to_string(want)
                        );
                    }
                };
                for (std::size_t k : b.nodes) nodes.insert(node(k));
                if (gdim == dim)
                {
                    if (b.type != wanted)
                    {
                        throw SolidError
                        (
                            SolidError::Kind::mesh, "gmsh file '" + fileName
                          + "': region '" + name + "' contains "
                          + std::to_string(ne) + " elements of type '"
                          + typeName(b.type) + "'; the solid needs "
                          + (dim == 2 ? "4-node quadrilaterals (recombine)"
                                      : "8-node hexahedra")
                        );
                    }
                    needNodes(nen);
                    for (std::size_t k = 0; k < ne; ++k)
                    {
                        if (!seen.insert(b.tags[k]).second)
                        {
                            throw SolidError
                            (
                                SolidError::Kind::mesh, "gmsh file '"
                              + fileName + "': element "
                              + std::to_string(b.tags[k])
                              + " belongs to two regions (second: '"
                              + name + "')"
                            );
                        }
                        // A node given twice: a degenerate element (was
                        // read, and run, silently; issue 19, adversarial
                        // pass 'repeatedNodeQuad')
                        std::set<std::size_t> distinct;
                        for (int a = 0; a < nen; ++a)
                        {
                            const std::size_t t = b.nodes[nn*k + a];
                            if (!distinct.insert(t).second)
                            {
                                throw SolidError
                                (
                                    SolidError::Kind::mesh, "gmsh file '"
                                  + fileName + "': element "
                                  + std::to_string(b.tags[k]) + " of region"
                                    " '" + name + "' lists node "
                                  + std::to_string(t) + " twice (a "
                                    "degenerate element; each of its "
                                  + std::to_string(nen) + " nodes must be "
                                    "distinct)"
                                );
                            }
                        }
                        for (int a = 0; a < nen; ++a)
                        {
                            mesh.conn.push_back(node(b.nodes[nn*k + a]));
                        }
                        mesh.region.push_back(regionId);
                    }
                }
                else if
                (
                    gdim == dim - 1
                 && b.type == (dim == 2 ? gmshLine2 : gmshQuad4)
                )
                {
                    const int nf = nodesPerFace(mesh.type);
                    needNodes(nf);
                    for (std::size_t k = 0; k < ne; ++k)
                    {
                        std::vector<int> f(nf);
                        for (int a = 0; a < nf; ++a)
                            f[a] = node(b.nodes[nn*k + a]);
                        mesh.faceSets[name].push_back(f);
                    }
                }
            }
        }
        mesh.nodeSets[name].assign(nodes.begin(), nodes.end());
    }
    if (mesh.conn.empty())
    {
        throw SolidError
        (
            SolidError::Kind::mesh, "gmsh file '" + fileName + "': the "
          + std::to_string(dim) + "D physical groups hold no elements"
        );
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
    {
        for (auto& f : s.second)
        {
            for (int& n : f)
            {
                if (newId[n] < 0)
                {
                    throw SolidError
                    (
                        SolidError::Kind::mesh, "gmsh file '" + fileName
                      + "': a face of the boundary group '" + s.first
                      + "' has a node that belongs to no "
                      + std::to_string(dim) + "D element"
                    );
                }
                n = newId[n];
            }
        }
    }

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
