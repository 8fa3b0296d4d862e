#include "interfaceMotion.H"
#include "fsiRanges.H"
#include "inputChecks.H"
#include "pointIOField.H"
#include "bitSet.H"
#include "wedgePolyPatch.H"
#include "emptyPolyPatch.H"
#include "PrimitivePatchInterpolation.H"

#include <algorithm>
#include <numeric>

Foam::vector Foam::interfaceMotion::radial(const point& p) const
{
    if (mag(axisDirection_) < SMALL) return Zero;
    const vector d = p - axisOrigin_;
    const vector r = d - (d & axisDirection_)*axisDirection_;
    // On the axis (collapsed wedge points): no radial displacement
    return mag(r) > 1e-9*mag(d) + VSMALL ? r/mag(r) : vector(Zero);
}


Foam::tensorField Foam::interfaceMotion::slipProjectors() const
{
    // Unit normals of every wall-type patch at its points, from the
    // reference points (a restart's mesh has moved); components below
    // 1e-9 are round-off of a plane along the axes and are dropped
    List<DynamicList<vector>> normals(mesh_.nPoints());
    forAll(mesh_.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh_.boundaryMesh()[patchi];
        if
        (
            patchi == patchi_ || isA<wedgePolyPatch>(pp)
         || isA<emptyPolyPatch>(pp) || pp.empty()
         || pp.coupled()            // processor (or cyclic) faces: no wall
        )
        {
            continue;
        }
        const labelList& mp = pp.meshPoints();
        vectorField pn(mp.size(), Zero);
        const faceList& lf = pp.localFaces();
        forAll(lf, facei)
        {
            const vector a = pp[facei].areaNormal(points0_);
            for (const label i : lf[facei]) pn[i] += a;
        }
        forAll(mp, i)
        {
            vector n = pn[i]/(mag(pn[i]) + VSMALL);
            for (direction c = 0; c < vector::nComponents; ++c)
            {
                if (mag(n[c]) < 1e-9) n[c] = 0;
            }
            normals[mp[i]].append(n/(mag(n) + VSMALL));
        }
    }

    // Projectors: Gram-Schmidt over the normals of each point (a normal
    // within 1e-6 of the span of the earlier ones adds no constraint)
    tensorField P(mesh_.nPoints(), tensor::I);
    forAll(normals, pointi)
    {
        DynamicList<vector> basis;
        for (vector n : normals[pointi])
        {
            for (const vector& b : basis) n -= (n & b)*b;
            if (mag(n) > 1e-6)
            {
                n /= mag(n);
                basis.append(n);
                P[pointi] -= n*n;
            }
        }
    }
    return P;
}


void Foam::interfaceMotion::checkEntries
(
    const dictionary& interfaceDict,
    scalar& motionDistance,
    label& motionNearest
)
{
    motionDistance = fsiRanges::read<scalar>
    (
        interfaceDict, "interface", "motionDistance"
    );
    motionNearest = fsiRanges::readOrDefault<label>
    (
        interfaceDict, "interface", "motionNearest", 8
    );
}


