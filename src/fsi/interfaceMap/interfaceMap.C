#include "interfaceMap.H"
#include "fsiRanges.H"
#include "inputChecks.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"
#include "SubField.H"
#include "Loads.H"

#include <map>

namespace
{

using Foam::vector;
using Foam::scalar;

// Closest point of triangle (a, b, c) to p as barycentric weights
// (Ericson, Real-Time Collision Detection, 2005, sec. 5.1.5)
Foam::FixedList<scalar, 3> closestOnTriangle
(
    const vector& p, const vector& a, const vector& b, const vector& c
)
{
    const vector ab = b - a, ac = c - a, ap = p - a;
    const scalar d1 = ab & ap, d2 = ac & ap;
    if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
    const vector bp = p - b;
    const scalar d3 = ab & bp, d4 = ac & bp;
    if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
    const scalar vc = d1*d4 - d3*d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
        const scalar v = d1/(d1 - d3);
        return {1 - v, v, 0};
    }
    const vector cp = p - c;
    const scalar d5 = ab & cp, d6 = ac & cp;
    if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
    const scalar vb = d5*d2 - d1*d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
        const scalar w = d2/(d2 - d6);
        return {1 - w, 0, w};
    }
    const scalar va = d3*d6 - d5*d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    {
        const scalar w = (d4 - d3)/((d4 - d3) + (d5 - d6));
        return {0, 1 - w, w};
    }
    const scalar denom = 1/(va + vb + vc);
    const scalar v = vb*denom, w = vc*denom;
    return {1 - v - w, v, w};
}

// Weights that add up to 1, rounded to multiples of 2^-32 and scaled back
// to sum 1: weights equal in exact arithmetic (symmetric faces, matching
// meshes) become bitwise equal, so that a symmetric load stays symmetric
// (a round-off asymmetry seeds the zero-stiffness modes of a fluid-like
// solid, which an added-mass-prone coupling amplifies: fsi.addedMass)
void snapWeights(Foam::UList<scalar>& w)
{
    const scalar q = std::ldexp(1.0, 32);
    scalar sum = 0;
    for (scalar& x : w)
    {
        x = std::round(x*q)/q;
        sum += x;
    }
    if (sum > 0)
    {
        for (scalar& x : w) x /= sum;
    }
}

// Compensated sum (Neumaier) of products w*x with their exact rounding
// errors (fma): the result does not depend on the order of the terms
// (except in rare ties), so that symmetric weights give bitwise symmetric
// values whatever the numbering
struct exactSum
{
    scalar s = 0, c = 0;

    void add(const scalar x)
    {
        const scalar t = s + x;
        c += std::abs(s) >= std::abs(x) ? (s - t) + x : (x - t) + s;
        s = t;
    }

    void addProduct(const scalar w, const scalar x)
    {
        const scalar p = w*x;
        add(p);
        add(std::fma(w, x, -p));
    }

    scalar value() const { return s + c; }
};

} // namespace


Foam::vector Foam::interfaceMap::solidPoint(const label i) const
{
    const solid::Vec3& X = solidMesh_.X[nodes_[i]];
    return vector(X[0], X[1], axisymmetric_ ? 0 : X[2]);
}


Foam::vector Foam::interfaceMap::toSolidFrame
(
    const point& p,
    vector& radial
) const
{
    if (!axisymmetric_)
    {
        radial = Zero;
        return p;
    }
    const vector d = p - axisOrigin_;
    const scalar z = d & axisDirection_;
    const vector rv = d - z*axisDirection_;
    const scalar r = mag(rv);
    radial = r > VSMALL ? rv/r : Zero;
    return vector(r, z, 0);
}


