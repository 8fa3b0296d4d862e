#include "hexFluidMesh.H"
#include "error.H"
#include "mathematicalConstants.H"
#include <gmsh.h>
#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace
{

// Node positions of [x0, x1] in n equal steps (the last one exact)
std::vector<Foam::scalar> uniform
(
    Foam::scalar x0,
    Foam::scalar x1,
    Foam::label n
)
{
    std::vector<Foam::scalar> x(n + 1);
    for (Foam::label i = 0; i <= n; ++i)
    {
        x[i] = x0 + (x1 - x0)*i/n;
    }
    x[n] = x1;
    return x;
}

} // End anonymous namespace


Foam::hexFluidMesh::hexFluidMesh(const sizes& s)
:
    s_(s)
{
    // x >= 0: lateralSize inside the inner box, then the spacing grows
    // linearly with the distance from it, from lateralSize to farSize
    // over growthDistance (the wedge's rule), scaled to end at L/2
    const scalar A = s_.a + s_.margin, B = s_.H + s_.margin;
    const scalar hl = s_.lateralSize, hf = s_.farSize;
    std::vector<scalar> xp =
        uniform(0, A, label(std::ceil(A/hl*(1 - 1e-12))));
    const label nIn = label(xp.size()) - 1;
    const scalar D = 0.5*s_.L - A;
    std::vector<scalar> f{0};
    while (f.back() < D)
    {
        f.push_back
        (
            f.back() + hl + (hf - hl)*std::min(1.0, f.back()/s_.growth)
        );
    }
    if (f.size() > 2 && f.back() - D > 0.5*(f.back() - f[f.size() - 2]))
    {
        f.pop_back();
    }
    for (std::size_t k = 1; k < f.size(); ++k)
    {
        xp.push_back(k + 1 < f.size() ? A + f[k]*D/f.back() : 0.5*s_.L);
    }
    if (s_.quarter)
    {
        x_ = xp;
        i0_ = 0;
        i1_ = nIn;
    }
    else
    {
        for (std::size_t k = xp.size() - 1; k > 0; --k) x_.push_back(-xp[k]);
        x_.insert(x_.end(), xp.begin(), xp.end());
        i0_ = label(xp.size()) - 1 - nIn;
        i1_ = label(xp.size()) - 1 + nIn;
    }

    // z: uniform at (at most) axialSize below and above z = B, to the
    // top of the water (height: L, or less for an inflow top)
    z_ = uniform(0, B, label(std::ceil(B/s_.axialSize*(1 - 1e-12))));
    kB_ = label(z_.size()) - 1;
    const std::vector<scalar> zu = uniform
    (
        B,
        s_.height,
        label(std::ceil((s_.height - B)/s_.axialSize*(1 - 1e-12)))
    );
    z_.insert(z_.end(), zu.begin() + 1, zu.end());

    // Segments: the shortest and the longest, then the layer count
    minRay_ = GREAT;
    maxRay_ = 0;
    for (label k = 0; k <= kB_; ++k)
    for (label j = i0_; j <= i1_; ++j)
    for (label i = i0_; i <= i1_; ++i)
    {
        if (outer(i, j, k))
        {
            const vec S = surfacePoint(i, j, k);
            const vec P = rounded({x_[i], x_[j], z_[k]});
            const scalar l = std::sqrt
            (
                sqr(P[0] - S[0]) + sqr(P[1] - S[1]) + sqr(P[2] - S[2])
            );
            minRay_ = std::min(minRay_, l);
            maxRay_ = std::max(maxRay_, l);
        }
    }
    // The smallest n with nearSize (maxRatio^n - 1)/(maxRatio - 1) >= the
    // longest ray
    nLayers_ = std::max
    (
        label(1),
        label(std::ceil
        (
            std::log(1 + (maxRatio_ - 1)*maxRay_/s_.nearSize)
           /std::log(maxRatio_) - 1e-12
        ))
    );
}


bool Foam::hexFluidMesh::open(int side) const
{
    return !(s_.quarter && (side == 0 || side == 2));
}


bool Foam::hexFluidMesh::outer(label i, label j, label k) const
{
    if (i < i0_ || i > i1_ || j < i0_ || j > i1_ || k > kB_)
    {
        return false;
    }
    return (i == i0_ && open(0)) || i == i1_ || (j == i0_ && open(2))
        || j == i1_ || k == kB_;
}


bool Foam::hexFluidMesh::removed(label i, label j, label k) const
{
    return i >= i0_ && i <= i1_ && j >= i0_ && j <= i1_ && k <= kB_
        && !outer(i, j, k);
}