Foam::interfaceMotion::interfaceMotion
(
    const fvMesh& mesh,
    const label interfacePatchi,
    const globalInterfacePatch& interfacePatch,
    const dictionary& interfaceDict,
    const vector& axisOrigin,
    const vector& axisDirection
)
:
    mesh_(mesh),
    patchi_(interfacePatchi),
    patch_(interfacePatch),
    points0_
    (
        pointIOField
        (
            IOobject
            (
                "points",
                mesh.time().constant(),
                polyMesh::meshSubDir,
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        )
    ),
    axisOrigin_(axisOrigin),
    axisDirection_
    (
        mag(axisDirection) > SMALL ? axisDirection/mag(axisDirection)
      : vector(Zero)
    )
{
    scalar L = 0;
    label n = 0;
    checkEntries(interfaceDict, L, n);
    const bool axi = mag(axisDirection_) > 0;

    // Interface points (whole patch) in the interpolation space: (r, z, 0)
    // or x
    const polyPatch& ip = mesh.boundaryMesh()[patchi_];
    const labelList& ipPoints = ip.meshPoints();
    const pointField& gp = patch_.localPoints();
    auto toSpace = [&](const point& x)
    {
        if (!axi) return vector(x);
        const vector d = x - axisOrigin_;
        const scalar z = d & axisDirection_;
        return vector(mag(d - z*axisDirection_), z, 0);
    };
    vectorField xi(gp.size());
    forAll(gp, k) xi[k] = toSpace(gp[k]);

    // Slip projectors of the points of the other wall-type patches
    const tensorField P(slipProjectors());
    bitSet onInterface(mesh.nPoints());
    onInterface.set(ipPoints);
    {
        DynamicList<Tuple2<label, tensor>> held;
        forAll(ipPoints, k)
        {
            if (P[ipPoints[k]] != tensor::I)
            {
                held.append(Tuple2<label, tensor>(k, P[ipPoints[k]]));
            }
        }
        interfaceSlip_.transfer(held);
    }

    DynamicList<label> moving;
    DynamicList<labelList> stencil;
    DynamicList<scalarField> weights;
    DynamicList<tensor> slip;
    DynamicList<labelPair> shared;
    DynamicList<tensor> sharedP;
    labelList order(gp.size());
    scalarField dist(gp.size());
    forAll(points0_, pointi)
    {
        if (onInterface.test(pointi)) continue;
        const vector x = toSpace(points0_[pointi]);
        forAll(xi, k) dist[k] = mag(x - xi[k]);
        std::iota(order.begin(), order.end(), 0);
        const label m = min(n, order.size());
        std::partial_sort
        (
            order.begin(), order.begin() + m, order.end(),
            [&](label a, label b) { return dist[a] < dist[b]; }
        );
        const scalar s = dist[order[0]]/L;
        if (s >= 1) continue;
        if (dist[order[0]] < VSMALL)
        {
            // On the interface of another rank: that point's displacement
            shared.append(labelPair(pointi, order[0]));
            sharedP.append(P[pointi]);
            continue;
        }
        const scalar phi = 1 - 3*sqr(s) + 2*pow3(s);
        labelList st(m);
        scalarField w(m);
        for (label j = 0; j < m; ++j)
        {
            st[j] = order[j];
            w[j] = 1/sqr(dist[order[j]]);
        }
        w *= phi/sum(w);
        moving.append(pointi);
        stencil.append(st);
        weights.append(w);
        slip.append(P[pointi]);
    }
    movingPoints_.transfer(moving);
    radialMoving_.setSize(movingPoints_.size());
    forAll(movingPoints_, i)
    {
        radialMoving_[i] = radial(points0_[movingPoints_[i]]);
    }
    radialPatch_.setSize(gp.size());
    forAll(gp, k)
    {
        radialPatch_[k] = radial(gp[k]);
    }
    stencil_.transfer(stencil);
    weights_.transfer(weights);
    slip_.transfer(slip);
    sharedPoints_.transfer(shared);
    sharedSlip_.transfer(sharedP);

    Info<< "FSI mesh motion: interpolation from the " << gp.size()
        << " interface points to " << movingPoints_.size()
        << " mesh points within " << L << " m (" << n << " nearest); "
        << interfaceSlip_.size() << " interface points held on wall or"
        << " symmetry patches" << endl;
}


Foam::tmp<Foam::pointField> Foam::interfaceMotion::newPoints
(
    const vectorField& patchDisplacement
) const
{
    const polyPatch& ip = mesh_.boundaryMesh()[patchi_];
    const labelList& ipPoints = ip.meshPoints();
    const labelList& toGlobal = patch_.localToGlobal();
    const pointField& gp = patch_.localPoints();
    const bool axi = mag(axisDirection_) > 0;

    // Interface displacements in the interpolation space: (d_r, d_z, 0)
    vectorField di(patchDisplacement);
    if (axi)
    {
        forAll(gp, k)
        {
            const vector& d = patchDisplacement[k];
            di[k] = vector(d & radialPatch_[k], d & axisDirection_, 0);
        }
    }

    tmp<pointField> tnew(new pointField(points0_));
    pointField& x = tnew.ref();
    forAll(ipPoints, k) x[ipPoints[k]] += patchDisplacement[toGlobal[k]];
    for (const Tuple2<label, tensor>& kP : interfaceSlip_)
    {
        // The coupling's displacement, held on the wall (the part removed
        // is round-off of the map or a component the solid prescribes)
        const label k = kP.first();
        x[ipPoints[k]] =
            points0_[ipPoints[k]] + (kP.second() & patchDisplacement[toGlobal[k]]);
    }
    forAll(sharedPoints_, i)
    {
        const labelPair& pk = sharedPoints_[i];
        x[pk.first()] += (sharedSlip_[i] & patchDisplacement[pk.second()]);
    }
    forAll(movingPoints_, i)
    {
        const label pointi = movingPoints_[i];
        vector d(Zero);
        forAll(stencil_[i], j) d += weights_[i][j]*di[stencil_[i][j]];
        if (axi)
        {
            d = d.x()*radialMoving_[i] + d.y()*axisDirection_;
        }
        x[pointi] += (slip_[i] & d);
    }
    return tnew;
}


Foam::labelList Foam::interfaceMotion::usedPatchPoints() const
{
    bitSet used(patch_.localPoints().size());
    used.set(patch_.localToGlobal());
    forAll(stencil_, i) used.set(stencil_[i]);
    for (const labelPair& pk : sharedPoints_)
    {
        used.set(pk.second());
    }
    return used.sortedToc();
}


Foam::labelList Foam::interfaceMotion::movedPoints() const
{
    const labelList& ipPoints = mesh_.boundaryMesh()[patchi_].meshPoints();
    labelList moved(ipPoints);
    moved.append(movingPoints_);
    for (const labelPair& pk : sharedPoints_)
    {
        moved.append(pk.first());
    }
    return moved;
}


// ************************************************************************* //