Foam::interfaceMap::stencil Foam::interfaceMap::project(const vector& x) const
{
    stencil best;
    best.distance = GREAT;
    forAll(faces_, facei)
    {
        const labelList& f = faces_[facei];
        if (axisymmetric_)
        {
            const vector a = solidPoint(f[0]), b = solidPoint(f[1]);
            const vector ab = b - a;
            const scalar t =
                min(max(((x - a) & ab)/max(magSqr(ab), VSMALL), 0), 1);
            const scalar d = mag(x - (a + t*ab));
            if (d < best.distance)
            {
                best.distance = d;
                best.face = facei;
                best.node = {f[0], f[1], f[1], f[1]};
                best.weight = {1 - t, t, 0, 0};
            }
            continue;
        }
        if (f.size() == 4)
        {
            // Bilinear quadrilateral: Gauss-Newton on the local coordinates
            const vector X[4] =
                {solidPoint(f[0]), solidPoint(f[1]),
                 solidPoint(f[2]), solidPoint(f[3])};
            const scalar xs[4] = {-1, 1, 1, -1}, es[4] = {-1, -1, 1, 1};
            scalar xi = 0, eta = 0;
            FixedList<scalar, 4> N;
            vector xp(Zero);
            for (label it = 0; it < 20; ++it)
            {
                vector dxi(Zero), deta(Zero);
                xp = Zero;
                for (label a = 0; a < 4; ++a)
                {
                    N[a] = 0.25*(1 + xs[a]*xi)*(1 + es[a]*eta);
                    xp += N[a]*X[a];
                    dxi += 0.25*xs[a]*(1 + es[a]*eta)*X[a];
                    deta += 0.25*es[a]*(1 + xs[a]*xi)*X[a];
                }
                const vector g = x - xp;
                const scalar a11 = dxi & dxi, a12 = dxi & deta,
                    a22 = deta & deta;
                const scalar det = a11*a22 - a12*a12;
                if (det <= VSMALL) break;
                const scalar b1 = dxi & g, b2 = deta & g;
                const scalar dx = (a22*b1 - a12*b2)/det;
                const scalar de = (a11*b2 - a12*b1)/det;
                xi = min(max(xi + dx, -1), 1);
                eta = min(max(eta + de, -1), 1);
                if (mag(dx) + mag(de) < 1e-12) break;
            }
            xp = Zero;
            for (label a = 0; a < 4; ++a)
            {
                N[a] = 0.25*(1 + xs[a]*xi)*(1 + es[a]*eta);
                xp += N[a]*X[a];
            }
            const scalar d = mag(x - xp);
            if (d < best.distance)
            {
                best.distance = d;
                best.face = facei;
                best.node = {f[0], f[1], f[2], f[3]};
                best.weight = N;
            }
            continue;
        }
        for (label k = 1; k + 1 < f.size(); ++k)
        {
            const label i0 = f[0], i1 = f[k], i2 = f[k + 1];
            const vector a = solidPoint(i0), b = solidPoint(i1),
                c = solidPoint(i2);
            const FixedList<scalar, 3> w = closestOnTriangle(x, a, b, c);
            const scalar d = mag(x - (w[0]*a + w[1]*b + w[2]*c));
            if (d < best.distance)
            {
                best.distance = d;
                best.face = facei;
                best.node = {i0, i1, i2, i2};
                best.weight = {w[0], w[1], w[2], 0};
            }
        }
    }
    return best;
}


Foam::List<Foam::interfaceMap::stencil> Foam::interfaceMap::projectAll
(
    const vectorField& xs,
    const pointField& pts,
    const scalar tol,
    const word& what,
    const UList<scalar>& hFluid
) const
{
    List<stencil> st(xs.size());
    label nOut = 0;
    scalar worst = 0;
    point worstPoint(Zero);
    forAll(xs, i)
    {
        st[i] = project(xs[i]);
        // Size of the nearest solid face: its longest edge
        scalar h = 0;
        for (label a = 0; a < 4; ++a)
        {
            for (label b = a + 1; b < 4; ++b)
            {
                h = max
                (
                    h,
                    mag(solidPoint(st[i].node[a]) - solidPoint(st[i].node[b]))
                );
            }
        }
        if (hFluid.size())
        {
            h = max(h, hFluid[i]);
        }
        if (st[i].distance > tol*h)
        {
            ++nOut;
            if (st[i].distance > worst)
            {
                worst = st[i].distance;
                worstPoint = pts[i];
            }
        }
    }
    if (nOut)
    {
        FatalErrorInFunction
            << "FSI interface: " << nOut << " of " << xs.size()
            << " fluid " << what << " lie off the solid interface (no"
            << " overlap of the two sides); worst " << worstPoint
            << " at " << worst << " m (mapTolerance " << tol
            << " x solid face size"
            << (hFluid.size() ? word(", or fluid face size if larger") : word())
            << "). Check the fluid patch, the solid face"
            << " set and the units of both meshes (constant/fsiProperties"
            << " interface: fluidPatch, solidFaceSet, mapTolerance;"
            << " constant/solidProperties: mesh)." << exit(FatalError);
    }
    return st;
}


Foam::scalarField Foam::interfaceMap::faceSizes
(
    const globalInterfacePatch& fluidPatch
)
{
    const pointField& lp = fluidPatch.localPoints();
    const faceList& lf = fluidPatch.localFaces();
    scalarField h(lf.size(), Zero);
    forAll(lf, facei)
    {
        const face& f = lf[facei];
        forAll(f, k)
        {
            h[facei] = max(h[facei], mag(lp[f[k]] - lp[f[f.fcIndex(k)]]));
        }
    }
    return h;
}


void Foam::interfaceMap::quadrature3D
(
    const globalInterfacePatch& fluidPatch,
    const label nSub,
    vectorField& xs,
    pointField& pts
)
{
    const pointField& lp = fluidPatch.localPoints();
    const pointField Cf(fluidPatch.faceCentres());
    DynamicList<point> qp;
    forAll(fluidPatch.localFaces(), facei)
    {
        const face& f = fluidPatch.localFaces()[facei];
        scalar total = 0;
        const label start = qp.size();
        forAll(f, k)
        {
            const point& a = lp[f[k]];
            const point& b = lp[f[f.fcIndex(k)]];
            const scalar area = 0.5*mag((a - Cf[facei]) ^ (b - Cf[facei]));
            if (nSub == 1)
            {
                qp.append((Cf[facei] + a + b)/3);
                quadFace_.append(facei);
                quadWeight_.append(area);
            }
            else
            {
                // nSub^2 equal subtriangles of (Cf, a, b): on the grid
                // Cf + i/n (a - Cf) + j/n (b - Cf), the nSub (nSub + 1)/2
                // upright ones (i + j <= n - 1) and the nSub (nSub - 1)/2
                // inverted ones (i + j <= n - 2); their centroids
                const vector ea = (a - Cf[facei])/(3*nSub);
                const vector eb = (b - Cf[facei])/(3*nSub);
                for (label i = 0; i < nSub; ++i)
                {
                    for (label j = 0; i + j < nSub; ++j)
                    {
                        qp.append(Cf[facei] + (3*i + 1)*ea + (3*j + 1)*eb);
                        quadFace_.append(facei);
                        quadWeight_.append(area/(nSub*nSub));
                        if (i + j < nSub - 1)
                        {
                            qp.append
                            (
                                Cf[facei] + (3*i + 2)*ea + (3*j + 2)*eb
                            );
                            quadFace_.append(facei);
                            quadWeight_.append(area/(nSub*nSub));
                        }
                    }
                }
            }
            total += area;
        }
        for (label q = start; q < qp.size(); ++q)
        {
            quadWeight_[q] /= total;
        }
    }
    pts = qp;
    xs = pts;
    quadRadial_.setSize(pts.size(), Zero);
}