Foam::hexFluidMesh::vec Foam::hexFluidMesh::rounded(const vec& P) const
{
    const scalar p = s_.topRounding;
    if (p == 0)
    {
        return P;
    }
    const scalar A = s_.a + s_.margin, B = s_.H + s_.margin;
    const scalar u = std::max(std::abs(P[0]), std::abs(P[1]))/A;
    const scalar w = P[2]/B;
    const scalar rInf = std::max(u, w);
    // The blend: 1 on the inner box, 0 from rho1 on (the water's top and
    // the side walls stay), smoothstep between; at most rhoMax_: farther
    // out the lateral spacing grows towards farSize and the flat cells
    // there (farSize x farSize x axialSize) fold under the move (a water
    // column to 30 um, rho1 2.53: faces 140 deg non-orthogonal)
    const scalar rho1 = std::min(std::min(s_.height/B, 0.5*s_.L/A), rhoMax_);
    const scalar q = std::min(1.0, std::max(0.0, (rInf - 1)/(rho1 - 1)));
    const scalar beta = 1 - q*q*(3 - 2*q);
    if (rInf == 0 || beta == 0)
    {
        return P;
    }
    const scalar rP = std::pow(std::pow(u, p) + std::pow(w, p), 1/p);
    // A scaling about the origin: exact zeros (the symmetry planes, the
    // substrate) stay zeros; on the substrate rP = rInf, f = 1
    const scalar f = std::pow(rInf/rP, beta);
    return {P[0]*f, P[1]*f, P[2]*f};
}


Foam::hexFluidMesh::vec Foam::hexFluidMesh::project(const vec& P) const
{
    const scalar c = 1/std::sqrt
    (
        (P[0]*P[0] + P[1]*P[1])/(s_.a*s_.a) + P[2]*P[2]/(s_.H*s_.H)
    );
    // c P: exact zeros stay zeros (the symmetry planes, the substrate)
    return {c*P[0], c*P[1], c*P[2]};
}


Foam::hexFluidMesh::vec Foam::hexFluidMesh::surfacePoint
(
    label i,
    label j,
    label k
) const
{
    const scalar x = x_[i], y = x_[j];
    scalar z = z_[k];

    // Side face (below the top edge): the height at which the radial
    // projection of the vertical line (x, y, 0..B) has covered k/kB of
    // its arc (chords of nArc equal steps in z, linear in between)
    if (k > 0 && k < kB_)
    {
        const label nArc = 2000;
        const scalar B = z_[kB_];
        std::vector<scalar> arc(nArc + 1, 0);
        vec prev = project({x, y, 0});
        for (label n = 1; n <= nArc; ++n)
        {
            const vec q = project({x, y, B*n/nArc});
            arc[n] = arc[n - 1] + std::sqrt
            (
                sqr(q[0] - prev[0]) + sqr(q[1] - prev[1])
              + sqr(q[2] - prev[2])
            );
            prev = q;
        }
        const scalar target = arc[nArc]*k/kB_;
        const label n = label
        (
            std::upper_bound(arc.begin(), arc.end(), target) - arc.begin()
        );
        const scalar w = (target - arc[n - 1])/(arc[n] - arc[n - 1]);
        z = B*(n - 1 + w)/nArc;
    }
    vec S = project({x, y, z});

    // Equiangular azimuth (the pole, x = y = 0, has none)
    if (x != 0 || y != 0)
    {
        const scalar quarter = 0.5*constant::mathematical::pi;
        const scalar phi = std::atan2(y, x);
        const scalar n = std::round(phi/quarter);
        const scalar phiE =
            n*quarter + 0.5*quarter*std::tan(phi - n*quarter);
        const scalar r = std::sqrt(S[0]*S[0] + S[1]*S[1]);
        // Nodes on x = 0 or y = 0 stay there exactly
        S[0] = x == 0 ? 0 : r*std::cos(phiE);
        S[1] = y == 0 ? 0 : r*std::sin(phiE);
    }
    return S;
}


std::vector<Foam::scalar> Foam::hexFluidMesh::layers(scalar l) const
{
    const label n = nLayers_;
    const scalar h0 = s_.nearSize;
    // Geometric ratio r with h0 (r^n - 1)/(r - 1) = l (bisection; r = 1:
    // a ray too short for n layers of h0 gets uniform layers)
    scalar r = 1;
    if (l > n*h0)
    {
        const auto sum = [&](scalar q)
        {
            return h0*(std::pow(q, n) - 1)/(q - 1);
        };
        scalar lo = 1, hi = maxRatio_;
        while (sum(hi) < l) hi *= 2;
        for (int it = 0; it < 200 && hi - lo > 1e-15; ++it)
        {
            const scalar m = 0.5*(lo + hi);
            (sum(m) < l ? lo : hi) = m;
        }
        r = 0.5*(lo + hi);
    }
    std::vector<scalar> f(n + 1, 0);
    scalar h = 1;
    for (label k = 1; k <= n; ++k)
    {
        f[k] = f[k - 1] + h;
        h *= r;
    }
    for (scalar& v : f) v /= f[n];
    f[n] = 1;
    return f;
}


