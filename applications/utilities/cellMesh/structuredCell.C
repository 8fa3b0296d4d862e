#include "structuredCell.H"
#include "mathematicalConstants.H"
#include <gmsh.h>
#include <algorithm>
#include <cmath>
#include <string>

using Foam::constant::mathematical::pi;

namespace
{

// The elements of the whole structured mesh, n, counted in closed form
// before any block is made (structuredCell::countBeforeBuilding), against
// maxElements (adv49b i03: a quarter with azimuthSize 1e-8 built hexahedra
// for 900 s, 2 GB and growing; i02, i55: counts above maxElements
// written; i55 (d): refused block by block only after 116 s and 1.43 GB,
// with a partial count). The blocks' counts couple across the regions,
// so the bound from the sizes checked before meshing (cellGeometry) can
// be far below them
void refuseAboveMaxElements
(
    const Foam::cellGeometry& geom,
    const std::size_t n,
    const char* what
)
{
    using namespace Foam;
    if (double(n) <= double(geom.maxElements()))
    {
        return;
    }
    FatalErrorInFunction
        << "the structured mesh (meshType structured) would have "
        << std::to_string(n).c_str() << " "
        << what << " (counted before any is made), more than maxElements "
        << geom.maxElements()
        << " (" << geom.file().c_str() << ")"
        << ": its blocks' counts couple across the regions (a fine "
        << "membraneSize or azimuthSize refines the blocks beside them), "
        << "so the count from the sizes checked before meshing was lower "
        << "(nucleusSize " << geom.nucleusSize() << " m, cytoplasmSize "
        << geom.cytoplasmSize() << " m, membraneSize "
        << geom.membraneSize() << " m";
    if (!geom.axisymmetric())
    {
        FatalError << ", azimuthSize " << geom.azimuthSize() << " m";
    }
    FatalError
        << ")." << nl << "    Nothing was written: larger sizes, or a "
        << "larger maxElements if that many is meant" << exit(FatalError);
}

} // End anonymous namespace