void Foam::interfaceMap::quadratureRz
(
    const globalInterfacePatch& fluidPatch,
    vectorField& xs,
    pointField& pts
)
{
    // Two segments of two Gauss points each per face: a fluid face that
    // covers several solid faces still loads the nodes under it
    const label nSeg = 2;
    const scalar g = 0.5/std::sqrt(3.0);
    const pointField& lp = fluidPatch.localPoints();
    const pointField Cf(fluidPatch.faceCentres());
    DynamicList<vector> qx;
    DynamicList<point> qp;
    DynamicList<vector> qr;
    forAll(fluidPatch.localFaces(), facei)
    {
        const face& f = fluidPatch.localFaces()[facei];

        // The face's r-z segment: its two most distant points in (r, z)
        vector radial;
        List<vector> rz(f.size());
        forAll(f, k) rz[k] = toSolidFrame(lp[f[k]], radial);
        vector a(rz[0]), b(rz[0]);
        scalar dMax = -1;
        forAll(rz, i)
        {
            for (label j = i + 1; j < rz.size(); ++j)
            {
                if (mag(rz[i] - rz[j]) > dMax)
                {
                    dMax = mag(rz[i] - rz[j]);
                    a = rz[i];
                    b = rz[j];
                }
            }
        }
        toSolidFrame(Cf[facei], radial);

        // Gauss points, weights r ds normalised over the face
        const label start = qx.size();
        scalar total = 0;
        for (label s = 0; s < nSeg; ++s)
        {
            for (const scalar xi : {0.5 - g, 0.5 + g})
            {
                const scalar t = (s + xi)/nSeg;
                const vector x(a + t*(b - a));
                qx.append(x);
                qp.append(axisOrigin_ + x.x()*radial + x.y()*axisDirection_);
                qr.append(radial);
                quadFace_.append(facei);
                quadWeight_.append(x.x());
                total += x.x();
            }
        }
        for (label q = start; q < qx.size(); ++q)
        {
            quadWeight_[q] /= total;
        }
    }
    xs = qx;
    pts = qp;
    quadRadial_ = qr;
}


void Foam::interfaceMap::pointWeights3D
(
    const globalInterfacePatch& fluidPatch
)
{
    // A face triangle t = (centre, p_k, p_k+1) of area share a_t: a_t/3 to
    // p_k and to p_k+1, a_t/3 to the centre, spread as 1/n over the n
    // points of the face (the centre's velocity in the swept volume of a
    // triangular face is the mean of its points' velocities)
    const pointField& lp = fluidPatch.localPoints();
    const pointField Cf(fluidPatch.faceCentres());
    DynamicList<label> df, dp;
    DynamicList<scalar> dw;
    forAll(fluidPatch.localFaces(), facei)
    {
        const face& f = fluidPatch.localFaces()[facei];
        scalarField w(f.size(), Zero);
        scalar total = 0;
        forAll(f, k)
        {
            const label k1 = f.fcIndex(k);
            const scalar area =
                0.5*mag((lp[f[k]] - Cf[facei]) ^ (lp[f[k1]] - Cf[facei]));
            w[k] += area/3;
            w[k1] += area/3;
            w += area/3/f.size();
            total += area;
        }
        w /= max(total, VSMALL);
        snapWeights(w);
        forAll(f, k)
        {
            df.append(facei);
            dp.append(f[k]);
            dw.append(w[k]);
        }
    }
    dualFace_.transfer(df);
    dualPoint_.transfer(dp);
    dualWeight_.transfer(dw);
}


void Foam::interfaceMap::pointInterpolationWeights()
{
    pointStart_.setSize(pointStencil_.size() + 1);
    DynamicList<label> nodes;
    DynamicList<scalar> weights;
    forAll(pointStencil_, pointi)
    {
        pointStart_[pointi] = nodes.size();
        const stencil& s = pointStencil_[pointi];
        for (label k = 0; k < 4; ++k)
        {
            if (s.weight[k] != 0)
            {
                nodes.append(s.node[k]);
                weights.append(s.weight[k]);
            }
        }
    }
    pointStart_.last() = nodes.size();
    pointNode_.transfer(nodes);
    pointWeight_.transfer(weights);
}