std::int64_t Foam::hexFluidMesh::nCells() const
{
    const std::int64_t nx = x_.size() - 1, nz = z_.size() - 1;
    const std::int64_t nA = i1_ - i0_;
    std::int64_t nOpen = nA*nA;
    nOpen += (open(0) ? 2 : 1)*nA*kB_ + (open(2) ? 2 : 1)*nA*kB_;
    return nx*nx*nz - nA*nA*kB_ + nLayers_*nOpen;
}


void Foam::hexFluidMesh::addHex(hex h)
{
    const auto d = [&](int p, int q)
    {
        vec v;
        for (int c = 0; c < 3; ++c)
        {
            v[c] = nodes_[h[q]][c] - nodes_[h[p]][c];
        }
        return v;
    };
    // Centre Jacobian of the trilinear map (edge means along the three
    // local directions)
    vec e[3];
    const int pairs[3][4][2] =
    {
        {{0, 1}, {3, 2}, {4, 5}, {7, 6}},
        {{0, 3}, {1, 2}, {4, 7}, {5, 6}},
        {{0, 4}, {1, 5}, {2, 6}, {3, 7}}
    };
    for (int a = 0; a < 3; ++a)
    {
        e[a] = {0, 0, 0};
        for (const auto& pq : pairs[a])
        {
            const vec v = d(pq[0], pq[1]);
            for (int c = 0; c < 3; ++c) e[a][c] += v[c];
        }
    }
    const scalar J =
        e[2][0]*(e[0][1]*e[1][2] - e[0][2]*e[1][1])
      + e[2][1]*(e[0][2]*e[1][0] - e[0][0]*e[1][2])
      + e[2][2]*(e[0][0]*e[1][1] - e[0][1]*e[1][0]);
    if (J < 0)
    {
        std::swap_ranges(h.begin(), h.begin() + 4, h.begin() + 4);
    }
    hexes_.push_back(h);
}


