#include "meshQuality.H"
#include "mathematicalConstants.H"
#include "vector.H"
#include "FixedList.H"
#include <gmsh.h>
#include <unordered_map>

using Foam::constant::mathematical::pi;

namespace
{

// gmsh element types
const int gmshQuad4 = 3;
const int gmshHex8 = 5;

// Corner neighbours of the gmsh hexahedron, ordered so that the triple
// product is positive for a valid element
const int hexCorner[8][3] =
{
    {1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
    {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}
};

const int hexEdge[12][2] =
{
    {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
    {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}
};

}


Foam::meshQuality::meshQuality(int dim, scalar scale)
:
    dim_(dim)
{
    std::vector<std::size_t> tags;
    std::vector<double> xyz, par;
    gmsh::model::mesh::getNodes(tags, xyz, par, -1, -1, true, false);
    std::unordered_map<std::size_t, vector> X;
    for (std::size_t i = 0; i < tags.size(); ++i)
    {
        X[tags[i]] = scale*vector(xyz[3*i], xyz[3*i + 1], xyz[3*i + 2]);
    }

    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, dim);
    for (const auto& g : groups)
    {
        regionStats s;
        std::string name;
        gmsh::model::getPhysicalName(g.first, g.second, name);
        s.name = name;
        std::vector<int> ents;
        gmsh::model::getEntitiesForPhysicalGroup(g.first, g.second, ents);
        for (const int ent : ents)
        {
            std::vector<int> types;
            std::vector<std::vector<std::size_t>> etags, ntags;
            gmsh::model::mesh::getElements(types, etags, ntags, dim, ent);
            for (std::size_t t = 0; t < types.size(); ++t)
            {
                const int wanted = dim == 2 ? gmshQuad4 : gmshHex8;
                if (types[t] != wanted)
                {
                    s.nOtherType += label(etags[t].size());
                    continue;
                }
                const int nen = dim == 2 ? 4 : 8;
                for (std::size_t k = 0; k < etags[t].size(); ++k)
                {
                    FixedList<vector, 8> x;
                    for (int i = 0; i < nen; ++i)
                    {
                        x[i] = X.at(ntags[t][nen*k + i]);
                    }
                    scalar lo = GREAT, hi = 0, jac = GREAT;
                    if (dim == 2)
                    {
                        for (int i = 0; i < 4; ++i)
                        {
                            const vector e1 = x[(i + 1) % 4] - x[i];
                            const vector e2 = x[(i + 3) % 4] - x[i];
                            lo = min(lo, mag(e1));
                            hi = max(hi, mag(e1));
                            jac = min
                            (
                                jac,
                                (e1.x()*e2.y() - e1.y()*e2.x())
                               /(mag(e1)*mag(e2) + VSMALL)
                            );
                        }
                        // Two triangles (0,1,2), (0,2,3): area and Pappus
                        scalar A = 0, V = 0;
                        for (const int j : {1, 2})
                        {
                            const vector u = x[j] - x[0];
                            const vector w = x[j + 1] - x[0];
                            const scalar At = 0.5*(u.x()*w.y() - u.y()*w.x());
                            A += At;
                            V += 2*pi*At*(x[0].x() + x[j].x() + x[j + 1].x())
                                /3;
                        }
                        s.measure += mag(A);
                        s.revolved += mag(V);
                    }
                    else
                    {
                        for (const auto& e : hexEdge)
                        {
                            const scalar l = mag(x[e[1]] - x[e[0]]);
                            lo = min(lo, l);
                            hi = max(hi, l);
                        }
                        for (int i = 0; i < 8; ++i)
                        {
                            const vector e1 = x[hexCorner[i][0]] - x[i];
                            const vector e2 = x[hexCorner[i][1]] - x[i];
                            const vector e3 = x[hexCorner[i][2]] - x[i];
                            jac = min
                            (
                                jac,
                                (e1 & (e2 ^ e3))
                               /(mag(e1)*mag(e2)*mag(e3) + VSMALL)
                            );
                        }
                        // 2x2x2 Gauss of det(dx/dxi) of the trilinear map
                        const scalar g = 1/sqrt(3.0);
                        const scalar sxi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
                        const scalar set[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
                        const scalar sze[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
                        scalar V = 0;
                        for (int q = 0; q < 8; ++q)
                        {
                            const scalar xi = g*sxi[q], et = g*set[q],
                                ze = g*sze[q];
                            vector dxi(Zero), det(Zero), dze(Zero);
                            for (int i = 0; i < 8; ++i)
                            {
                                dxi += 0.125*sxi[i]*(1 + et*set[i])
                                    *(1 + ze*sze[i])*x[i];
                                det += 0.125*set[i]*(1 + xi*sxi[i])
                                    *(1 + ze*sze[i])*x[i];
                                dze += 0.125*sze[i]*(1 + xi*sxi[i])
                                    *(1 + et*set[i])*x[i];
                            }
                            V += dxi & (det ^ dze);
                        }
                        s.measure += mag(V);
                    }
                    s.nElements++;
                    s.minEdge = min(s.minEdge, lo);
                    s.maxEdge = max(s.maxEdge, hi);
                    s.maxAspect = max(s.maxAspect, hi/lo);
                    s.minScaledJacobian = min(s.minScaledJacobian, jac);
                }
            }
        }
        regions_.append(s);
    }
}


Foam::meshQuality::regionStats Foam::meshQuality::total() const
{
    regionStats all;
    all.name = "total";
    for (const regionStats& s : regions_)
    {
        all.nElements += s.nElements;
        all.nOtherType += s.nOtherType;
        all.minEdge = min(all.minEdge, s.minEdge);
        all.maxEdge = max(all.maxEdge, s.maxEdge);
        all.maxAspect = max(all.maxAspect, s.maxAspect);
        all.minScaledJacobian = min(all.minScaledJacobian, s.minScaledJacobian);
        all.measure += s.measure;
        all.revolved += s.revolved;
    }
    return all;
}


void Foam::meshQuality::write(Ostream& os) const
{
    os  << "Mesh quality (" << (dim_ == 2 ? "quadrilaterals" : "hexahedra")
        << "; edges in m, " << (dim_ == 2 ? "area m^2, revolved m^3"
                                          : "volume m^3") << ")" << nl
        << "    region  elements  minEdge  maxEdge  maxAspectRatio"
        << "  minScaledJacobian  " << (dim_ == 2 ? "area  revolvedVolume"
                                                 : "volume") << nl;
    List<regionStats> rows(regions_);
    rows.append(total());
    for (const regionStats& s : rows)
    {
        os  << "    " << s.name << "  " << s.nElements << "  " << s.minEdge
            << "  " << s.maxEdge << "  " << s.maxAspect << "  "
            << s.minScaledJacobian << "  " << s.measure;
        if (dim_ == 2)
        {
            os  << "  " << s.revolved;
        }
        os  << nl;
    }
}