Foam::label Foam::interfaceMap::unseenModes
(
    const boolList& fixedDofs,
    scalar& sigmaRatio
) const
{
    if (mapType_ != "faces")
    {
        FatalErrorInFunction
            << "unseen modes are counted for the r-z faces map only"
            << abort(FatalError);
    }
    // Columns: the interface nodes with a free component (a node fixed in
    // every component does not move, so the fluid need not see it); one
    // component suffices, the stencils are the same for both
    const label dim = solidMesh_.dim();
    labelList column(nodes_.size(), -1);
    label nFree = 0;
    forAll(nodes_, a)
    {
        bool free = fixedDofs.empty();
        for (label d = 0; d < dim && !free; ++d)
        {
            free = !fixedDofs[dim*nodes_[a] + d];
        }
        if (free) column[a] = nFree++;
    }
    Eigen::MatrixXd WtW = Eigen::MatrixXd::Zero(nFree, nFree);
    forAll(pointStencil_, pointi)
    {
        const label start = pointStart_[pointi];
        const label end = pointStart_[pointi + 1];
        for (label i = start; i < end; ++i)
        {
            const label ci = column[pointNode_[i]];
            if (ci < 0) continue;
            for (label j = start; j < end; ++j)
            {
                const label cj = column[pointNode_[j]];
                if (cj < 0) continue;
                WtW(ci, cj) += pointWeight_[i]*pointWeight_[j];
            }
        }
    }
    if (!nFree)
    {
        sigmaRatio = 1;
        return 0;
    }
    const Eigen::VectorXd lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>
        (
            WtW, Eigen::EigenvaluesOnly
        ).eigenvalues();
    const scalar lMax = lambda.maxCoeff();
    sigmaRatio = std::sqrt(std::max(lambda.minCoeff(), 0.0)/lMax);
    label n = 0;
    for (Eigen::Index i = 0; i < lambda.size(); ++i)
    {
        if (lambda(i) < 1e-6*lMax) ++n;
    }
    return n;
}


void Foam::interfaceMap::projectionWeights
(
    const globalInterfacePatch& fluidPatch,
    const scalar tol,
    const boolList& fixedDofs
)
{
    // Quadrature: each face triangle t = (centre, p_k, p_k+1) cut into m^2
    // equal triangles, their centroids with the area A_t/m^2; m from the
    // face size over the solid face size at the face (about two quadrature
    // points per solid face length, at most 6)
    const pointField& lp = fluidPatch.localPoints();
    const faceList& lf = fluidPatch.localFaces();
    const pointField Cf(fluidPatch.faceCentres());
    const label nPts = lp.size();

    DynamicList<point> qx;          // quadrature points
    DynamicList<scalar> qA;         // their areas
    DynamicList<label> qFace, qK;   // face, its triangle k
    DynamicList<scalar> qS, qT;     // weights of p_k and p_k+1
    const scalarField hFace(faceSizes(fluidPatch));
    forAll(lf, facei)
    {
        const face& f = lf[facei];
        const scalar hf = hFace[facei];
        // Solid face size near the face: the longest edge of the stencils
        // of its points
        scalar hs = GREAT;
        forAll(f, k)
        {
            const stencil& st = pointStencil_[f[k]];
            scalar h = 0;
            for (label a = 0; a < 4; ++a)
            {
                for (label b = a + 1; b < 4; ++b)
                {
                    h = max
                    (
                        h,
                        mag(solidPoint(st.node[a]) - solidPoint(st.node[b]))
                    );
                }
            }
            hs = min(hs, h);
        }
        const label m =
            min(label(6), max(label(1), label(std::ceil(2*hf/max(hs, VSMALL)))));
        forAll(f, k)
        {
            const point& c = Cf[facei];
            const vector e1 = lp[f[k]] - c, e2 = lp[f[f.fcIndex(k)]] - c;
            const scalar At = 0.5*mag(e1 ^ e2)/scalar(m*m);
            for (label i = 0; i < m; ++i)
            {
                for (label j = 0; i + j < m; ++j)
                {
                    // Upward triangle, then the downward one beside it
                    for (label up = 0; up < 2; ++up)
                    {
                        if (up == 1 && i + j > m - 2) break;
                        const scalar s = (3*i + 1 + up)/(3.0*m);
                        const scalar t = (3*j + 1 + up)/(3.0*m);
                        qx.append(c + s*e1 + t*e2);
                        qA.append(At);
                        qFace.append(facei);
                        qK.append(k);
                        qS.append(s);
                        qT.append(t);
                    }
                }
            }
        }
    }
    const pointField pts(qx);
    const vectorField xs(pts);
    const List<stencil> qStencil
    (
        projectAll
        (
            xs, pts, tol, "projection points",
            scalarField(UIndirectList<scalar>(hFace, qFace))
        )
    );

    // Per patch point: sum_q phi_p(x_q) A_q N_a(x_q), then normalised
    List<std::map<label, scalar>> rows(nPts);
    scalarField Ap(nPts, Zero);
    forAll(qStencil, q)
    {
        const face& f = lf[qFace[q]];
        const label n = f.size();
        const scalar lc = 1 - qS[q] - qT[q];
        const stencil& st = qStencil[q];
        forAll(f, j)
        {
            scalar phi = lc/n;
            if (j == qK[q]) phi += qS[q];
            if (j == f.fcIndex(qK[q])) phi += qT[q];
            const scalar w = phi*qA[q];
            const label p = f[j];
            Ap[p] += w;
            for (label a = 0; a < 4; ++a)
            {
                if (st.weight[a] != 0)
                {
                    rows[p][st.node[a]] += w*st.weight[a];
                }
            }
        }
    }

    // Components prescribed at every node of a point's stencil keep the
    // point stencil (symmetry planes, substrate). A weight below 1e-9 is
    // the round-off of a point on a stencil edge or node (gmsh writes the
    // points of y = 0 at y ~ 1e-21 m): it is dropped from the stencil
    // first, else the pole and the contact-line points were not pinned
    const label dim = solidMesh_.dim();
    pointPinned_.setSize(nPts, 0);
    label nPinned = 0;
    if (fixedDofs.size())
    {
        forAll(pointPinned_, p)
        {
            stencil& st = pointStencil_[p];
            bool dropped = false;
            scalar sum = 0;
            for (label a = 0; a < 4; ++a)
            {
                if (st.weight[a] != 0 && mag(st.weight[a]) < 1e-9)
                {
                    st.weight[a] = 0;
                    dropped = true;
                }
                sum += st.weight[a];
            }
            for (label a = 0; dropped && a < 4; ++a) st.weight[a] /= sum;
            for (label d = 0; d < dim; ++d)
            {
                bool all = true;
                for (label a = 0; a < 4; ++a)
                {
                    if
                    (
                        st.weight[a] != 0
                     && !fixedDofs[dim*nodes_[st.node[a]] + d]
                    )
                    {
                        all = false;
                    }
                }
                if (all)
                {
                    pointPinned_[p] |= (1 << d);
                    ++nPinned;
                }
            }
        }
    }

    pointStart_.setSize(nPts + 1);
    DynamicList<label> nodes;
    DynamicList<scalar> weights;
    forAll(rows, p)
    {
        pointStart_[p] = nodes.size();
        if (!(Ap[p] > 0))
        {
            FatalErrorInFunction
                << "fluid patch point " << lp[p] << " has no projection"
                << " weight" << exit(FatalError);
        }
        scalarField w(label(rows[p].size()));
        label i = 0;
        for (const auto& e : rows[p])
        {
            nodes.append(e.first);
            w[i++] = e.second/Ap[p];
        }
        snapWeights(w);
        weights.append(w);
    }
    pointStart_.last() = nodes.size();
    pointNode_.transfer(nodes);
    pointWeight_.transfer(weights);
    Info<< "FSI interface: projection map, " << qStencil.size()
        << " quadrature points on " << lf.size() << " fluid faces, "
        << pointNode_.size() << " point weights, " << nPinned
        << " point components pinned to prescribed solid nodes" << endl;
}