void Foam::hexFluidMesh::build()
{
    const label nx = label(x_.size()), nz = label(z_.size());
    const auto t = [&](label i, label j, label k)
    {
        return (std::size_t(k)*nx + j)*nx + i;
    };
    const std::size_t none = std::size_t(-1);

    // orthogonal: the coordinates a node may move in (bits 1 x, 2 y, 4 z)
    // and the direction it may not move in (layer 1: its ray), per node.
    // The planes a node lies on stay exact: the symmetry planes of the
    // quarter (x or y = 0: that coordinate fixed), the substrate (z fixed);
    // the water's top and side walls and the cell's surface do not move
    std::vector<unsigned char> free;
    std::vector<vec> normal;
    const auto planeBits = [&](label i, label j, label k)
    {
        unsigned char b = 7;
        if (s_.quarter && i == 0) b &= ~1u;
        if (s_.quarter && j == 0) b &= ~2u;
        if (k == 0) b &= ~4u;
        return b;
    };
    const label D = smoothDepth_;
    const auto tensorBits = [&](label i, label j, label k)
    {
        const bool wall =
            k == nz - 1 || i == nx - 1 || j == nx - 1
         || (!s_.quarter && (i == 0 || j == 0));
        const bool near =
            i >= i0_ - D && i <= i1_ + D && j >= i0_ - D && j <= i1_ + D
         && k <= kB_ + D;
        return (s_.orthogonal && near && !wall)
            ? planeBits(i, j, k) : static_cast<unsigned char>(0);
    };

    // Tensor nodes (those inside the inner box removed)
    std::vector<std::size_t> id(std::size_t(nx)*nx*nz, none);
    for (label k = 0; k < nz; ++k)
    for (label j = 0; j < nx; ++j)
    for (label i = 0; i < nx; ++i)
    {
        if (!removed(i, j, k))
        {
            id[t(i, j, k)] = nodes_.size();
            nodes_.push_back(rounded({x_[i], x_[j], z_[k]}));
            free.push_back(tensorBits(i, j, k));
            normal.push_back({0, 0, 0});
        }
    }
    std::vector<bool> onCell(nodes_.size(), false);

    // Ray nodes of the O-grid: layers 0 (on the spheroid) to nLayers - 1
    // of each outer node; layer nLayers is the outer node itself
    std::vector<std::size_t> ray(id.size(), none);
    for (label k = 0; k <= kB_; ++k)
    for (label j = i0_; j <= i1_; ++j)
    for (label i = i0_; i <= i1_; ++i)
    {
        if (!outer(i, j, k)) continue;
        const vec P = nodes_[id[t(i, j, k)]];
        const vec S = surfacePoint(i, j, k);
        const vec d{P[0] - S[0], P[1] - S[1], P[2] - S[2]};
        const scalar l = std::sqrt(d[0]*d[0] + d[1]*d[1] + d[2]*d[2]);
        const std::vector<scalar> f = layers(l);
        ray[t(i, j, k)] = nodes_.size();
        for (label m = 0; m < nLayers_; ++m)
        {
            // Exact zeros stay zeros (S and P both in the plane): the
            // symmetry planes and the substrate remain plane
            nodes_.push_back
                ({S[0] + f[m]*d[0], S[1] + f[m]*d[1], S[2] + f[m]*d[2]});
            onCell.push_back(m == 0);
            // The nodes on the cell's surface slide on it (moved along
            // its tangent plane, then projected back: bit 8); the first
            // layer's outer nodes move only across their ray (its
            // thickness, nearSize, stays)
            free.push_back
            (
                s_.orthogonal
              ? static_cast<unsigned char>(planeBits(i, j, k) | (m == 0 ? 8 : 0))
              : static_cast<unsigned char>(0)
            );
            vec nv{0, 0, 0};
            if (m == 0)
            {
                nv = {S[0]/sqr(s_.a), S[1]/sqr(s_.a), S[2]/sqr(s_.H)};
                const scalar ln =
                    std::sqrt(nv[0]*nv[0] + nv[1]*nv[1] + nv[2]*nv[2]);
                for (scalar& c : nv) c /= ln;
            }
            else if (m == 1)
            {
                nv = {d[0]/l, d[1]/l, d[2]/l};
            }
            normal.push_back(nv);
        }
    }
    const auto layerNode = [&](std::size_t tn, label m)
    {
        return m == nLayers_ ? id[tn] : ray[tn] + m;
    };

    // Tensor cells outside the inner box
    for (label k = 0; k + 1 < nz; ++k)
    for (label j = 0; j + 1 < nx; ++j)
    for (label i = 0; i + 1 < nx; ++i)
    {
        if (i >= i0_ && i < i1_ && j >= i0_ && j < i1_ && k < kB_) continue;
        addHex
        ({
            id[t(i, j, k)], id[t(i + 1, j, k)], id[t(i + 1, j + 1, k)],
            id[t(i, j + 1, k)], id[t(i, j, k + 1)], id[t(i + 1, j, k + 1)],
            id[t(i + 1, j + 1, k + 1)], id[t(i, j + 1, k + 1)]
        });
    }

    // O-grid cells: one column of nLayers per quad of an open face
    std::vector<std::array<std::size_t, 4>> quads;
    for (label b = 0; b < i1_ - i0_; ++b)
    {
        const label p = i0_ + b;
        for (label c = 0; c < i1_ - i0_; ++c)
        {
            const label q = i0_ + c;
            quads.push_back
                ({t(p, q, kB_), t(p + 1, q, kB_), t(p + 1, q + 1, kB_),
                  t(p, q + 1, kB_)});
        }
        for (label k = 0; k < kB_; ++k)
        {
            for (const label i : {i0_, i1_})
            {
                if (i == i0_ && !open(0)) continue;
                quads.push_back
                    ({t(i, p, k), t(i, p + 1, k), t(i, p + 1, k + 1),
                      t(i, p, k + 1)});
            }
            for (const label j : {i0_, i1_})
            {
                if (j == i0_ && !open(2)) continue;
                quads.push_back
                    ({t(p, j, k), t(p + 1, j, k), t(p + 1, j, k + 1),
                      t(p, j, k + 1)});
            }
        }
    }
    for (const auto& q : quads)
    {
        for (label m = 0; m < nLayers_; ++m)
        {
            addHex
            ({
                layerNode(q[0], m), layerNode(q[1], m), layerNode(q[2], m),
                layerNode(q[3], m), layerNode(q[0], m + 1),
                layerNode(q[1], m + 1), layerNode(q[2], m + 1),
                layerNode(q[3], m + 1)
            });
        }
    }
    if (std::int64_t(hexes_.size()) != nCells())
    {
        FatalErrorInFunction
            << "Built " << label(hexes_.size()) << " hexahedra, estimated "
            << label(nCells()) << exit(FatalError);
    }
    if (s_.orthogonal)
    {
        orthogonalise(free, normal);
    }
    classifyBoundary(onCell);
}


