#include "InterfacePatch.H"
#include "SolidError.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace
{

[[noreturn]] void fail(const std::string& msg)
{
    throw solid::SolidError(solid::SolidError::Kind::parameter,
        "interface patch: " + msg);
}

void checkSize(double size)
{
    if (!(size > 0) || !std::isfinite(size))
    {
        fail("size " + std::to_string(size) + " m: must be > 0");
    }
}

void checkRegion(const solid::Mesh& m, int r)
{
    if (r < 0 || r >= int(m.regionNames.size()))
    {
        fail("region id " + std::to_string(r) + " not in the mesh");
    }
}

//- The integral of q (piecewise constant, q[i] on [b[i], b[i + 1]]) from
//  b[0] to x, with prefix P[i] = the integral to b[i]
double integral
(
    const std::vector<double>& b,
    const std::vector<double>& P,
    const std::vector<double>& q,
    double x
)
{
    const std::size_t n = q.size();
    if (x <= b[0]) return 0;
    if (x >= b[n]) return P[n];
    const std::size_t i =
        std::upper_bound(b.begin(), b.end(), x) - b.begin() - 1;
    return P[i] + q[i]*(x - b[i]);
}

//- The point at arc length x along points (ends of pieces b)
solid::Vec3 pointAt
(
    const std::vector<double>& b,
    const std::vector<solid::Vec3>& pts,
    double x
)
{
    const std::size_t n = b.size() - 1;
    x = std::min(std::max(x, b[0]), b[n]);
    std::size_t i = std::upper_bound(b.begin(), b.end(), x) - b.begin();
    i = std::min(std::max<std::size_t>(i, 1), n) - 1;
    const double l = b[i + 1] - b[i];
    const double s = l > 0 ? (x - b[i])/l : 0;
    return (1 - s)*pts[i] + s*pts[i + 1];
}

} // namespace


solid::InterfacePatch::InterfacePatch
(
    const Mesh& m,
    int a,
    int b,
    double size
)
:
    size_(size),
    axisymmetric_(m.axisymmetric()),
    twoSided_(true)
{
    checkSize(size);
    checkRegion(m, a);
    checkRegion(m, b);
    if (a == b) fail("a region paired with itself");
    // The faces of a's elements by their sorted nodes
    const auto& local = elementFaces(m.type);
    std::map<std::vector<int>, std::pair<int, int>> facesOfA;
    for (int e = 0; e < m.nElements(); ++e)
    {
        if (m.region[e] != a) continue;
        for (std::size_t k = 0; k < local.size(); ++k)
        {
            std::vector<int> key;
            for (const int l : local[k]) key.push_back(m.element(e)[l]);
            std::sort(key.begin(), key.end());
            facesOfA[key] = {e, int(k)};
        }
    }
    for (int e = 0; e < m.nElements(); ++e)
    {
        if (m.region[e] != b) continue;
        for (std::size_t k = 0; k < local.size(); ++k)
        {
            std::vector<int> key;
            for (const int l : local[k]) key.push_back(m.element(e)[l]);
            std::sort(key.begin(), key.end());
            const auto it = facesOfA.find(key);
            if (it == facesOfA.end()) continue;
            Facet f;
            const int ea = it->second.first;
            for (const int l : local[it->second.second])
            {
                f.nodes.push_back(m.element(ea)[l]);
            }
            f.element[0] = ea;
            f.element[1] = e;
            facets_.push_back(f);
        }
    }
    if (facets_.empty())
    {
        fail("regions " + m.regionNames[a] + " and " + m.regionNames[b]
            + " share no face");
    }
    // The band: elements of either region with a node on the other
    std::vector<char> inA(m.nNodes(), 0), inB(m.nNodes(), 0);
    for (int e = 0; e < m.nElements(); ++e)
    {
        for (int k = 0; k < m.nen(); ++k)
        {
            if (m.region[e] == a) inA[m.element(e)[k]] = 1;
            if (m.region[e] == b) inB[m.element(e)[k]] = 1;
        }
    }
    for (int e = 0; e < m.nElements(); ++e)
    {
        if (m.region[e] != a && m.region[e] != b) continue;
        const std::vector<char>& other = m.region[e] == a ? inB : inA;
        for (int k = 0; k < m.nen(); ++k)
        {
            if (other[m.element(e)[k]])
            {
                band_.push_back(e);
                break;
            }
        }
    }
    build(m);
}