namespace
{

// Nodes closer than this are one node [m]
const double mergeTol = 1e-12;

// Column radius and butterfly square as fractions of a_n and r_c
const double columnFraction = 0.5;
const double squareFraction = 0.5;

// Nucleus O-grid: ring thickness on the equator as a fraction of
// a_n - r_c, core half-height as a fraction of the local half-height
const double ringFraction = 0.35;
const double coreFraction = 0.55;

// Outward faces of the gmsh hexahedron
const int hexFace[6][4] =
{
    {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
    {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}
};

Foam::label atLeastOne(double x)
{
    return std::max(Foam::label(1), Foam::label(std::ceil(x - 1e-9)));
}

double centreJacobian(const std::array<Foam::structuredCell::vec, 8>& x)
{
    double J[3][3];
    for (int k = 0; k < 3; ++k)
    {
        J[k][0] = 0.25*((x[1][k] + x[2][k] + x[5][k] + x[6][k])
                      - (x[0][k] + x[3][k] + x[4][k] + x[7][k]));
        J[k][1] = 0.25*((x[2][k] + x[3][k] + x[6][k] + x[7][k])
                      - (x[0][k] + x[1][k] + x[4][k] + x[5][k]));
        J[k][2] = 0.25*((x[4][k] + x[5][k] + x[6][k] + x[7][k])
                      - (x[0][k] + x[1][k] + x[2][k] + x[3][k]));
    }
    return J[0][0]*(J[1][1]*J[2][2] - J[1][2]*J[2][1])
         - J[0][1]*(J[1][0]*J[2][2] - J[1][2]*J[2][0])
         + J[0][2]*(J[1][0]*J[2][1] - J[1][1]*J[2][0]);
}

}


Foam::scalar Foam::structuredCell::innerTheta(scalar r) const
{
    // r of the inner parallel curve increases with theta (t below the
    // smallest radius of curvature)
    scalar lo = 0, hi = 0.5*pi;
    for (int it = 0; it < 100; ++it)
    {
        const scalar mid = 0.5*(lo + hi);
        (g_.inner(mid).first() < r ? lo : hi) = mid;
    }
    return 0.5*(lo + hi);
}


Foam::scalar Foam::structuredCell::innerZ(scalar r) const
{
    return g_.inner(innerTheta(r)).second();
}


std::vector<Foam::scalar> Foam::structuredCell::levels(scalar r) const
{
    const scalar q = std::sqrt(std::max(scalar(0), 1 - sqr(r/g_.an())));
    // The scaled cell's nucleus stands on the substrate
    const scalar z1 = g_.scaledNucleus() ? 0 : g_.zn() - g_.cn()*q;
    const scalar z2 = g_.zn() + g_.cn()*q;
    const scalar z3 = innerZ(r);
    const scalar z4 = g_.H()*std::sqrt(std::max(scalar(0), 1 - sqr(r/g_.a())));
    std::vector<scalar> z;
    for (label k = 0; k < nGapBottom_; ++k) z.push_back(z1*k/nGapBottom_);
    const auto nucleus = [&](scalar l0, scalar l1, label n)
    {
        for (label k = 0; k < n; ++k)
        {
            z.push_back(z1 + (z2 - z1)*(l0 + (l1 - l0)*k/n));
        }
    };
    nucleus(0, lambda1_, nRingBottom_);
    nucleus(lambda1_, lambda2_, nCoreV_);
    nucleus(lambda2_, 1, nRingN_);
    for (label k = 0; k < nGap_; ++k) z.push_back(z2 + (z3 - z2)*k/nGap_);
    const label L = g_.layers();
    for (label k = 0; k <= L; ++k) z.push_back(z3 + (z4 - z3)*k/L);
    return z;
}


Foam::structuredCell::vec2 Foam::structuredCell::nucleusPoint
(
    scalar psi
) const
{
    return {g_.an()*std::sin(psi), g_.zn() - g_.cn()*std::cos(psi)};
}


Foam::structuredCell::block2D Foam::structuredCell::coons
(
    const std::vector<vec2>& s0,
    const std::vector<vec2>& s1,
    const std::vector<vec2>& t0,
    const std::vector<vec2>& t1
)
{
    block2D b;
    b.ni = label(s0.size()) - 1;
    b.nj = label(t0.size()) - 1;
    b.p.resize((b.ni + 1)*(b.nj + 1));
    for (label j = 0; j <= b.nj; ++j)
    {
        const double v = double(j)/b.nj;
        for (label i = 0; i <= b.ni; ++i)
        {
            const double u = double(i)/b.ni;
            for (int k = 0; k < 2; ++k)
            {
                b.at(i, j)[k] =
                    (1 - v)*s0[i][k] + v*s1[i][k]
                  + (1 - u)*t0[j][k] + u*t1[j][k]
                  - (1 - u)*(1 - v)*s0[0][k] - u*(1 - v)*s0[b.ni][k]
                  - (1 - u)*v*s1[0][k] - u*v*s1[b.ni][k];
            }
        }
    }
    return b;
}


Foam::structuredCell::block2D Foam::structuredCell::ruled
(
    const std::vector<vec2>& s0,
    const std::vector<vec2>& s1,
    label nj
)
{
    block2D b;
    b.ni = label(s0.size()) - 1;
    b.nj = nj;
    b.p.resize((b.ni + 1)*(b.nj + 1));
    for (label j = 0; j <= nj; ++j)
    {
        const double v = double(j)/nj;
        for (label i = 0; i <= b.ni; ++i)
        {
            for (int k = 0; k < 2; ++k)
            {
                b.at(i, j)[k] = s0[i][k] + v*(s1[i][k] - s0[i][k]);
            }
        }
    }
    return b;
}


std::vector<Foam::structuredCell::vec2> Foam::structuredCell::segment
(
    const vec2& a,
    const vec2& b,
    label n
)
{
    std::vector<vec2> p(n + 1);
    for (label i = 0; i <= n; ++i)
    {
        const double u = double(i)/n;
        p[i] = {a[0] + u*(b[0] - a[0]), a[1] + u*(b[1] - a[1])};
    }
    return p;
}


std::size_t Foam::structuredCell::node(vec x)
{
    for (double& c : x)
    {
        if (std::abs(c) < mergeTol) c = 0;
    }
    key q;
    for (int k = 0; k < 3; ++k) q[k] = std::llround(x[k]/mergeTol);
    auto it = index_.find(q);
    if (it != index_.end()) return it->second;
    // A point within mergeTol of an existing one may round to a
    // neighbouring cell of the quantisation grid
    for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
    for (int dz = -1; dz <= 1; ++dz)
    {
        it = index_.find(key{q[0] + dx, q[1] + dy, q[2] + dz});
        if (it != index_.end()) return it->second;
    }
    index_[q] = nodes_.size();
    nodes_.push_back(x);
    return nodes_.size() - 1;
}


void Foam::structuredCell::addBlock
(
    const std::vector<std::array<vec, 8>>& h,
    int region
)
{
    double sum = 0;
    for (const auto& x : h) sum += centreJacobian(x);
    const bool flip = sum < 0;
    for (const auto& x : h)
    {
        hex e;
        for (int k = 0; k < 8; ++k)
        {
            e[k] = node(x[flip ? (k + 4) % 8 : k]);
        }
        hexes_.push_back(e);
        region_.push_back(region);
    }
}


void Foam::structuredCell::revolve(const block2D& b, int region)
{
    // Azimuth nodes: those of the butterfly's outer circle
    const label nPhi = quarter_ ? nSq_ : 4*nSq_;
    std::vector<std::array<vec, 8>> h;
    for (label l = 0; l < nPhi; ++l)
    {
        const double p0 = 0.5*pi*l/nSq_, p1 = 0.5*pi*(l + 1)/nSq_;
        const auto at = [&](label i, label j, double phi) -> vec
        {
            const vec2& x = b.at(i, j);
            return {x[0]*std::cos(phi), x[0]*std::sin(phi), x[1]};
        };
        for (label j = 0; j < b.nj; ++j)
        for (label i = 0; i < b.ni; ++i)
        {
            h.push_back
            ({
                at(i, j, p0), at(i + 1, j, p0), at(i + 1, j + 1, p0),
                at(i, j + 1, p0), at(i, j, p1), at(i + 1, j, p1),
                at(i + 1, j + 1, p1), at(i, j + 1, p1)
            });
        }
    }
    addBlock(h, region);
}


void Foam::structuredCell::column()
{
    // Butterfly: square [-s, s]^2 and four ring blocks to the circle r_c;
    // ring block k faces the direction k pi/2, its arc from
    // k pi/2 - pi/4 to k pi/2 + pi/4
    std::vector<block2D> disc;
    {
        const vec2 c0{-s_, -s_}, c1{s_, -s_}, c3{-s_, s_}, c2{s_, s_};
        disc.push_back
        (
            coons
            (
                segment(c0, c1, nSq_), segment(c3, c2, nSq_),
                segment(c0, c3, nSq_), segment(c1, c2, nSq_)
            )
        );
    }
    for (int k = 0; k < 4; ++k)
    {
        const double th = 0.5*pi*k;
        const double c = std::cos(th), s = std::sin(th);
        // Square side facing direction th, from its -45 to its +45 corner
        const vec2 a{s_*(c + s), s_*(s - c)}, b{s_*(c - s), s_*(s + c)};
        const std::vector<vec2> side = segment(a, b, nSq_);
        std::vector<vec2> arc(nSq_ + 1);
        for (label i = 0; i <= nSq_; ++i)
        {
            const double phi = th - 0.25*pi + 0.5*pi*i/nSq_;
            arc[i] = {rc_*std::cos(phi), rc_*std::sin(phi)};
        }
        block2D r;
        r.ni = nSq_;
        r.nj = nRing_;
        r.p.resize((r.ni + 1)*(r.nj + 1));
        for (label j = 0; j <= nRing_; ++j)
        for (label i = 0; i <= nSq_; ++i)
        {
            const double v = double(j)/nRing_;
            r.at(i, j) =
            {
                side[i][0] + v*(arc[i][0] - side[i][0]),
                side[i][1] + v*(arc[i][1] - side[i][1])
            };
        }
        disc.push_back(r);
    }

    // Vertical lines: every level interval
    const label k4 =
        nGapBottom_ + nRingBottom_ + nCoreV_ + nRingN_ + nGap_ + g_.layers();
    for (const block2D& b : disc)
    {
        std::vector<std::vector<scalar>> z(b.p.size());
        for (std::size_t n = 0; n < b.p.size(); ++n)
        {
            z[n] = levels(std::hypot(b.p[n][0], b.p[n][1]));
        }
        std::vector<std::array<vec, 8>> h[3];
        for (label j = 0; j < b.nj; ++j)
        for (label i = 0; i < b.ni; ++i)
        {
            const label c[4] =
            {
                j*(b.ni + 1) + i, j*(b.ni + 1) + i + 1,
                (j + 1)*(b.ni + 1) + i + 1, (j + 1)*(b.ni + 1) + i
            };
            double cx = 0, cy = 0;
            for (const label n : c)
            {
                cx += b.p[n][0];
                cy += b.p[n][1];
            }
            if (quarter_ && (cx < 0 || cy < 0)) continue;
            for (label k = 0; k < k4; ++k)
            {
                std::array<vec, 8> x;
                for (int m = 0; m < 4; ++m)
                {
                    const vec2& p = b.p[c[m]];
                    x[m] = {p[0], p[1], z[c[m]][k]};
                    x[m + 4] = {p[0], p[1], z[c[m]][k + 1]};
                }
                h[levelRegion(k)].push_back(x);
            }
        }
        for (int r = 0; r < 3; ++r) addBlock(h[r], r);
    }
}


int Foam::structuredCell::levelRegion(label k) const
{
    // Level index ranges of the regions: cytoplasm gap under the nucleus,
    // nucleus, cytoplasm gap above it, membrane
    const label nNuc = nRingBottom_ + nCoreV_ + nRingN_;
    const label k1 = nGapBottom_, k2 = k1 + nNuc, k3 = k2 + nGap_;
    return k < k1 || (k >= k2 && k < k3)
        ? cytoplasmRegion
        : k < k2 ? nucleusRegion : membraneRegion;
}


void Foam::structuredCell::addQuads(const block2D& b, int region)
{
    std::vector<std::array<vec2, 4>> q;
    double sum = 0;
    for (label j = 0; j < b.nj; ++j)
    for (label i = 0; i < b.ni; ++i)
    {
        const std::array<vec2, 4> x
        {
            b.at(i, j), b.at(i + 1, j), b.at(i + 1, j + 1), b.at(i, j + 1)
        };
        // Twice the area of the quadrilateral (its diagonals' product)
        sum +=
            (x[2][0] - x[0][0])*(x[3][1] - x[1][1])
          - (x[2][1] - x[0][1])*(x[3][0] - x[1][0]);
        q.push_back(x);
    }
    // One block has one orientation; a single inverted element stays
    // inverted and is reported by the quality check
    const bool flip = sum < 0;
    for (const auto& x : q)
    {
        quad e;
        for (int k = 0; k < 4; ++k)
        {
            const vec2& p = x[flip ? (4 - k) % 4 : k];
            e[k] = node({p[0], p[1], 0});
        }
        quads_.push_back(e);
        region_.push_back(region);
    }
}


void Foam::structuredCell::sectionBlock(const block2D& b, int region)
{
    pending_.push_back({b, region});
}


void Foam::structuredCell::smoothSection()
{
    // The union of the pending blocks as one quadrilateral mesh: node ids
    // by quantised position (the blocks share their interface nodes'
    // formulas, so equal points are equal to within mergeTol)
    std::vector<vec2> X;
    std::vector<std::vector<std::size_t>> ids(pending_.size());
    {
        std::map<std::pair<long long, long long>, std::size_t> at;
        const auto id = [&](const vec2& x)
        {
            const long long q0 = std::llround(x[0]/mergeTol);
            const long long q1 = std::llround(x[1]/mergeTol);
            for (int d0 = -1; d0 <= 1; ++d0)
            for (int d1 = -1; d1 <= 1; ++d1)
            {
                const auto it = at.find({q0 + d0, q1 + d1});
                if (it != at.end()) return it->second;
            }
            at[{q0, q1}] = X.size();
            X.push_back(x);
            return X.size() - 1;
        };
        for (std::size_t b = 0; b < pending_.size(); ++b)
        {
            for (const vec2& x : pending_[b].first.p)
            {
                ids[b].push_back(id(x));
            }
        }
    }
    const std::size_t nNodes = X.size();

    // Quadrilaterals, counter-clockwise, with their regions
    std::vector<quad> Q;
    std::vector<int> R;
    const auto area2 = [&](const quad& q)
    {
        return (X[q[2]][0] - X[q[0]][0])*(X[q[3]][1] - X[q[1]][1])
             - (X[q[2]][1] - X[q[0]][1])*(X[q[3]][0] - X[q[1]][0]);
    };
    for (std::size_t b = 0; b < pending_.size(); ++b)
    {
        const block2D& bl = pending_[b].first;
        const auto n = [&](label i, label j)
        {
            return ids[b][j*(bl.ni + 1) + i];
        };
        for (label j = 0; j < bl.nj; ++j)
        for (label i = 0; i < bl.ni; ++i)
        {
            quad q{n(i, j), n(i + 1, j), n(i + 1, j + 1), n(i, j + 1)};
            if (area2(q) < 0) std::swap(q[1], q[3]);
            Q.push_back(q);
            R.push_back(pending_[b].second);
        }
    }

    // Node roles: fixed (the union's boundary, the membrane's nodes),
    // sliding (nucleus-cytoplasm interface), free
    std::vector<label> valence(nNodes, 0);
    std::vector<bool> fixed(nNodes, false), inNuc(nNodes, false),
        inCyt(nNodes, false);
    std::map<std::pair<std::size_t, std::size_t>, label> edgeUse;
    for (std::size_t e = 0; e < Q.size(); ++e)
    {
        for (int k = 0; k < 4; ++k)
        {
            const std::size_t a = Q[e][k], b = Q[e][(k + 1) % 4];
            ++edgeUse[{std::min(a, b), std::max(a, b)}];
            ++valence[a];
            if (R[e] == membraneRegion) fixed[a] = true;
            if (R[e] == nucleusRegion) inNuc[a] = true;
            if (R[e] == cytoplasmRegion) inCyt[a] = true;
        }
    }
    for (const auto& kv : edgeUse)
    {
        if (kv.second == 1)
        {
            fixed[kv.first.first] = fixed[kv.first.second] = true;
        }
    }
    std::vector<bool> slide(nNodes, false);
    for (std::size_t n = 0; n < nNodes; ++n)
    {
        slide[n] = !fixed[n] && inNuc[n] && inCyt[n];
    }
    // A node of 2 elements of one region on the substrate (z = 0) or on
    // the axis (r = 0) slides along it so that the grid line leaving it
    // is normal to it (its coordinate along it that of its edge
    // neighbour off it); the ends of these lines and every other
    // boundary node stay
    std::vector<int> along(nNodes, -1);
    for (std::size_t n = 0; n < nNodes; ++n)
    {
        if
        (
            fixed[n] && valence[n] == 2 && !(inNuc[n] && inCyt[n])
        )
        {
            if (X[n][1] == 0) along[n] = 0;
            else if (section_ && X[n][0] == 0) along[n] = 1;
        }
    }
    for (std::size_t e = 0; e < Q.size(); ++e)
    {
        if (R[e] != membraneRegion) continue;
        for (const std::size_t n : Q[e]) along[n] = -1;
    }

    // Each moving node's stencil: a node of 4 elements its edge
    // neighbours E0..E3 counter-clockwise and the diagonals D0..D3 (Dk
    // between Ek and Ek+1), so that u runs E2 -> E0 and v E3 -> E1; any
    // other its edge neighbours (Laplace)
    struct stencil
    {
        std::size_t n;
        bool winslow;
        std::vector<std::size_t> E, D;
    };
    std::vector<std::vector<std::size_t>> around(nNodes);
    for (std::size_t e = 0; e < Q.size(); ++e)
    {
        for (const std::size_t n : Q[e]) around[n].push_back(e);
    }
    std::vector<stencil> moving;
    smoothFree_ = 0;
    smoothSliding_ = 0;
    std::vector<std::pair<std::size_t, std::size_t>> boundarySliders;
    for (std::size_t n = 0; n < nNodes; ++n)
    {
        if (along[n] < 0) continue;
        // its edge neighbour off the line
        for (const std::size_t e : around[n])
        {
            const quad& q = Q[e];
            const int k = int(std::find(q.begin(), q.end(), n) - q.begin());
            for (const std::size_t m : {q[(k + 1) % 4], q[(k + 3) % 4]})
            {
                if
                (
                    X[m][1 - along[n]] != 0
                 && (boundarySliders.empty() || boundarySliders.back().first != n)
                )
                {
                    boundarySliders.push_back({n, m});
                }
            }
        }
    }
    smoothBoundary_ = boundarySliders.size();
    for (std::size_t n = 0; n < nNodes; ++n)
    {
        if (fixed[n]) continue;
        stencil st{n, valence[n] == 4, {}, {}};
        // (next, diagonal, previous) of n in each of its elements
        std::vector<std::array<std::size_t, 3>> corner;
        for (const std::size_t e : around[n])
        {
            const quad& q = Q[e];
            const int k = int(std::find(q.begin(), q.end(), n) - q.begin());
            corner.push_back({q[(k + 1) % 4], q[(k + 2) % 4], q[(k + 3) % 4]});
        }
        if (st.winslow)
        {
            std::size_t c = 0;
            for (int m = 0; m < 4; ++m)
            {
                st.E.push_back(corner[c][0]);
                st.D.push_back(corner[c][1]);
                const std::size_t prev = corner[c][2];
                std::size_t next = corner.size();
                for (std::size_t k = 0; k < corner.size(); ++k)
                {
                    if (corner[k][0] == prev) next = k;
                }
                if (next == corner.size())
                {
                    FatalErrorInFunction
                        << "the elements around the node at ("
                        << X[n][0] << ", " << X[n][1] << ") m do not "
                        << "close around it" << exit(FatalError);
                }
                c = next;
            }
        }
        else
        {
            for (const auto& cn : corner)
            {
                for (const std::size_t m : {cn[0], cn[2]})
                {
                    if (std::find(st.E.begin(), st.E.end(), m) == st.E.end())
                    {
                        st.E.push_back(m);
                    }
                }
            }
        }
        moving.push_back(st);
        ++(slide[n] ? smoothSliding_ : smoothFree_);
    }

    // The nucleus surface's closest point to x, by Newton on its angle
    // psi from the bottom, from psi0
    const scalar an = g_.an(), cn = g_.cn(), zn = g_.zn();
    std::vector<scalar> psi(nNodes, 0);
    for (std::size_t n = 0; n < nNodes; ++n)
    {
        if (slide[n]) psi[n] = closestNucleusAngle(X[n]);
    }
    const auto project = [&](const vec2& x, scalar& p) -> vec2
    {
        for (int it = 0; it < 20; ++it)
        {
            const scalar s = std::sin(p), c = std::cos(p);
            const vec2 e{an*s, zn - cn*c};
            const vec2 d1{an*c, cn*s}, d2{-an*s, cn*c};
            const scalar f = (e[0] - x[0])*d1[0] + (e[1] - x[1])*d1[1];
            const scalar fp = sqr(d1[0]) + sqr(d1[1])
                + (e[0] - x[0])*d2[0] + (e[1] - x[1])*d2[1];
            const scalar dp = f/max(fp, 0.5*(sqr(d1[0]) + sqr(d1[1])));
            p -= dp;
            if (std::abs(dp) < 1e-14) break;
        }
        return nucleusPoint(p);
    };

    // Gauss-Seidel sweeps until the largest move of a sweep is below
    // 1e-7 of the smallest element size
    const scalar h = min
    (
        min(g_.nucleusSize(), g_.cytoplasmSize()), g_.membraneSize()
    );
    const label maxSweeps = 200000;
    smoothSweeps_ = 0;
    smoothLastMove_ = 0;
    do
    {
        smoothLastMove_ = 0;
        for (const stencil& st : moving)
        {
            vec2 x{0, 0};
            if (st.winslow)
            {
                const auto& E = st.E;
                const auto& D = st.D;
                scalar xu[2], xv[2], xuv[2];
                for (int k = 0; k < 2; ++k)
                {
                    xu[k] = 0.5*(X[E[0]][k] - X[E[2]][k]);
                    xv[k] = 0.5*(X[E[1]][k] - X[E[3]][k]);
                    xuv[k] = 0.25*
                        (X[D[0]][k] - X[D[1]][k] + X[D[2]][k] - X[D[3]][k]);
                }
                const scalar alpha = sqr(xv[0]) + sqr(xv[1]);
                const scalar beta = xu[0]*xv[0] + xu[1]*xv[1];
                const scalar gamma = sqr(xu[0]) + sqr(xu[1]);
                for (int k = 0; k < 2; ++k)
                {
                    x[k] =
                    (
                        alpha*(X[E[0]][k] + X[E[2]][k])
                      + gamma*(X[E[1]][k] + X[E[3]][k])
                      - 2*beta*xuv[k]
                    )/(2*(alpha + gamma));
                }
            }
            else
            {
                for (const std::size_t m : st.E)
                {
                    x[0] += X[m][0]/st.E.size();
                    x[1] += X[m][1]/st.E.size();
                }
            }
            if (slide[st.n]) x = project(x, psi[st.n]);
            smoothLastMove_ = max
            (
                smoothLastMove_,
                std::hypot(x[0] - X[st.n][0], x[1] - X[st.n][1])
            );
            X[st.n] = x;
        }
        for (const auto& nm : boundarySliders)
        {
            const int k = along[nm.first];
            smoothLastMove_ = max
            (
                smoothLastMove_,
                std::abs(X[nm.second][k] - X[nm.first][k])
            );
            X[nm.first][k] = X[nm.second][k];
        }
        ++smoothSweeps_;
        // progress, so that a long smoothing is not silence (adv50b k08:
        // 95,797 sweeps, 74 s CPU, no line between the summary and the
        // end)
        if (smoothSweeps_ % 5000 == 0)
        {
            Info<< "structuredSmoothing elliptic: sweep " << smoothSweeps_
                << " of at most " << maxSweeps << ", largest move "
                << smoothLastMove_ << " m (stops below " << 1e-7*h
                << " m), " << moving.size() << " nodes" << endl;
        }
    } while (smoothLastMove_ > 1e-7*h && smoothSweeps_ < maxSweeps);

    // Every element keeps its orientation
    label inverted = 0;
    for (const quad& q : Q)
    {
        for (int k = 0; k < 4; ++k)
        {
            const vec2& p = X[q[k]];
            const vec2& a = X[q[(k + 1) % 4]];
            const vec2& b = X[q[(k + 3) % 4]];
            if
            (
                (a[0] - p[0])*(b[1] - p[1]) - (a[1] - p[1])*(b[0] - p[0])
             <= 0
            )
            {
                ++inverted;
                break;
            }
        }
    }
    if (inverted)
    {
        FatalErrorInFunction
            << "structuredSmoothing elliptic: " << inverted << " of "
            << Q.size() << " quadrilaterals of the r-z blocks are not convex"
            << " after " << smoothSweeps_ << " sweeps (use "
            << "structuredSmoothing none)" << exit(FatalError);
    }

    for (std::size_t b = 0; b < pending_.size(); ++b)
    {
        block2D& bl = pending_[b].first;
        for (std::size_t k = 0; k < bl.p.size(); ++k) bl.p[k] = X[ids[b][k]];
    }
}


Foam::label Foam::structuredCell::columnElements() const
{
    return max(label(1), label(std::round(rc_/firstWidth_)));
}


void Foam::structuredCell::countBeforeBuilding
(
    const std::vector<std::pair<label, label>>& blocks
)
{
    // the r-z blocks' elements
    std::size_t section = 0;
    for (const auto& b : blocks)
    {
        section += std::size_t(b.first)*std::size_t(b.second);
    }
    // the column's level intervals (levels())
    const std::size_t k4 =
        std::size_t(nGapBottom_) + nRingBottom_ + nCoreV_ + nRingN_ + nGap_
      + g_.layers();
    if (section_)
    {
        // the r-z blocks and the column's (sectionColumn)
        predicted_ = section + std::size_t(columnElements())*k4;
    }
    else
    {
        // each r-z block revolved over the azimuth (revolve) and the
        // butterfly disc's columns, a quarter of them in a quarter
        // (column)
        const std::size_t nSq = std::size_t(nSq_);
        predicted_ =
            std::size_t(quarter_ ? nSq : 4*nSq)*section
          + k4*(nSq*nSq + 4*nSq*std::size_t(nRing_))/(quarter_ ? 4 : 1);
    }
    refuseAboveMaxElements
    (
        g_, predicted_, section_ ? "quadrilaterals" : "hexahedra"
    );
}


void Foam::structuredCell::sectionColumn()
{
    // Vertical node lines at r_i = i r_c/nCol with the column's levels:
    // one r-z block per region's range of level intervals
    nCol_ = columnElements();
    std::vector<std::vector<scalar>> z(nCol_ + 1);
    for (label i = 0; i <= nCol_; ++i)
    {
        z[i] = levels(rc_*i/nCol_);
    }
    const label nLevels = label(z[0].size()) - 1;
    label k0 = 0;
    while (k0 < nLevels)
    {
        const int r = levelRegion(k0);
        label k1 = k0 + 1;
        while (k1 < nLevels && levelRegion(k1) == r) ++k1;
        block2D b;
        b.ni = nCol_;
        b.nj = k1 - k0;
        b.p.resize((b.ni + 1)*(b.nj + 1));
        for (label j = 0; j <= b.nj; ++j)
        for (label i = 0; i <= b.ni; ++i)
        {
            b.at(i, j) = {rc_*i/nCol_, z[i][k0 + j]};
        }
        sectionBlock(b, r);
        k0 = k1;
    }
}


void Foam::structuredCell::classifyEdges()
{
    std::map<edge, std::pair<int, edge>> count;
    for (const quad& q : quads_)
    {
        for (int k = 0; k < 4; ++k)
        {
            const edge e{q[k], q[(k + 1) % 4]};
            const edge key{std::min(e[0], e[1]), std::max(e[0], e[1])};
            auto it = count.find(key);
            if (it == count.end()) count[key] = {1, e};
            else ++it->second.first;
        }
    }
    const scalar a = g_.a(), H = g_.H();
    label bad = 0;
    for (const auto& kv : count)
    {
        if (kv.second.first > 2)
        {
            FatalErrorInFunction
                << "An edge is shared by " << kv.second.first
                << " quadrilaterals" << exit(FatalError);
        }
        if (kv.second.first != 1) continue;
        const edge& e = kv.second.second;
        bool onZ = true, onAxis = true, onOuter = true;
        for (const std::size_t n : e)
        {
            const vec& x = nodes_[n];
            onAxis = onAxis && x[0] == 0;
            onZ = onZ && x[1] == 0;
            const scalar s = sqr(x[0]/a) + sqr(x[1]/H);
            onOuter = onOuter && std::abs(s - 1) < 1e-9;
        }
        const char* name =
            onZ ? "fixedBottom"
          : onAxis ? "axis"
          : onOuter ? "outerSurface" : nullptr;
        if (name) edges_[name].push_back(e);
        else ++bad;
    }
    if (bad)
    {
        FatalErrorInFunction
            << bad << " boundary edges of the r-z section are neither on "
            << "the substrate, the axis nor the outer surface: the blocks "
            << "are not conformal" << exit(FatalError);
    }
}


std::map<Foam::label, Foam::label>
Foam::structuredCell::interiorValences() const
{
    std::vector<label> n(nodes_.size(), 0);
    std::vector<bool> boundary(nodes_.size(), false);
    for (const quad& q : quads_)
    {
        for (const std::size_t k : q) ++n[k];
    }
    for (const hex& h : hexes_)
    {
        for (const std::size_t k : h) ++n[k];
    }
    for (const auto& kv : edges_)
    {
        for (const edge& e : kv.second)
        {
            boundary[e[0]] = boundary[e[1]] = true;
        }
    }
    for (const auto& kv : faces_)
    {
        for (const quad& q : kv.second)
        {
            for (const std::size_t k : q) boundary[k] = true;
        }
    }
    std::map<label, label> v;
    for (std::size_t k = 0; k < n.size(); ++k)
    {
        if (!boundary[k]) ++v[n[k]];
    }
    return v;
}


void Foam::structuredCell::classifyBoundary()
{
    std::map<std::array<std::size_t, 4>, std::pair<int, quad>> count;
    for (const hex& e : hexes_)
    {
        for (const auto& f : hexFace)
        {
            quad q{e[f[0]], e[f[1]], e[f[2]], e[f[3]]};
            std::array<std::size_t, 4> key = q;
            std::sort(key.begin(), key.end());
            auto it = count.find(key);
            if (it == count.end()) count[key] = {1, q};
            else ++it->second.first;
        }
    }
    const scalar a = g_.a(), H = g_.H();
    label bad = 0;
    for (const auto& kv : count)
    {
        if (kv.second.first > 2)
        {
            FatalErrorInFunction
                << "A face is shared by " << kv.second.first
                << " hexahedra" << exit(FatalError);
        }
        if (kv.second.first != 1) continue;
        const quad& q = kv.second.second;
        bool onZ = true, onX = true, onY = true, onOuter = true;
        for (const std::size_t n : q)
        {
            const vec& x = nodes_[n];
            onX = onX && x[0] == 0;
            onY = onY && x[1] == 0;
            onZ = onZ && x[2] == 0;
            const scalar e = (sqr(x[0]) + sqr(x[1]))/sqr(a) + sqr(x[2]/H);
            onOuter = onOuter && std::abs(e - 1) < 1e-9;
        }
        const char* name =
            onZ ? "fixedBottom"
          : quarter_ && onX ? "symmetryX"
          : quarter_ && onY ? "symmetryY"
          : onOuter ? "outerSurface" : nullptr;
        if (name) faces_[name].push_back(q);
        else ++bad;
    }
    if (bad)
    {
        FatalErrorInFunction
            << bad << " boundary faces are neither on the substrate, the "
            << "symmetry planes nor the outer surface: the blocks are not "
            << "conformal" << exit(FatalError);
    }
}


Foam::structuredCell::vec2 Foam::structuredCell::nucleusOnDiagonal
(
    const vec2& c,
    scalar dz
) const
{
    const scalar an = g_.an(), cn = g_.cn(), zn = g_.zn();
    scalar lo = 0, hi = an;
    for (int it = 0; it < 100; ++it)
    {
        const scalar s = 0.5*(lo + hi);
        const scalar r = c[0] + s/std::sqrt(2.0);
        const scalar z = c[1] + dz*s/std::sqrt(2.0);
        (sqr(r/an) + sqr((z - zn)/cn) < 1 ? lo : hi) = s;
    }
    return {c[0] + lo/std::sqrt(2.0), c[1] + dz*lo/std::sqrt(2.0)};
}


Foam::scalar Foam::structuredCell::closestNucleusAngle(const vec2& x) const
{
    const auto d2 = [&](scalar p)
    {
        const vec2 y = nucleusPoint(p);
        return sqr(y[0] - x[0]) + sqr(y[1] - x[1]);
    };
    // the best distance kept, not computed again at every candidate (the
    // same choices; half the time of a fine membrane's count, adv50a k05)
    scalar best = 0;
    scalar dBest = d2(best);
    for (int k = 0; k <= 4000; ++k)
    {
        const scalar p = pi*k/4000;
        const scalar d = d2(p);
        if (d < dBest)
        {
            best = p;
            dBest = d;
        }
    }
    scalar lo = best - pi/4000, hi = best + pi/4000;
    for (int it = 0; it < 60; ++it)
    {
        const scalar m1 = lo + (hi - lo)/3, m2 = hi - (hi - lo)/3;
        if (d2(m1) < d2(m2)) hi = m2; else lo = m1;
    }
    return 0.5*(lo + hi);
}


void Foam::structuredCell::membraneCurves
(
    label nM,
    std::vector<vec2>& In,
    std::vector<vec2>& Out
) const
{
    const scalar a = g_.a(), t = g_.t();
    const scalar theta0 = innerTheta(rc_);
    std::vector<scalar> thIn(nM + 1);
    {
        const int nTab = 4000;
        std::vector<scalar> s(nTab + 1, 0);
        for (int i = 1; i <= nTab; ++i)
        {
            const auto x = g_.inner(theta0 + (0.5*pi - theta0)*(i - 1)/nTab);
            const auto y = g_.inner(theta0 + (0.5*pi - theta0)*i/nTab);
            s[i] = s[i - 1]
                + std::hypot(y.first() - x.first(), y.second() - x.second());
        }
        for (label i = 0; i <= nM; ++i)
        {
            const scalar target = s[nTab]*i/nM;
            const int k = std::min
            (
                nTab - 1,
                int(std::lower_bound(s.begin(), s.end(), target) - s.begin())
              - 1
            );
            const int kk = std::max(0, k);
            const scalar w = (target - s[kk])/(s[kk + 1] - s[kk]);
            thIn[i] = theta0 + (0.5*pi - theta0)*(kk + w)/nTab;
        }
        thIn[0] = theta0;
        thIn[nM] = 0.5*pi;
    }
    const scalar thetaOut0 = std::asin(rc_/a);
    In.resize(nM + 1);
    Out.resize(nM + 1);
    for (label i = 0; i <= nM; ++i)
    {
        const auto x = g_.inner(thIn[i]);
        In[i] = {x.first(), x.second()};
        const scalar th = thIn[i] + (thetaOut0 - theta0)*(1 - double(i)/nM);
        const auto y = g_.outer(th);
        Out[i] = {y.first(), y.second()};
    }
    In[0] = {rc_, innerZ(rc_)};
    In[nM] = {a - t, 0};
    Out[0] = {rc_, g_.H()*std::sqrt(1 - sqr(rc_/a))};
    Out[nM] = {a, 0};
}


void Foam::structuredCell::centredSections()
{
    const scalar a = g_.a(), t = g_.t(), an = g_.an(), cn = g_.cn(),
        zn = g_.zn();
    const scalar hN = g_.nucleusSize(), hC = g_.cytoplasmSize();
    const scalar hT = min(hC, g_.membraneSize());

    // Nucleus O-grid in the section (half-lens r >= r_c)
    const scalar qc = std::sqrt(1 - sqr(rc_/an));
    const scalar z1c = zn - cn*qc, hD = 2*cn*qc;
    const scalar rq = an - ringFraction*(an - rc_);
    const scalar kappa = coreFraction*cn*std::sqrt(1 - sqr(rq/an));
    lambda1_ = (zn - kappa - z1c)/hD;
    lambda2_ = 1 - lambda1_;
    // J1: the nucleus surface on the -45 degree ray from the core corner
    const vec2 J1 = nucleusOnDiagonal({rq, zn - kappa}, -1);
    const scalar psi1 = std::asin(rc_/an);
    const scalar psiJ = std::atan2(J1[0]/an, (zn - J1[1])/cn);
    nRingN_ = atLeastOne(max(lambda1_*hD, an - rq)/hN);

    // Substrate + membrane inner curve Gamma: its element count T must
    // equal the nucleus curve's (one C-shaped cytoplasm block)
    const scalar theta0 = innerTheta(rc_);
    const scalar Lb = a - t - rc_;
    const scalar Li = g_.arcLength(theta0, 0.5*pi, true);
    const label nB = atLeastOne(Lb/hC);
    const label nM = atLeastOne(Li/hT);
    const label T = nB + nM;

    // Membrane inner curve from r_c (theta0) to the substrate, uniform in
    // arc length, and the matched outer points
    std::vector<vec2> In, Out;
    membraneCurves(nM, In, Out);
    firstWidth_ = std::hypot(In[1][0] - In[0][0], In[1][1] - In[0][1]);

    // Gamma: substrate P0 -> R, then the inner curve R -> P3
    std::vector<vec2> Gamma = segment({rc_, 0}, {a - t, 0}, nB);
    for (label i = nM - 1; i >= 0; --i) Gamma.push_back(In[i]);

    // Nucleus curve Lambda (P1 -> J1 -> J2 -> P2) with T elements: node i
    // at the nucleus point closest to Gamma(i), so that the cytoplasm node
    // lines leave the nucleus along its normals (the closest-point map of
    // the convex nucleus is monotone along Gamma); J1 and J2 are the nodes
    // closest to the design points (symmetric counts: the core
    // rectangle), each piece then remapped to end exactly there
    std::vector<scalar> psiStar(T + 1);
    for (label i = 0; i <= T; ++i)
    {
        psiStar[i] = closestNucleusAngle(Gamma[i]);
    }
    // The ends Gamma(0) = P0, Gamma(T) = P3 (below and above the lens
    // corners) project beyond P1, P2: rescale affinely onto [psi1,
    // pi - psi1]
    {
        const scalar p0 = psiStar[0], p1 = psiStar[T];
        for (scalar& p : psiStar)
        {
            p = psi1 + (p - p0)*(pi - 2*psi1)/(p1 - p0);
        }
    }
    psiStar[0] = psi1;
    psiStar[T] = pi - psi1;
    label mBot = 1, mTop = 1;
    for (label i = 1; i < T; ++i)
    {
        if (std::abs(psiStar[i] - psiJ) < std::abs(psiStar[mBot] - psiJ))
        {
            mBot = i;
        }
        if
        (
            std::abs(psiStar[T - i] - (pi - psiJ))
          < std::abs(psiStar[T - mTop] - (pi - psiJ))
        )
        {
            mTop = i;
        }
    }
    const label mB = std::max(label(1), std::min((mBot + mTop)/2, (T - 1)/2));
    nCoreV_ = T - 2*mB;
    const label nNuc = 2*nRingN_ + nCoreV_;
    std::vector<vec2> Lambda(T + 1);
    const auto remap = [&](label i0, label i1, scalar p0, scalar p1)
    {
        remapNucleus(psiStar, i0, i1, p0, p1, Lambda);
    };
    remap(0, mB, psi1, psiJ);
    remap(mB, T - mB, psiJ, pi - psiJ);
    remap(T - mB, T, pi - psiJ, pi - psi1);

    // Cytoplasm layers: across the thickest part of the C-shaped block
    // (from the nucleus to the rim) and the gaps on the axis
    scalar thick = max(zn - cn, innerZ(0) - zn - cn);
    for (std::size_t i = 0; i < Gamma.size(); ++i)
    {
        thick = max
        (
            thick,
            std::hypot(Gamma[i][0] - Lambda[i][0], Gamma[i][1] - Lambda[i][1])
        );
    }
    nGap_ = atLeastOne(thick/hC);
    nGapBottom_ = nGap_;
    nRingBottom_ = nRingN_;

    // the whole mesh's elements, before any block is made
    countBeforeBuilding
    ({
        {mB, nCoreV_}, {mB, nRingN_}, {nCoreV_, nRingN_}, {mB, nRingN_},
        {T, nGap_}, {nM, g_.layers()}
    });

    // Column levels at r_c (shared by the left sides of the r-z blocks)
    const std::vector<scalar> zc = levels(rc_);
    const auto colPt = [&](label k) { return vec2{rc_, zc[k]}; };
    const auto colSide = [&](label k0, label k1)
    {
        std::vector<vec2> p;
        const label d = k1 > k0 ? 1 : -1;
        for (label k = k0; k != k1 + d; k += d) p.push_back(colPt(k));
        return p;
    };
    Lambda.front() = colPt(nGap_);
    Lambda.back() = colPt(nGap_ + nNuc);

    // Nucleus O-grid blocks
    const vec2 K0 = colPt(nGap_ + nRingN_);
    const vec2 K3 = colPt(nGap_ + nRingN_ + nCoreV_);
    const vec2 K1{rq, K0[1]}, K2{rq, K3[1]};
    const vec2 J2 = Lambda[mB + nCoreV_];
    const std::vector<vec2> coreBottom = segment(K0, K1, mB);
    const std::vector<vec2> coreTop = segment(K3, K2, mB);
    const std::vector<vec2> coreRight = segment(K1, K2, nCoreV_);
    const std::vector<vec2> lamB(Lambda.begin(), Lambda.begin() + mB + 1);
    const std::vector<vec2> lamR
    (
        Lambda.begin() + mB, Lambda.begin() + mB + nCoreV_ + 1
    );
    const std::vector<vec2> lamT
    (
        Lambda.rbegin(), Lambda.rbegin() + mB + 1
    );
    sectionBlock
    (
        coons
        (
            coreBottom, coreTop,
            colSide(nGap_ + nRingN_, nGap_ + nRingN_ + nCoreV_), coreRight
        ),
        nucleusRegion
    );
    sectionBlock
    (
        coons
        (
            lamB, coreBottom, colSide(nGap_, nGap_ + nRingN_),
            segment(Lambda[mB], K1, nRingN_)
        ),
        nucleusRegion
    );
    sectionBlock
    (
        coons
        (
            lamR, coreRight, segment(Lambda[mB], K1, nRingN_),
            segment(J2, K2, nRingN_)
        ),
        nucleusRegion
    );
    sectionBlock
    (
        coons
        (
            lamT, coreTop, colSide(nGap_ + nNuc, nGap_ + nNuc - nRingN_),
            segment(J2, K2, nRingN_)
        ),
        nucleusRegion
    );

    // Cytoplasm C-block: straight node lines from Lambda(i) to Gamma(i)
    // (a ruled block; its ends are the column's vertical lines)
    sectionBlock(ruled(Lambda, Gamma, nGap_), cytoplasmRegion);

    // Membrane: straight node lines between matched inner/outer points
    sectionBlock(ruled(In, Out, g_.layers()), membraneRegion);
}


void Foam::structuredCell::scaledSections()
{
    // The nucleus: the semi-spheroid (r/a_n)^2 + (z/c_n)^2 <= 1, z >= 0
    // (zn = 0); psi in [pi/2, pi] from its base rim to its top
    const scalar an = g_.an(), cn = g_.cn();
    const scalar hN = g_.nucleusSize(), hC = g_.cytoplasmSize();
    const scalar hT = min(hC, g_.membraneSize());

    // Core rectangle [r_c, r_q] x [0, kappa] on the substrate (the upper
    // half of the centred spheroid's core) and its column fraction
    const scalar z2c = cn*std::sqrt(1 - sqr(rc_/an));
    const scalar rq = an - ringFraction*(an - rc_);
    const scalar kappa = coreFraction*cn*std::sqrt(1 - sqr(rq/an));
    lambda1_ = 0;
    lambda2_ = kappa/z2c;
    nGapBottom_ = 0;
    nRingBottom_ = 0;
    // J: the nucleus surface on the +45 degree ray from the core corner
    const vec2 J = nucleusOnDiagonal({rq, kappa}, 1);
    const scalar psiJ = std::atan2(J[0]/an, -J[1]/cn);
    const scalar psiC = pi - std::asin(rc_/an);
    nRingN_ = atLeastOne(max(z2c - kappa, an - rq)/hN);

    // One element count T along the membrane inner curve (column to the
    // substrate) and the nucleus curve (column to its base rim): the
    // cytoplasm is one ruled block between them
    const scalar Li = g_.arcLength(innerTheta(rc_), 0.5*pi, true);
    scalar Ln = 0;
    {
        const int n = 4000;
        for (int i = 0; i < n; ++i)
        {
            const vec2 x = nucleusPoint(0.5*pi + (psiC - 0.5*pi)*i/n);
            const vec2 y = nucleusPoint(0.5*pi + (psiC - 0.5*pi)*(i + 1)/n);
            Ln += std::hypot(y[0] - x[0], y[1] - x[1]);
        }
    }
    const label T = max
    (
        label(2),
        max(atLeastOne(Li/hT), atLeastOne(Ln/hN))
    );
    std::vector<vec2> In, Out;
    membraneCurves(T, In, Out);
    firstWidth_ = std::hypot(In[1][0] - In[0][0], In[1][1] - In[0][1]);

    // Nucleus curve Lambda (column -> J -> base rim (a_n, 0)): node i at
    // the nucleus point closest to In(i) (cytoplasm node lines along the
    // nucleus normals), rescaled affinely to end at the column and the
    // rim (In(T) = (a - t, 0) projects onto the rim exactly); J the node
    // closest to the design point, each piece remapped to end there
    std::vector<scalar> psiStar(T + 1);
    for (label i = 0; i <= T; ++i)
    {
        psiStar[i] = closestNucleusAngle(In[i]);
    }
    {
        const scalar p0 = psiStar[0], p1 = psiStar[T];
        for (scalar& p : psiStar)
        {
            p = psiC + (p - p0)*(0.5*pi - psiC)/(p1 - p0);
        }
    }
    psiStar[0] = psiC;
    psiStar[T] = 0.5*pi;
    label mB = 1;
    for (label i = 1; i < T; ++i)
    {
        if (std::abs(psiStar[i] - psiJ) < std::abs(psiStar[mB] - psiJ))
        {
            mB = i;
        }
    }
    // Elements of the ring above the core (column to J): mB; beside the
    // core (J to the rim): nCoreV_
    nCoreV_ = T - mB;
    const label nNuc = nCoreV_ + nRingN_;
    std::vector<vec2> Lambda(T + 1);
    const auto remap = [&](label i0, label i1, scalar p0, scalar p1)
    {
        remapNucleus(psiStar, i0, i1, p0, p1, Lambda);
    };
    remap(0, mB, psiC, psiJ);
    remap(mB, T, psiJ, 0.5*pi);

    // Cytoplasm layers: across the thickest part of the block and the
    // gap on the axis
    scalar thick = innerZ(0) - cn;
    for (label i = 0; i <= T; ++i)
    {
        thick = max
        (
            thick,
            std::hypot(In[i][0] - Lambda[i][0], In[i][1] - Lambda[i][1])
        );
    }
    nGap_ = atLeastOne(thick/hC);

    // the whole mesh's elements, before any block is made
    countBeforeBuilding
    ({
        {mB, nCoreV_}, {nCoreV_, nRingN_}, {mB, nRingN_}, {T, nGap_},
        {T, g_.layers()}
    });

    // Column levels at r_c (shared by the left sides of the r-z blocks)
    const std::vector<scalar> zc = levels(rc_);
    const auto colPt = [&](label k) { return vec2{rc_, zc[k]}; };
    const auto colSide = [&](label k0, label k1)
    {
        std::vector<vec2> p;
        const label d = k1 > k0 ? 1 : -1;
        for (label k = k0; k != k1 + d; k += d) p.push_back(colPt(k));
        return p;
    };
    Lambda.front() = colPt(nNuc);
    Lambda.back() = {an, 0};

    // Nucleus O-grid blocks: the core, the ring beside it (its base on
    // the substrate from r_q to a_n) and the ring above it
    const vec2 K0 = colPt(0), K3 = colPt(nCoreV_);
    const vec2 K1{rq, 0}, K2{rq, K3[1]};
    const vec2 Jm = Lambda[mB];
    const std::vector<vec2> coreBottom = segment(K0, K1, mB);
    const std::vector<vec2> coreTop = segment(K3, K2, mB);
    const std::vector<vec2> coreRight = segment(K1, K2, nCoreV_);
    const std::vector<vec2> ringSide = segment(Jm, K2, nRingN_);
    const std::vector<vec2> lamR
    (
        Lambda.rbegin(), Lambda.rbegin() + nCoreV_ + 1
    );
    const std::vector<vec2> lamT(Lambda.begin(), Lambda.begin() + mB + 1);
    sectionBlock
    (
        coons(coreBottom, coreTop, colSide(0, nCoreV_), coreRight),
        nucleusRegion
    );
    sectionBlock
    (
        coons
        (
            lamR, coreRight, segment(Lambda.back(), K1, nRingN_), ringSide
        ),
        nucleusRegion
    );
    sectionBlock
    (
        coons(lamT, coreTop, colSide(nNuc, nCoreV_), ringSide),
        nucleusRegion
    );

    // Cytoplasm: straight node lines from Lambda(i) to In(i) (its ends:
    // the column's vertical line and the substrate from a_n to a - t)
    sectionBlock(ruled(Lambda, In, nGap_), cytoplasmRegion);

    // Membrane: straight node lines between matched inner/outer points
    sectionBlock(ruled(In, Out, g_.layers()), membraneRegion);
}


Foam::structuredCell::structuredCell(const cellGeometry& geom)
:
    g_(geom),
    quarter_(geom.mode() == cellGeometry::meshMode::quarter3D),
    section_(geom.axisymmetric()),
    nCol_(0),
    firstWidth_(0),
    smoothSweeps_(0),
    smoothLastMove_(0),
    smoothFree_(0),
    smoothSliding_(0),
    smoothBoundary_(0),
    predicted_(0)
{
    const scalar a = g_.a(), an = g_.an();
    rc_ = columnFraction*an;
    s_ = squareFraction*rc_;

    // Azimuth: elements per quarter turn (even: the quarter's planes are
    // grid planes of the butterfly)
    nSq_ = 2*atLeastOne(0.25*pi*0.5*(rc_ + a)/g_.azimuthSize());
    nRing_ = max
    (
        label(1), label(std::round((rc_ - s_)/(0.5*pi*rc_/nSq_)))
    );

    if (g_.scaledNucleus())
    {
        scaledSections();
    }
    else
    {
        centredSections();
    }
    if (section_)
    {
        sectionColumn();
    }
    if (g_.ellipticSmoothing())
    {
        smoothSection();
    }
    for (const auto& b : pending_)
    {
        if (section_)
        {
            addQuads(b.first, b.second);
        }
        else
        {
            revolve(b.first, b.second);
        }
    }
    if (section_)
    {
        classifyEdges();
    }
    else
    {
        column();
        classifyBoundary();
    }
    // the closed form is the mesh's count (the refusal above relies on it)
    const std::size_t made = section_ ? quads_.size() : hexes_.size();
    if (made != predicted_)
    {
        FatalErrorInFunction
            << "the structured mesh has " << std::to_string(made).c_str()
            << " elements, its count before building "
            << std::to_string(predicted_).c_str()
            << ": the closed-form count of structuredCell is wrong (a bug:"
            << " please report it with the cellMeshDict)" << exit(FatalError);
    }
}


namespace
{

// The mesh as gmsh discrete entities of dimension dim: the nodes, the
// elements of each region (gmsh element type elementType) as a physical
// group named after the region, and each boundary group (elements of
// dimension dim - 1, gmsh type boundaryType) as a physical group of its
// name. The r-z section (dim 2: quadrilaterals, lines, x = r, y = z) and
// the 3D cell (dim 3: hexahedra, quadrilaterals) are written alike.
template<class Element, class BoundaryElement>
void addToGmsh
(
    const int dim,
    const int elementType,
    const int boundaryType,
    const std::vector<std::array<double, 3>>& nodes,
    const std::vector<Element>& elements,
    const std::vector<int>& region,
    const std::map<std::string, std::vector<BoundaryElement>>& groups,
    const double unit
)
{
    const char* regionNames[3] = {"nucleus", "cytoplasm", "membrane"};
    for (int r = 0; r < 3; ++r)
    {
        gmsh::model::addDiscreteEntity(dim, r + 1);
    }
    std::vector<std::size_t> tags(nodes.size());
    std::vector<double> xyz;
    xyz.reserve(3*nodes.size());
    for (std::size_t n = 0; n < nodes.size(); ++n)
    {
        tags[n] = n + 1;
        for (int k = 0; k < 3; ++k) xyz.push_back(nodes[n][k]/unit);
    }
    gmsh::model::mesh::addNodes(dim, 1, tags, xyz);

    std::size_t next = 1;
    for (int r = 0; r < 3; ++r)
    {
        std::vector<std::size_t> et, nt;
        for (std::size_t e = 0; e < elements.size(); ++e)
        {
            if (region[e] != r) continue;
            et.push_back(next++);
            for (const std::size_t n : elements[e]) nt.push_back(n + 1);
        }
        gmsh::model::mesh::addElementsByType(r + 1, elementType, et, nt);
        const int g = gmsh::model::addPhysicalGroup(dim, {r + 1});
        gmsh::model::setPhysicalName(dim, g, regionNames[r]);
    }
    int entity = 0;
    for (const auto& kv : groups)
    {
        gmsh::model::addDiscreteEntity(dim - 1, ++entity);
        std::vector<std::size_t> et, nt;
        for (const BoundaryElement& b : kv.second)
        {
            et.push_back(next++);
            for (const std::size_t n : b) nt.push_back(n + 1);
        }
        gmsh::model::mesh::addElementsByType(entity, boundaryType, et, nt);
        const int g = gmsh::model::addPhysicalGroup(dim - 1, {entity});
        gmsh::model::setPhysicalName(dim - 1, g, kv.first);
    }
}

} // End anonymous namespace


void Foam::structuredCell::toGmsh(scalar unit) const
{
    // gmsh element types: 1 line, 3 quadrilateral, 5 hexahedron
    if (section_)
    {
        addToGmsh(2, 3, 1, nodes_, quads_, region_, edges_, unit);
    }
    else
    {
        addToGmsh(3, 5, 3, nodes_, hexes_, region_, faces_, unit);
    }
}


void Foam::structuredCell::remapNucleus
(
    const std::vector<scalar>& psiStar,
    label i0, label i1, scalar p0, scalar p1,
    std::vector<vec2>& Lambda
) const
{
    for (label i = i0; i <= i1; ++i)
    {
        const scalar f =
            (psiStar[i] - psiStar[i0])/(psiStar[i1] - psiStar[i0]);
        Lambda[i] = nucleusPoint(p0 + f*(p1 - p0));
    }
}