Foam::scalarField Foam::interfaceMap::pointMap(const vectorField& G) const
{
    const label dim = solidMesh_.dim();
    List<FixedList<exactSum, 3>> gAcc(pointStart_.size() - 1);
    forAll(dualWeight_, i)
    {
        for (direction d = 0; d < 3; ++d)
        {
            gAcc[dualPoint_[i]][d].addProduct
            (
                dualWeight_[i], G[dualFace_[i]][d]
            );
        }
    }
    vectorField Gp(gAcc.size());
    forAll(Gp, p)
    {
        for (direction d = 0; d < 3; ++d) Gp[p][d] = gAcc[p][d].value();
    }
    List<exactSum> acc(nDofs());
    forAll(Gp, pointi)
    {
        const label pinned =
            pointPinned_.size() ? pointPinned_[pointi] : label(0);
        for (label d = 0; d < dim; ++d)
        {
            if (pinned & (1 << d))
            {
                const stencil& s = pointStencil_[pointi];
                for (label k = 0; k < 4; ++k)
                {
                    acc[dim*s.node[k] + d].addProduct
                    (
                        s.weight[k], Gp[pointi][d]
                    );
                }
                continue;
            }
            for
            (
                label i = pointStart_[pointi];
                i < pointStart_[pointi + 1];
                ++i
            )
            {
                acc[dim*pointNode_[i] + d].addProduct
                (
                    pointWeight_[i], Gp[pointi][d]
                );
            }
        }
    }
    scalarField f(nDofs());
    forAll(f, i) f[i] = acc[i].value();
    return f;
}


Foam::vector Foam::interfaceMap::toSolidForce
(
    const vector& F,
    const label q
) const
{
    if (!axisymmetric_)
    {
        return F;
    }
    return vector
    (
        ringFactorRadial_*(F & quadRadial_[q]),
        ringFactorAxial_*(F & axisDirection_),
        0
    );
}