solid::InterfacePatch::InterfacePatch
(
    const Mesh& m,
    int a,
    const std::vector<char>& boundaryNode,
    double size
)
:
    size_(size),
    axisymmetric_(m.axisymmetric()),
    twoSided_(false)
{
    checkSize(size);
    checkRegion(m, a);
    if (int(boundaryNode.size()) != m.nNodes())
    {
        fail("boundary marks for " + std::to_string(boundaryNode.size())
            + " nodes, the mesh has " + std::to_string(m.nNodes()));
    }
    const auto& local = elementFaces(m.type);
    std::map<std::vector<int>, int> count;
    for (int e = 0; e < m.nElements(); ++e)
    {
        for (const auto& face : local)
        {
            std::vector<int> key;
            for (const int l : face) key.push_back(m.element(e)[l]);
            std::sort(key.begin(), key.end());
            ++count[key];
        }
    }
    for (int e = 0; e < m.nElements(); ++e)
    {
        if (m.region[e] != a) continue;
        bool inBand = false;
        for (const auto& face : local)
        {
            std::vector<int> nodes, key;
            bool onBoundary = true;
            for (const int l : face)
            {
                const int n = m.element(e)[l];
                nodes.push_back(n);
                onBoundary = onBoundary && boundaryNode[n];
                inBand = inBand || boundaryNode[n];
            }
            key = nodes;
            std::sort(key.begin(), key.end());
            if (!onBoundary || count[key] != 1) continue;
            Facet f;
            f.nodes = nodes;
            f.element[0] = e;
            facets_.push_back(f);
        }
        if (inBand) band_.push_back(e);
    }
    if (facets_.empty())
    {
        fail("no face of region " + m.regionNames[a] + " on the boundary");
    }
    build(m);
}


void solid::InterfacePatch::build(const Mesh& m)
{
    for (Facet& f : facets_)
    {
        const Vec3& X0 = m.X[f.nodes[0]];
        const Vec3& X1 = m.X[f.nodes[1]];
        if (axisymmetric_)
        {
            const Vec3 d(X1 - X0);
            f.size = d.norm();
            f.centroid = 0.5*(X0 + X1);
            if (f.size > 0) f.normal = Vec3(d(1), -d(0), 0)/f.size;
        }
        else
        {
            const Vec3& X2 = m.X[f.nodes[2]];
            const Vec3& X3 = m.X[f.nodes[3]];
            const Vec3 c((X2 - X0).cross(X3 - X1));
            f.size = 0.5*c.norm();
            f.centroid = 0.25*(X0 + X1 + X2 + X3);
            if (f.size > 0) f.normal = c.normalized();
        }
        for (const int e : f.element)
        {
            if (e >= 0) elements_.push_back(e);
        }
    }
    std::sort(band_.begin(), band_.end());
    band_.erase(std::unique(band_.begin(), band_.end()), band_.end());
    elements_.insert(elements_.end(), band_.begin(), band_.end());
    std::sort(elements_.begin(), elements_.end());
    elements_.erase(std::unique(elements_.begin(), elements_.end()),
        elements_.end());
    if (axisymmetric_)
    {
        buildChains(m);
    }
    else
    {
        buildBalls(m);
    }
}


void solid::InterfacePatch::buildChains(const Mesh& m)
{
    // The facets at each node; a curve runs through nodes of two facets
    std::map<int, std::vector<int>> at;
    for (std::size_t f = 0; f < facets_.size(); ++f)
    {
        for (const int n : facets_[f].nodes) at[n].push_back(int(f));
    }
    std::vector<char> used(facets_.size(), 0);
    const auto walk = [&](int node, int f, bool closed)
    {
        Chain c;
        c.closed = closed;
        c.points.push_back(m.X[node]);
        while (f >= 0 && !used[f])
        {
            used[f] = 1;
            const std::vector<int>& n = facets_[f].nodes;
            node = n[0] == node ? n[1] : n[0];
            c.facets.push_back(f);
            c.points.push_back(m.X[node]);
            const std::vector<int>& there = at[node];
            f = there.size() == 2 ? (there[0] == f ? there[1] : there[0]) : -1;
        }
        chains_.push_back(c);
    };
    // Open curves from their ends (and from junctions of three or more)
    for (const auto& [node, fs] : at)
    {
        if (fs.size() == 2) continue;
        for (const int f : fs)
        {
            if (!used[f]) walk(node, f, false);
        }
    }
    // Closed curves
    for (std::size_t f = 0; f < facets_.size(); ++f)
    {
        if (!used[f]) walk(facets_[f].nodes[0], int(f), true);
    }
}