void Foam::hexFluidMesh::orthogonalise
(
    const std::vector<unsigned char>& free,
    const std::vector<vec>& normal
)
{
    const std::size_t nNodes = nodes_.size(), nHex = hexes_.size();

    // Interior faces: the owner's four nodes (outward from the owner, the
    // gmsh hexahedron's faces as in classifyBoundary), owner, neighbour
    const int hexFaces[6][4] =
    {
        {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
        {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}
    };
    struct face { quad q; std::size_t own, nei; };
    std::vector<face> faces;
    {
        std::map<quad, std::pair<std::size_t, quad>> seen;
        for (std::size_t c = 0; c < nHex; ++c)
        {
            for (const auto& hf : hexFaces)
            {
                const quad q{hexes_[c][hf[0]], hexes_[c][hf[1]],
                             hexes_[c][hf[2]], hexes_[c][hf[3]]};
                quad k = q;
                std::sort(k.begin(), k.end());
                const auto it = seen.find(k);
                if (it == seen.end())
                {
                    seen.emplace(k, std::make_pair(c, q));
                }
                else
                {
                    faces.push_back({it->second.second, it->second.first, c});
                }
            }
        }
    }

    // Per node: its hexahedra; per hexahedron: its interior faces
    std::vector<std::vector<std::size_t>> nodeHexes(nNodes), hexFacesOf(nHex);
    for (std::size_t c = 0; c < nHex; ++c)
    {
        for (const std::size_t n : hexes_[c]) nodeHexes[n].push_back(c);
    }
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
        hexFacesOf[faces[f].own].push_back(f);
        hexFacesOf[faces[f].nei].push_back(f);
    }

    const auto centre = [&](std::size_t c)
    {
        vec C{0, 0, 0};
        for (const std::size_t n : hexes_[c])
        {
            for (int a = 0; a < 3; ++a) C[a] += 0.125*nodes_[n][a];
        }
        return C;
    };
    // tan^4 of the face's non-orthogonality (GREAT if 90 deg or more)
    const auto faceCost = [&](std::size_t f, scalar& cosine)
    {
        const quad& q = faces[f].q;
        const vec& p0 = nodes_[q[0]];
        const vec& p1 = nodes_[q[1]];
        const vec& p2 = nodes_[q[2]];
        const vec& p3 = nodes_[q[3]];
        const vec a{p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
        const vec b{p3[0] - p1[0], p3[1] - p1[1], p3[2] - p1[2]};
        const vec n
        {
            a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2],
            a[0]*b[1] - a[1]*b[0]
        };
        const vec Co = centre(faces[f].own), Cn = centre(faces[f].nei);
        const vec d{Cn[0] - Co[0], Cn[1] - Co[1], Cn[2] - Co[2]};
        const scalar nn = std::sqrt(n[0]*n[0] + n[1]*n[1] + n[2]*n[2]);
        const scalar dd = std::sqrt(d[0]*d[0] + d[1]*d[1] + d[2]*d[2]);
        cosine = (n[0]*d[0] + n[1]*d[1] + n[2]*d[2])/(nn*dd + VSMALL);
        if (!(cosine > 1e-3))
        {
            return scalar(GREAT);
        }
        const scalar t2 = (1 - cosine*cosine)/(cosine*cosine);
        return t2*t2;
    };
    // The smallest scaled Jacobian of the hexahedron's eight corners
    // (each corner's three edges, in the gmsh hexahedron's right-handed
    // order: positive for a valid cell)
    const int corner[8][3] =
    {
        {1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
        {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}
    };
    const auto scaledJacobian = [&](std::size_t c)
    {
        scalar m = GREAT;
        for (int v = 0; v < 8; ++v)
        {
            const vec& o = nodes_[hexes_[c][v]];
            vec e[3];
            scalar len = 1;
            for (int a = 0; a < 3; ++a)
            {
                const vec& p = nodes_[hexes_[c][corner[v][a]]];
                e[a] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
                len *= std::sqrt
                    (e[a][0]*e[a][0] + e[a][1]*e[a][1] + e[a][2]*e[a][2]);
            }
            const scalar J =
                e[0][0]*(e[1][1]*e[2][2] - e[1][2]*e[2][1])
              + e[0][1]*(e[1][2]*e[2][0] - e[1][0]*e[2][2])
              + e[0][2]*(e[1][0]*e[2][1] - e[1][1]*e[2][0]);
            m = std::min(m, J/(len + VSMALL));
        }
        return m;
    };
    // The shortest of the hexahedron's twelve edges
    const int edges[12][2] =
    {
        {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4},
        {0, 4}, {1, 5}, {2, 6}, {3, 7}
    };
    const auto shortestEdge = [&](std::size_t c)
    {
        scalar m = GREAT;
        for (const auto& e : edges)
        {
            const vec& p = nodes_[hexes_[c][e[0]]];
            const vec& q = nodes_[hexes_[c][e[1]]];
            m = std::min
            (
                m, sqr(p[0] - q[0]) + sqr(p[1] - q[1]) + sqr(p[2] - q[2])
            );
        }
        return std::sqrt(m);
    };
    // The largest warp of the hexahedron's six faces: the distance of a
    // face's nodes from the plane through their mean normal to its
    // diagonals' cross product, over the shorter diagonal
    const auto warp = [&](std::size_t c)
    {
        scalar m = 0;
        for (const auto& hf : hexFaces)
        {
            const vec* p[4];
            for (int k = 0; k < 4; ++k) p[k] = &nodes_[hexes_[c][hf[k]]];
            const vec a{(*p[2])[0] - (*p[0])[0], (*p[2])[1] - (*p[0])[1],
                        (*p[2])[2] - (*p[0])[2]};
            const vec b{(*p[3])[0] - (*p[1])[0], (*p[3])[1] - (*p[1])[1],
                        (*p[3])[2] - (*p[1])[2]};
            vec n
            {
                a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2],
                a[0]*b[1] - a[1]*b[0]
            };
            const scalar ln = std::sqrt(n[0]*n[0] + n[1]*n[1] + n[2]*n[2]);
            const scalar dmin = std::sqrt(std::min
            (
                a[0]*a[0] + a[1]*a[1] + a[2]*a[2],
                b[0]*b[0] + b[1]*b[1] + b[2]*b[2]
            ));
            // The signed distance of node 0 from the plane through the
            // mean: all four are +-h for a quadrilateral
            vec C{0, 0, 0};
            for (int k = 0; k < 4; ++k)
            {
                for (int d = 0; d < 3; ++d) C[d] += 0.25*(*p[k])[d];
            }
            const scalar h = std::abs
            (
                ((*p[0])[0] - C[0])*n[0] + ((*p[0])[1] - C[1])*n[1]
              + ((*p[0])[2] - C[2])*n[2]
            )/(ln + VSMALL);
            m = std::max(m, h/(dmin + VSMALL));
        }
        return m;
    };
    // addHex orients every hexahedron by its centre Jacobian; the corners
    // of a moved one keep at least min(minScaledJacobian_, their own) and
    // its edges at least minEdgeFraction_ of its shortest (a scaled
    // Jacobian alone lets an edge shrink to nothing)
    std::vector<scalar> jMin(nHex), eMin(nHex), wMax(nHex);
    for (std::size_t c = 0; c < nHex; ++c)
    {
        jMin[c] = std::min(minScaledJacobian_, scaledJacobian(c));
        eMin[c] = minEdgeFraction_*shortestEdge(c);
        wMax[c] = std::max(maxWarp_, warp(c));
    }

    // The free nodes, their interior faces and their shortest edge
    std::vector<std::size_t> freeNodes;
    std::vector<std::vector<std::size_t>> nodeFaces(nNodes);
    std::vector<scalar> step(nNodes, 0), stepMax(nNodes, 0);
    for (std::size_t n = 0; n < nNodes; ++n)
    {
        if (!free[n]) continue;
        freeNodes.push_back(n);
        std::vector<std::size_t>& fs = nodeFaces[n];
        scalar lmin = GREAT;
        for (const std::size_t c : nodeHexes[n])
        {
            fs.insert(fs.end(), hexFacesOf[c].begin(), hexFacesOf[c].end());
            for (const std::size_t m : hexes_[c])
            {
                if (m == n) continue;
                const scalar l = std::sqrt
                (
                    sqr(nodes_[m][0] - nodes_[n][0])
                  + sqr(nodes_[m][1] - nodes_[n][1])
                  + sqr(nodes_[m][2] - nodes_[n][2])
                );
                lmin = std::min(lmin, l);
            }
        }
        std::sort(fs.begin(), fs.end());
        fs.erase(std::unique(fs.begin(), fs.end()), fs.end());
        stepMax[n] = step[n] = 0.25*lmin;
    }

    const auto totalCost = [&](scalar& worst)
    {
        scalar sum = 0, cmin = 1, c;
        for (std::size_t f = 0; f < faces.size(); ++f)
        {
            sum += faceCost(f, c);
            cmin = std::min(cmin, c);
        }
        worst = std::acos(std::max(-1.0, std::min(1.0, cmin)))
           *180/constant::mathematical::pi;
        return sum;
    };
    // The node's faces, and its distance from where the straight rays
    // put it (in its shortest edge's quarter, squared, times
    // displacementWeight_: where a move gains almost nothing, the node
    // stays, and the grid's spacing with it)
    const std::vector<vec> start(nodes_);
    // The node's edges (the other node, the length before)
    std::vector<std::vector<std::pair<std::size_t, scalar>>> nodeEdges(nNodes);
    for (const hex& h : hexes_)
    {
        for (const auto& e : edges)
        {
            const std::size_t p = h[e[0]], q = h[e[1]];
            const scalar l = std::sqrt
            (
                sqr(nodes_[p][0] - nodes_[q][0])
              + sqr(nodes_[p][1] - nodes_[q][1])
              + sqr(nodes_[p][2] - nodes_[q][2])
            );
            if (free[p]) nodeEdges[p].push_back({q, l});
            if (free[q]) nodeEdges[q].push_back({p, l});
        }
    }
    for (auto& ne : nodeEdges)
    {
        std::sort(ne.begin(), ne.end());
        ne.erase(std::unique(ne.begin(), ne.end()), ne.end());
    }
    const auto localCost = [&](std::size_t n)
    {
        scalar sum = 0, c;
        for (const std::size_t f : nodeFaces[n]) sum += faceCost(f, c);
        const vec& x = nodes_[n];
        const vec& x0 = start[n];
        for (const auto& e : nodeEdges[n])
        {
            const vec& y = nodes_[e.first];
            const scalar l = std::sqrt
                (sqr(x[0] - y[0]) + sqr(x[1] - y[1]) + sqr(x[2] - y[2]));
            sum += lengthWeight_*sqr((l - e.second)/e.second);
        }
        return sum + displacementWeight_
           *(sqr(x[0] - x0[0]) + sqr(x[1] - x0[1]) + sqr(x[2] - x0[2]))
           /sqr(stepMax[n]);
    };
    const auto valid = [&](std::size_t n)
    {
        for (const std::size_t c : nodeHexes[n])
        {
            if
            (
               !(
                    scaledJacobian(c) >= jMin[c]
                 && shortestEdge(c) >= eMin[c] && warp(c) <= wMax[c]
                )
            )
            {
                return false;
            }
        }
        return true;
    };
    // The move d with the fixed coordinates and the component along the
    // node's normal removed
    const auto constrain = [&](std::size_t n, vec& d)
    {
        const vec& nv = normal[n];
        const scalar dn = d[0]*nv[0] + d[1]*nv[1] + d[2]*nv[2];
        for (int a = 0; a < 3; ++a)
        {
            d[a] -= dn*nv[a];
            if (!(free[n] & (1u << a))) d[a] = 0;
        }
    };

    // The x <-> y mirror of every free node (the straight grid is
    // symmetric under the swap to round-off): the two move together, so
    // that the mesh stays symmetric (node by node in one order, the
    // sweeps would not keep it: up to 0.27 um apart on the item-1
    // quarter); a node on x = y is its own
    std::vector<std::size_t> mirror(nNodes, nNodes);
    {
        const scalar tol = 1e-9*s_.L, bin = 1e3*tol;
        typedef std::array<long long, 3> key;
        const auto keyOf = [&](const vec& p)
        {
            return key
            {
                static_cast<long long>(std::floor(p[0]/bin)),
                static_cast<long long>(std::floor(p[1]/bin)),
                static_cast<long long>(std::floor(p[2]/bin))
            };
        };
        std::map<key, std::vector<std::size_t>> bins;
        for (std::size_t n = 0; n < nNodes; ++n)
        {
            bins[keyOf(nodes_[n])].push_back(n);
        }
        for (const std::size_t n : freeNodes)
        {
            const vec q{nodes_[n][1], nodes_[n][0], nodes_[n][2]};
            const key k = keyOf(q);
            for (long long a = -1; a <= 1; ++a)
            for (long long b = -1; b <= 1; ++b)
            for (long long c = -1; c <= 1; ++c)
            {
                const auto it = bins.find({k[0] + a, k[1] + b, k[2] + c});
                if (it == bins.end()) continue;
                for (const std::size_t m : it->second)
                {
                    if
                    (
                        std::abs(nodes_[m][0] - q[0]) < tol
                     && std::abs(nodes_[m][1] - q[1]) < tol
                     && std::abs(nodes_[m][2] - q[2]) < tol
                    )
                    {
                        mirror[n] = m;
                    }
                }
            }
            if (mirror[n] == nNodes || !free[mirror[n]])
            {
                FatalErrorInFunction
                    << "The node at (" << nodes_[n][0] << " " << nodes_[n][1]
                    << " " << nodes_[n][2] << ") m has no free mirror node"
                    << " across x = y" << exit(FatalError);
            }
        }
    }

    scalar cost = totalCost(nonOrthoBefore_);
    for (sweeps_ = 0; sweeps_ < maxSweeps_; )
    {
        for (const std::size_t n : freeNodes)
        {
            const std::size_t m = mirror[n];
            if (m < n) continue;    // moved with its mirror
            const bool self = m == n;
            vec& x = nodes_[n];
            vec& y = nodes_[m];
            const vec x0 = x, y0 = y;
            const auto pairCost = [&]()
            {
                return self ? localCost(n) : localCost(n) + localCost(m);
            };
            const auto place = [&](const vec& p)
            {
                x = p;
                if (!self) y = {p[1], p[0], p[2]};
            };
            const auto restore = [&]()
            {
                x = x0;
                y = y0;
            };
            // On x = y the move stays on it
            const auto diagonal = [&](vec& d)
            {
                if (self) d[0] = d[1] = 0.5*(d[0] + d[1]);
            };
            const scalar e0 = pairCost();
            // Central differences of the local sum
            const scalar h = 1e-4*stepMax[n];
            vec g{0, 0, 0};
            for (int a = 0; a < 3; ++a)
            {
                if (!(free[n] & (1u << a))) continue;
                vec p = x0;
                p[a] = x0[a] + h;
                place(p);
                const scalar ep = pairCost();
                p[a] = x0[a] - h;
                place(p);
                const scalar em = pairCost();
                restore();
                g[a] = (ep - em)/(2*h);
            }
            constrain(n, g);
            diagonal(g);
            const scalar gn = std::sqrt(g[0]*g[0] + g[1]*g[1] + g[2]*g[2]);
            if (!(gn > 0) || !std::isfinite(gn)) continue;
            // Backtracking along -g from the node's last step
            bool moved = false;
            scalar alpha = step[n];
            for (int tries = 0; tries < 8 && !moved; ++tries, alpha *= 0.5)
            {
                vec d{-alpha*g[0]/gn, -alpha*g[1]/gn, -alpha*g[2]/gn};
                constrain(n, d);
                diagonal(d);
                vec p = x0;
                for (int a = 0; a < 3; ++a)
                {
                    if (free[n] & (1u << a)) p[a] = x0[a] + d[a];
                }
                if (free[n] & 8u)
                {
                    // Back onto the spheroid (a scaling: zeros stay)
                    p = project(p);
                }
                place(p);
                if (pairCost() < e0 && valid(n) && (self || valid(m)))
                {
                    moved = true;
                    step[n] = std::min(2*alpha, stepMax[n]);
                }
                else
                {
                    restore();
                }
            }
            if (!moved) step[n] *= 0.5;
        }
        ++sweeps_;
        scalar worst;
        const scalar next = totalCost(worst);
        const bool done = !(cost - next > smoothTol_*cost);
        cost = next;
        nonOrthoAfter_ = worst;
        if (done) break;
    }
}