Foam::interfaceMap::interfaceMap
(
    const globalInterfacePatch& fluidPatch,
    const solid::Mesh& solidMesh,
    const dictionary& dict,
    const boolList& fixedDofs
)
:
    solidMesh_(solidMesh),
    axisymmetric_(solidMesh.axisymmetric()),
    axisOrigin_(Zero),
    axisDirection_(Zero),
    ringFactorRadial_(1),
    ringFactorAxial_(1),
    faceSet_(dict.get<word>("solidFaceSet")),
    mapType_(axisymmetric_ ? "faces" : "projection")
{
    const word& setName = faceSet_;
    if (!solidMesh.faceSets.count(setName))
    {
        wordList names;
        for (const auto& s : solidMesh.faceSets) names.append(s.first);
        FatalIOErrorInFunction(dict)
            << "solidFaceSet " << setName << " is not a face set of the"
            << " solid mesh; face sets: " << names << exit(FatalIOError);
    }
    const scalar tol = fsiRanges::readOrDefault<scalar>
    (
        dict, "interface", "mapTolerance", 0.1
    );
    // Subtriangles per side of each fluid face triangle in the 3D force
    // quadrature (the pressure load's samples of the fluid pressure on the
    // solid faces); 1: the triangles' centroids
    const label pressureQuadrature = fsiRanges::readOrDefault<label>
    (
        dict, "interface", "pressureQuadrature", 1
    );
    if (axisymmetric_ && pressureQuadrature != 1)
    {
        FatalIOErrorInFunction(dict)
            << "pressureQuadrature " << pressureQuadrature << " is for 3D "
            << "solid meshes (the r-z quadrature is two segments of two "
            << "Gauss points per face); remove the entry" << exit(FatalIOError);
    }
    if (fluidPatch.empty())
    {
        FatalIOErrorInFunction(dict)
            << "fluid patch " << fluidPatch.name() << " has no faces"
            << exit(FatalIOError);
    }

    // Local numbering of the solid interface nodes
    std::map<int, label> local;
    const auto& set = solidMesh.faceSets.at(setName);
    faces_.setSize(label(set.size()));
    forAll(faces_, facei)
    {
        const auto& f = set[facei];
        faces_[facei].setSize(label(f.size()));
        forAll(faces_[facei], k)
        {
            auto it = local.find(f[k]);
            if (it == local.end())
            {
                it = local.emplace(f[k], nodes_.size()).first;
                nodes_.append(f[k]);
            }
            faces_[facei][k] = it->second;
        }
    }

    if (axisymmetric_)
    {
        axisOrigin_ = dict.get<point>("axisOrigin");
        axisDirection_ = dict.get<vector>("axisDirection");
        if (mag(axisDirection_) < VSMALL)
        {
            FatalIOErrorInFunction(dict)
                << "axisDirection must be non-zero" << exit(FatalIOError);
        }
        axisDirection_ /= mag(axisDirection_);

        // Wedge angle from the azimuth of the patch points
        const pointField& pp = fluidPatch.localPoints();
        vector e1(Zero);
        scalar rMax = 0;
        forAll(pp, i)
        {
            vector rad;
            const vector rz = toSolidFrame(pp[i], rad);
            if (rz.x() > rMax) { rMax = rz.x(); e1 = rad; }
        }
        const vector e2 = axisDirection_ ^ e1;
        scalar phiMin = GREAT, phiMax = -GREAT;
        forAll(pp, i)
        {
            vector rad;
            const vector rz = toSolidFrame(pp[i], rad);
            if (rz.x() < 1e-6*rMax) continue;
            const scalar phi = std::atan2(rad & e2, rad & e1);
            phiMin = min(phiMin, phi);
            phiMax = max(phiMax, phi);
        }
        const scalar theta = phiMax - phiMin;
        if (!(theta > SMALL))
        {
            FatalIOErrorInFunction(dict)
                << "r-z solid mesh, but the fluid patch "
                << fluidPatch.name() << " is not a wedge about the axis "
                << axisOrigin_ << " " << axisDirection_ << exit(FatalIOError);
        }
        ringFactorRadial_ = constant::mathematical::pi/std::sin(0.5*theta);
        ringFactorAxial_ = constant::mathematical::twoPi/std::sin(theta);
        Info<< "FSI interface: axisymmetric, fluid wedge angle "
            << radToDeg(theta) << " deg" << endl;
    }

    {
        const pointField& lp = fluidPatch.localPoints();
        vectorField xs(lp.size());
        pointRadial_.setSize(lp.size());
        forAll(lp, i) xs[i] = toSolidFrame(lp[i], pointRadial_[i]);
        pointStencil_ = projectAll(xs, lp, tol, "points", scalarField());
    }
    // One map per dimension: r-z faces, 3D projection (the 3D faces and
    // points maps, not dual or loading the solid at the fluid points only,
    // were used by no case and are gone); the entry may name it
    if (dict.getOrDefault<word>("map", mapType_) != mapType_)
    {
        FatalIOErrorInFunction(dict)
            << "map " << dict.get<word>("map") << " is not valid for "
            << (axisymmetric_ ? "an r-z" : "a 3D") << " solid mesh: the map"
            << " is " << mapType_ << exit(FatalIOError);
    }
    if (mapType_ == "projection")
    {
        projectionWeights(fluidPatch, tol, fixedDofs);
    }
    else
    {
        pointInterpolationWeights();
    }
    if (mapType_ != "faces")
    {
        pointWeights3D(fluidPatch);
    }
    {
        vectorField xs;
        pointField pts;
        if (axisymmetric_)
        {
            quadratureRz(fluidPatch, xs, pts);
        }
        else
        {
            quadrature3D(fluidPatch, pressureQuadrature, xs, pts);
        }
        quadStencil_ = projectAll
        (
            xs, pts, tol, "face points",
            scalarField(UIndirectList<scalar>(faceSizes(fluidPatch), quadFace_))
        );
    }

    load_ = dict.getOrDefault<word>("load", "mappedForces");
    if (load_ == "projection")
    {
        // Renamed: 'projection' is also a map, which it is not
        FatalIOErrorInFunction(dict)
            << "load projection is now 'load mappedForces' (the fluid's "
            << "face forces through the transpose of the map: conservative "
            << "nodal forces); the other load is pressure"
            << exit(FatalIOError);
    }
    // mappedForces (the map's conservative nodal forces) or pressure (the
    // fluid pressure on the solid's faces), named with the file, the line
    // and the closest word (adv48b g39)
    load_ = foamTools::readOneOfOrDefault
    (
        dict, "load", {"mappedForces", "pressure"}, "mappedForces"
    );
    if (load_ == "pressure")
    {
        // Solid faces without a quadrature point take the nearest face's
        labelList count(faces_.size(), Zero);
        for (const stencil& st : quadStencil_) ++count[st.face];
        vectorField c(faces_.size(), Zero);
        forAll(faces_, s)
        {
            for (const label a : faces_[s]) c[s] += solidPoint(a);
            c[s] /= faces_[s].size();
        }
        pressureDonor_ = identity(faces_.size());
        label nDonated = 0;
        forAll(faces_, s)
        {
            if (count[s]) continue;
            scalar dBest = GREAT;
            forAll(faces_, k)
            {
                if (count[k] && mag(c[k] - c[s]) < dBest)
                {
                    dBest = mag(c[k] - c[s]);
                    pressureDonor_[s] = k;
                }
            }
            ++nDonated;
        }
        // Total force of a uniform pressure: solid faces against fluid
        vectorField Sf(fluidPatch.size(), Zero);
        {
            const pointField& lp = fluidPatch.localPoints();
            forAll(fluidPatch.localFaces(), f)
            {
                Sf[f] = fluidPatch.localFaces()[f].areaNormal(lp);
            }
        }
        const scalarField f1
        (
            nodalPressureForces(Sf, Sf, scalarField(nDofs(), Zero))
        );
        const label dim = solidMesh_.dim();
        vector Fs(Zero);
        forAll(f1, i) Fs[i % dim] += f1[i];
        const vector Ff = axisymmetric_ ? ringForce(Sf) : sum(Sf);
        Info<< "FSI interface: load pressure (the fluid pressure on the "
            << "solid's faces); " << nDonated << " solid faces without a "
            << "fluid quadrature point take the nearest one's; uniform "
            << "pressure 1 Pa: total force on the solid " << Fs
            << " N against the fluid's " << Ff << " N (difference "
            << mag(Fs - Ff)/max(mag(Ff), VSMALL) << " of it"
            << (axisymmetric_ ? "; full ring, (r z 0)" : "") << ")" << endl;
    }

    Info<< "FSI interface: fluid patch " << fluidPatch.name() << " ("
        << fluidPatch.size() << " faces) <-> solid face set " << setName
        << " (" << faces_.size() << " faces, " << nodes_.size()
        << " nodes), largest gap " << maxGap() << " m, map " << mapType_
        << endl;
}