void solid::InterfacePatch::buildBalls(const Mesh& m)
{
    // Each facet's 6 x 6 sub-cells (bilinear map, midpoint rule): their
    // centres and areas
    constexpr int n = 6;
    sub_.assign(facets_.size(), {});
    subArea_.assign(facets_.size(), {});
    reach_.assign(facets_.size(), 0);
    for (std::size_t f = 0; f < facets_.size(); ++f)
    {
        const std::vector<int>& nd = facets_[f].nodes;
        const Vec3 &X0 = m.X[nd[0]], &X1 = m.X[nd[1]], &X2 = m.X[nd[2]],
            &X3 = m.X[nd[3]];
        double total = 0;
        for (int i = 0; i < n; ++i)
        {
            for (int j = 0; j < n; ++j)
            {
                const double u = (i + 0.5)/n, v = (j + 0.5)/n;
                const Vec3 X((1 - u)*(1 - v)*X0 + u*(1 - v)*X1 + u*v*X2
                    + (1 - u)*v*X3);
                const Vec3 du((1 - v)*(X1 - X0) + v*(X2 - X3));
                const Vec3 dv((1 - u)*(X3 - X0) + u*(X2 - X1));
                const double A = du.cross(dv).norm()/(n*n);
                sub_[f].push_back(X);
                subArea_[f].push_back(A);
                total += A;
            }
        }
        facets_[f].size = total;
        for (const int k : nd)
        {
            reach_[f] = std::max(reach_[f],
                (m.X[k] - facets_[f].centroid).norm());
        }
    }
    for (std::size_t k = 0; k < facets_.size(); ++k)
    {
        Ball b(ballAround(facets_[k].centroid, int(k)));
        if (b.area > 0) balls_.push_back(b);
    }
}


solid::InterfacePatch::Ball solid::InterfacePatch::ballAround
(
    const Vec3& c,
    int centre
) const
{
    const double radius = 0.5*size_;
    Ball b;
    b.centre = centre;
    for (std::size_t f = 0; f < facets_.size(); ++f)
    {
        if ((facets_[f].centroid - c).norm() > radius + reach_[f])
        {
            continue;
        }
        double A = 0;
        for (std::size_t s = 0; s < sub_[f].size(); ++s)
        {
            if ((sub_[f][s] - c).norm() <= radius) A += subArea_[f][s];
        }
        if (A > 0)
        {
            b.facets.push_back(int(f));
            b.areas.push_back(A);
            b.area += A;
        }
    }
    return b;
}


void solid::InterfacePatch::unroll
(
    const Chain& c,
    const std::vector<double>& q,
    std::vector<double>& b,
    std::vector<double>& P,
    std::vector<double>& v,
    std::vector<Vec3>& pts
) const
{
    const std::size_t n = c.facets.size();
    const std::size_t rounds = c.closed ? 2 : 1;
    b.assign(1, 0);
    P.assign(1, 0);
    v.clear();
    pts.assign(1, c.points[0]);
    for (std::size_t r = 0; r < rounds; ++r)
    {
        for (std::size_t i = 0; i < n; ++i)
        {
            const Facet& f = facets_[c.facets[i]];
            v.push_back(q[c.facets[i]]);
            b.push_back(b.back() + f.size);
            P.push_back(P.back() + q[c.facets[i]]*f.size);
            pts.push_back(c.points[i + 1]);
        }
    }
}