void Foam::hexFluidMesh::classifyBoundary(const std::vector<bool>& onCell)
{
    struct keyHash
    {
        std::size_t operator()(const quad& k) const
        {
            std::size_t h = 0;
            for (const std::size_t v : k) h = h*1000003u ^ v;
            return h;
        }
    };
    // Faces of the gmsh hexahedron (outward for a positive Jacobian)
    const int hexFaces[6][4] =
    {
        {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
        {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}
    };
    std::unordered_map<quad, std::pair<label, quad>, keyHash> count;
    count.reserve(3*hexes_.size() + 1000);
    for (const hex& h : hexes_)
    {
        for (const auto& hf : hexFaces)
        {
            const quad q{h[hf[0]], h[hf[1]], h[hf[2]], h[hf[3]]};
            quad k = q;
            std::sort(k.begin(), k.end());
            auto& c = count[k];
            if (++c.first == 1) c.second = q;
        }
    }
    const scalar tol = 1e-9*s_.L;
    const auto all = [&](const quad& q, int c, scalar v)
    {
        for (const std::size_t n : q)
        {
            if (std::abs(nodes_[n][c] - v) > tol) return false;
        }
        return true;
    };
    for (const auto& kv : count)
    {
        const label n = kv.second.first;
        const quad& q = kv.second.second;
        if (n > 2)
        {
            FatalErrorInFunction
                << "A water face is shared by " << n << " hexahedra"
                << exit(FatalError);
        }
        if (n == 2) continue;
        const scalar h = 0.5*s_.L;
        const char* name =
            all(q, 2, 0) ? "bottom"
          : all(q, 2, s_.height) ? "top"
          : all(q, 0, h) || all(q, 1, h) || all(q, 0, -h) || all(q, 1, -h)
          ? "sides"
          : s_.quarter && all(q, 0, 0) ? "symmetryX"
          : s_.quarter && all(q, 1, 0) ? "symmetryY"
          : onCell[q[0]] && onCell[q[1]] && onCell[q[2]] && onCell[q[3]]
          ? "cellInterface"
          : nullptr;
        if (!name)
        {
            FatalErrorInFunction
                << "A boundary face of the hexahedral water at ("
                << nodes_[q[0]][0] << " " << nodes_[q[0]][1] << " "
                << nodes_[q[0]][2] << ") m is on no patch: the grid is "
                << "not conformal" << exit(FatalError);
        }
        faces_[name].push_back(q);
    }
    // Deterministic order of the patch faces (the hash map's is not)
    for (auto& kv : faces_)
    {
        std::sort(kv.second.begin(), kv.second.end());
    }
}


void Foam::hexFluidMesh::toGmsh(scalar unit) const
{
    gmsh::model::addDiscreteEntity(3, 1);
    std::vector<std::size_t> tags(nodes_.size());
    std::vector<double> xyz;
    xyz.reserve(3*nodes_.size());
    for (std::size_t n = 0; n < nodes_.size(); ++n)
    {
        tags[n] = n + 1;
        for (int c = 0; c < 3; ++c) xyz.push_back(nodes_[n][c]/unit);
    }
    gmsh::model::mesh::addNodes(3, 1, tags, xyz);

    std::size_t next = 1;
    std::vector<std::size_t> et, nt;
    for (const hex& h : hexes_)
    {
        et.push_back(next++);
        for (const std::size_t n : h) nt.push_back(n + 1);
    }
    gmsh::model::mesh::addElementsByType(1, 5, et, nt);
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}),
        "water");
    int surface = 0;
    for (const auto& kv : faces_)
    {
        gmsh::model::addDiscreteEntity(2, ++surface);
        et.clear();
        nt.clear();
        for (const quad& q : kv.second)
        {
            et.push_back(next++);
            for (const std::size_t n : q) nt.push_back(n + 1);
        }
        gmsh::model::mesh::addElementsByType(surface, 3, et, nt);
        gmsh::model::setPhysicalName
        (
            2, gmsh::model::addPhysicalGroup(2, {surface}), kv.first
        );
    }
}