Foam::scalarField Foam::interfaceMap::interfaceDofs(const Eigen::VectorXd& full) const
{
    const label dim = solidMesh_.dim();
    scalarField x(nDofs());
    forAll(nodes_, i)
    {
        for (label d = 0; d < dim; ++d)
        {
            x[dim*i + d] = full(dim*nodes_[i] + d);
        }
    }
    return x;
}


Foam::vector Foam::interfaceMap::pointValue
(
    const scalarField& dofs,
    const label pointi
) const
{
    const label dim = solidMesh_.dim();
    vector val(Zero);
    if (mapType_ == "projection")
    {
        for (label d = 0; d < dim; ++d)
        {
            exactSum a;
            for
            (
                label i = pointStart_[pointi];
                i < pointStart_[pointi + 1];
                ++i
            )
            {
                a.addProduct(pointWeight_[i], dofs[dim*pointNode_[i] + d]);
            }
            val[d] = a.value();
        }
    }
    else
    for (label i = pointStart_[pointi]; i < pointStart_[pointi + 1]; ++i)
    {
        for (label d = 0; d < dim; ++d)
        {
            val[d] += pointWeight_[i]*dofs[dim*pointNode_[i] + d];
        }
    }
    const label pinned =
        pointPinned_.size() ? pointPinned_[pointi] : label(0);
    for (label d = 0; pinned && d < dim; ++d)
    {
        if (pinned & (1 << d))
        {
            const stencil& s = pointStencil_[pointi];
            val[d] = 0;
            for (label k = 0; k < 4; ++k)
            {
                val[d] += s.weight[k]*dofs[dim*s.node[k] + d];
            }
        }
    }
    return axisymmetric_
        ? val.x()*pointRadial_[pointi] + val.y()*axisDirection_
        : val;
}