double solid::InterfacePatch::chainMaximum
(
    const Chain& c,
    const std::vector<double>& q,
    Vec3& at
) const
{
    // The curve's pieces (a closed curve twice: windows across its start)
    const std::size_t n = c.facets.size();
    std::vector<double> b, P, v;
    std::vector<Vec3> pts;
    unroll(c, q, b, P, v, pts);
    const double S = b[n];
    const double L = size_;
    if (S <= L)
    {
        at = pointAt(b, pts, 0.5*S);
        return P[n]/S;
    }
    // Window starts x in [0, xEnd]: where an end of the window is at a
    // piece's end
    const double xEnd = c.closed ? S : S - L;
    double best = -std::numeric_limits<double>::infinity();
    double bestX = 0;
    const auto tryAt = [&](double x)
    {
        x = std::min(std::max(x, 0.0), xEnd);
        const double mean =
            (integral(b, P, v, x + L) - integral(b, P, v, x))/L;
        if (mean > best)
        {
            best = mean;
            bestX = x;
        }
    };
    for (std::size_t i = 0; i < b.size(); ++i)
    {
        if (b[i] <= xEnd) tryAt(b[i]);
        if (b[i] >= L && b[i] - L <= xEnd) tryAt(b[i] - L);
    }
    tryAt(xEnd);
    at = pointAt(b, pts, bestX + 0.5*L);
    return best;
}


double solid::InterfacePatch::largestMean
(
    const std::vector<double>& q,
    Vec3& at
) const
{
    if (q.size() != facets_.size())
    {
        fail(std::to_string(q.size()) + " values for "
            + std::to_string(facets_.size()) + " facets");
    }
    double best = -std::numeric_limits<double>::infinity();
    if (axisymmetric_)
    {
        for (const Chain& c : chains_)
        {
            Vec3 x;
            const double mean = chainMaximum(c, q, x);
            if (mean > best)
            {
                best = mean;
                at = x;
            }
        }
    }
    else
    {
        for (const Ball& ball : balls_)
        {
            double s = 0;
            for (std::size_t i = 0; i < ball.facets.size(); ++i)
            {
                s += ball.areas[i]*q[ball.facets[i]];
            }
            const double mean = s/ball.area;
            if (mean > best)
            {
                best = mean;
                at = facets_[ball.centre].centroid;
            }
        }
    }
    return best;
}


std::size_t solid::InterfacePatch::addPlace(const Vec3& X)
{
    if (!X.allFinite()) fail("a place's point is not finite");
    Place pl;
    if (axisymmetric_)
    {
        // The curves' point nearest X (in the r-z plane) and its arc
        // length on its curve
        double best = std::numeric_limits<double>::infinity();
        double s = 0;
        for (std::size_t k = 0; k < chains_.size(); ++k)
        {
            const Chain& c = chains_[k];
            double b = 0;
            for (std::size_t i = 0; i < c.facets.size(); ++i)
            {
                const Vec3 A(c.points[i](0), c.points[i](1), 0);
                const Vec3 B(c.points[i + 1](0), c.points[i + 1](1), 0);
                const Vec3 P(X(0), X(1), 0);
                const double l2 = (B - A).squaredNorm();
                const double t = l2 > 0
                  ? std::min(1.0, std::max(0.0, (P - A).dot(B - A)/l2))
                  : 0.0;
                const double d = (A + t*(B - A) - P).norm();
                const double len = facets_[c.facets[i]].size;
                if (d < best)
                {
                    best = d;
                    pl.chain = int(k);
                    s = b + t*len;
                }
                b += len;
            }
        }
        const Chain& c = chains_[pl.chain];
        double S = 0;
        for (const int f : c.facets) S += facets_[f].size;
        if (S <= size_)
        {
            pl.start = 0;
        }
        else if (c.closed)
        {
            pl.start = s - 0.5*size_;
            if (pl.start < 0) pl.start += S;
        }
        else
        {
            pl.start = std::min(std::max(s - 0.5*size_, 0.0), S - size_);
        }
        std::vector<double> b, P, v;
        std::vector<Vec3> pts;
        unroll(c, std::vector<double>(facets_.size(), 0), b, P, v, pts);
        pl.centre = pointAt(b, pts, pl.start + 0.5*std::min(S, size_));
    }
    else
    {
        // The sub-cell centre nearest X, the ball around it
        double best = std::numeric_limits<double>::infinity();
        int centre = -1;
        for (std::size_t f = 0; f < facets_.size(); ++f)
        {
            for (const Vec3& Y : sub_[f])
            {
                const double d = (Y - X).norm();
                if (d < best)
                {
                    best = d;
                    centre = int(f);
                    pl.centre = Y;
                }
            }
        }
        pl.ball = ballAround(pl.centre, centre);
    }
    places_.push_back(pl);
    return places_.size() - 1;
}