Foam::tmp<Foam::vectorField> Foam::interfaceMap::pointValues
(
    const scalarField& dofs
) const
{
    tmp<vectorField> tv(new vectorField(pointStencil_.size()));
    vectorField& v = tv.ref();
    forAll(v, pointi)
    {
        v[pointi] = pointValue(dofs, pointi);
    }
    return tv;
}


Foam::tmp<Foam::vectorField> Foam::interfaceMap::pointValues
(
    const scalarField& dofs,
    const labelUList& points
) const
{
    tmp<vectorField> tv(new vectorField(pointStencil_.size(), Zero));
    vectorField& v = tv.ref();
    for (const label pointi : points)
    {
        v[pointi] = pointValue(dofs, pointi);
    }
    return tv;
}


Foam::scalarField Foam::interfaceMap::nodalForces
(
    const vectorField& faceForces
) const
{
    if (mapType_ != "faces")
    {
        return pointMap(faceForces);
    }
    const label dim = solidMesh_.dim();
    scalarField f(nDofs(), Zero);
    forAll(quadStencil_, q)
    {
        const stencil& s = quadStencil_[q];
        const vector F = quadWeight_[q]*faceForces[quadFace_[q]];
        const vector Fs = toSolidForce(F, q);
        for (label k = 0; k < 4; ++k)
        {
            for (label d = 0; d < dim; ++d)
            {
                f[dim*s.node[k] + d] += s.weight[k]*Fs[d];
            }
        }
    }
    return f;
}


Foam::scalarField Foam::interfaceMap::nodalImpedance
(
    const scalarField& Z,
    const vectorField& Sf
) const
{
    // Per quadrature point: Z S_d^2/|S| in the solid frame, components
    // taken positive (a diagonal, not a force)
    if (mapType_ != "faces")
    {
        vectorField D(Z.size());
        forAll(D, facei)
        {
            D[facei] =
                Z[facei]*cmptMultiply(Sf[facei], Sf[facei])
               /max(mag(Sf[facei]), VSMALL);
        }
        return pointMap(D);
    }
    const label dim = solidMesh_.dim();
    scalarField f(nDofs(), Zero);
    forAll(quadStencil_, q)
    {
        const label facei = quadFace_[q];
        const vector S = toSolidForce(Sf[facei], q);
        const vector D =
            quadWeight_[q]*Z[facei]*cmptMultiply(S, S)/max(mag(S), VSMALL);
        const stencil& s = quadStencil_[q];
        for (label k = 0; k < 4; ++k)
        {
            for (label d = 0; d < dim; ++d)
            {
                f[dim*s.node[k] + d] += s.weight[k]*D[d];
            }
        }
    }
    return f;
}


Foam::vector Foam::interfaceMap::ringForce
(
    const vectorField& faceForces
) const
{
    vector sum(Zero);
    forAll(quadStencil_, q)
    {
        sum += quadWeight_[q]*toSolidForce(faceForces[quadFace_[q]], q);
    }
    return sum;
}


Foam::scalar Foam::interfaceMap::maxGap() const
{
    scalar g = 0;
    for (const stencil& s : pointStencil_) g = max(g, s.distance);
    for (const stencil& s : quadStencil_) g = max(g, s.distance);
    return g;
}


Foam::scalarField Foam::interfaceMap::facePressures
(
    const vectorField& faceForces,
    const vectorField& Sf
) const
{
    // Area average of the fluid face pressures at the quadrature points on
    // each solid face (r-z: the weights r ds of the ring)
    scalarField P(faces_.size(), Zero), A(faces_.size(), Zero);
    forAll(quadStencil_, q)
    {
        const label f = quadFace_[q];
        const scalar a = quadWeight_[q]*mag(Sf[f]);
        const scalar p = (faceForces[f] & Sf[f])/max(magSqr(Sf[f]), VSMALL);
        P[quadStencil_[q].face] += a*p;
        A[quadStencil_[q].face] += a;
    }
    forAll(P, s)
    {
        if (A[s] > 0) P[s] /= A[s];
    }
    scalarField Pd(P.size());
    forAll(Pd, s) Pd[s] = P[pressureDonor_[s]];
    return Pd;
}


Foam::scalarField Foam::interfaceMap::nodalPressureForces
(
    const vectorField& faceForces,
    const vectorField& Sf,
    const scalarField& u
) const
{
    // The solid's own follower pressure on the face set, on the faces
    // displaced by u (the fluid's wall: the configuration in which the
    // fluid computed these pressures)
    const scalarField P(facePressures(faceForces, Sf));
    solid::PressureLoad load(faceSet_, [](double) { return 1.0; });
    load.setFacePressures(std::vector<double>(P.begin(), P.end()));

    const label dim = solidMesh_.dim();
    Eigen::VectorXd uAll(Eigen::VectorXd::Zero(dim*solidMesh_.nNodes()));
    forAll(nodes_, i)
    {
        for (label d = 0; d < dim; ++d)
        {
            uAll(dim*nodes_[i] + d) = u[dim*i + d];
        }
    }
    Eigen::VectorXd f(Eigen::VectorXd::Zero(uAll.size()));
    load.addForce(solidMesh_, uAll, 0, f, nullptr);
    return interfaceDofs(f);
}