const solid::Vec3& solid::InterfacePatch::placeCentre(std::size_t i) const
{
    if (i >= places_.size())
    {
        fail("place " + std::to_string(i) + " of "
            + std::to_string(places_.size()));
    }
    return places_[i].centre;
}


double solid::InterfacePatch::meanAt
(
    const std::vector<double>& q,
    std::size_t i
) const
{
    if (q.size() != facets_.size())
    {
        fail(std::to_string(q.size()) + " values for "
            + std::to_string(facets_.size()) + " facets");
    }
    placeCentre(i);     // the index checked
    const Place& pl = places_[i];
    if (axisymmetric_)
    {
        std::vector<double> b, P, v;
        std::vector<Vec3> pts;
        unroll(chains_[pl.chain], q, b, P, v, pts);
        const std::size_t n = chains_[pl.chain].facets.size();
        const double S = b[n];
        if (S <= size_) return P[n]/S;
        return (integral(b, P, v, pl.start + size_)
            - integral(b, P, v, pl.start))/size_;
    }
    double s = 0;
    for (std::size_t k = 0; k < pl.ball.facets.size(); ++k)
    {
        s += pl.ball.areas[k]*q[pl.ball.facets[k]];
    }
    return s/pl.ball.area;
}


double solid::InterfacePatch::shear(const Mat3& sigma, const Vec3& n)
{
    // Of the deviatoric part (the same value: the isotropic part's
    // traction is normal): sigma's diagonal is the pressure's size (1e8
    // Pa in the blast), the shear a few Pa, and the traction's tangential
    // part computed from sigma itself loses it to round-off
    const Mat3 d(sigma - sigma.trace()/3.0*Mat3::Identity());
    const Vec3 t(d*n);
    return (t - n.dot(t)*n).norm();
}


solid::InterfaceMeasures solid::InterfacePatch::evaluate
(
    const std::function<const ElementStress&(int)>& stress
) const
{
    InterfaceMeasures r;
    r.pMax = -std::numeric_limits<double>::infinity();
    for (const int e : band_)
    {
        const ElementStress& s = stress(e);
        r.pMax = std::max(r.pMax, s.p);
        r.vonMisesMax = std::max(r.vonMisesMax, tensor::vonMises(s.sigma));
    }
    r.pPatch = r.vonMisesPatch = r.shearPatch =
        -std::numeric_limits<double>::infinity();
    const double lowest = -std::numeric_limits<double>::infinity();
    r.pAt.assign(places_.size(), lowest);
    r.vonMisesAt.assign(places_.size(), lowest);
    r.shearAt.assign(places_.size(), lowest);
    const std::size_t nf = facets_.size();
    std::vector<double> p(nf), vm(nf), tau(nf);
    for (int side = 0; side < (twoSided_ ? 2 : 1); ++side)
    {
        for (std::size_t f = 0; f < nf; ++f)
        {
            const ElementStress& s = stress(facets_[f].element[side]);
            p[f] = s.p;
            vm[f] = tensor::vonMises(s.sigma);
            tau[f] = shear(s.sigma, facets_[f].normal);
            r.shearMax = std::max(r.shearMax, tau[f]);
        }
        Vec3 at;
        r.pPatch = std::max(r.pPatch, largestMean(p, at));
        r.shearPatch = std::max(r.shearPatch, largestMean(tau, at));
        const double v = largestMean(vm, at);
        if (v > r.vonMisesPatch)
        {
            r.vonMisesPatch = v;
            r.vonMisesPatchAt = at;
        }
        for (std::size_t i = 0; i < places_.size(); ++i)
        {
            r.pAt[i] = std::max(r.pAt[i], meanAt(p, i));
            r.vonMisesAt[i] = std::max(r.vonMisesAt[i], meanAt(vm, i));
            r.shearAt[i] = std::max(r.shearAt[i], meanAt(tau, i));
        }
    }
    return r;
}
