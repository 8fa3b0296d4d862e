#include "MUSCLReconstruction.H"
#include "surfaceFields.H"
#include "NVDTVD.H"
#include "NVDVTVDV.H"
#include "MUSCL.H"
#include "vanLeer.H"
#include "Minmod.H"
#include "vanAlbada.H"
#include "calculatedFvPatchFields.H"
#include "IStringStream.H"

#include <type_traits>

const Foam::Enum<Foam::MUSCLReconstruction::limiterType>
Foam::MUSCLReconstruction::scalarNames
({
    { limiterType::upwind, "upwind" },
    { limiterType::MUSCL, "MUSCL" },
    { limiterType::vanLeer, "vanLeer" },
    { limiterType::Minmod, "Minmod" },
    { limiterType::vanAlbada, "vanAlbada" },
    { limiterType::BarthJespersen, "BarthJespersen" },
    { limiterType::venkatakrishnan, "venkatakrishnan" },
});


const Foam::Enum<Foam::MUSCLReconstruction::limiterType>
Foam::MUSCLReconstruction::vectorNames
({
    { limiterType::upwind, "upwind" },
    { limiterType::MUSCL, "MUSCLV" },
    { limiterType::vanLeer, "vanLeerV" },
    { limiterType::Minmod, "MinmodV" },
    { limiterType::vanAlbada, "vanAlbadaV" },
    { limiterType::BarthJespersen, "BarthJespersen" },
    { limiterType::venkatakrishnan, "venkatakrishnan" },
});


const Foam::wordList Foam::MUSCLReconstruction::gradientNames
({
    "Gauss linear", "leastSquares", "pointCellsLeastSquares"
});


const Foam::scalar Foam::MUSCLReconstruction::venkatakrishnanK = 5;


namespace
{

using namespace Foam;

//- Interpolation weights of the owner-side and neighbour-side values of
//  one face of linear weight w: limiter w + (1 - limiter) pos0(faceFlux),
//  limiterOf(faceFlux) the limiter for the direction faceFlux (+1: from
//  the owner, -1: from the neighbour), the pos0(faceFlux) factor kept as
//  a multiplication so that the result is OpenFOAM's
//  limitedSurfaceInterpolationScheme's in every bit (signed zeros
//  included)
template<class LimiterOf>
inline void tvdWeights
(
    const LimiterOf& limiterOf,
    const scalar w,
    scalar& lambdaL,
    scalar& lambdaR
)
{
    static const scalar pos0Owner = 1;
    static const scalar pos0Neighbour = 0;

    const scalar limL = limiterOf(1);
    const scalar limR = limiterOf(-1);
    lambdaL = limL*w + (1.0 - limL)*pos0Owner;
    lambdaR = limR*w + (1.0 - limR)*pos0Neighbour;
}


//- OpenFOAM's limiter functions of one NVD family (NVDTVD for scalars,
//  NVDVTVDV for vectors), called rather than copied so that the limiter is
//  theirs to the last bit; their constructors take the scheme's stream and
//  read nothing from it
template<class NVD>
class limiterFunctions
{
    IStringStream none_;
    MUSCLLimiter<NVD> MUSCL_;
    vanLeerLimiter<NVD> vanLeer_;
    MinmodLimiter<NVD> Minmod_;
    vanAlbadaLimiter<NVD> vanAlbada_;

public:

    typedef MUSCLReconstruction::limiterType limiterType;

    limiterFunctions()
    :
        none_(""),
        MUSCL_(none_),
        vanLeer_(none_),
        Minmod_(none_),
        vanAlbada_(none_)
    {}

    //- The limiter of a face with weight w for the direction faceFlux
    //  (+1: from the owner, -1: from the neighbour)
    inline scalar operator()
    (
        const limiterType type,
        const scalar w,
        const scalar faceFlux,
        const typename NVD::phiType& phiP,
        const typename NVD::phiType& phiN,
        const typename NVD::gradPhiType& gradP,
        const typename NVD::gradPhiType& gradN,
        const vector& d
    ) const
    {
        switch (type)
        {
            case limiterType::MUSCL:
                return MUSCL_.limiter(w, faceFlux, phiP, phiN, gradP, gradN, d);
            case limiterType::vanLeer:
                return
                    vanLeer_.limiter(w, faceFlux, phiP, phiN, gradP, gradN, d);
            case limiterType::Minmod:
                return
                    Minmod_.limiter(w, faceFlux, phiP, phiN, gradP, gradN, d);
            case limiterType::vanAlbada:
                return
                    vanAlbada_.limiter
                    (
                        w, faceFlux, phiP, phiN, gradP, gradN, d
                    );
            default:
                return 0;
        }
    }

    //- Interpolation weights of the owner-side and neighbour-side values
    //  of one face (tvdWeights with the limiter of type)
    inline void weights
    (
        const limiterType type,
        const scalar w,
        const typename NVD::phiType& phiP,
        const typename NVD::phiType& phiN,
        const typename NVD::gradPhiType& gradP,
        const typename NVD::gradPhiType& gradN,
        const vector& d,
        scalar& lambdaL,
        scalar& lambdaR
    ) const
    {
        tvdWeights
        (
            [&](const scalar faceFlux)
            {
                return
                    (*this)(type, w, faceFlux, phiP, phiN, gradP, gradN, d);
            },
            w, lambdaL, lambdaR
        );
    }

    //- The limiter object of OpenFOAM's class Limiter<NVD> (one of the
    //  four above)
    template<template<class> class Limiter>
    const Limiter<NVD>& get() const
    {
        if constexpr (std::is_same<Limiter<NVD>, MUSCLLimiter<NVD>>::value)
        {
            return MUSCL_;
        }
        else if constexpr
        (
            std::is_same<Limiter<NVD>, vanLeerLimiter<NVD>>::value
        )
        {
            return vanLeer_;
        }
        else if constexpr
        (
            std::is_same<Limiter<NVD>, MinmodLimiter<NVD>>::value
        )
        {
            return Minmod_;
        }
        else
        {
            static_assert
            (
                std::is_same<Limiter<NVD>, vanAlbadaLimiter<NVD>>::value,
                "not a limiter of limiterFunctions"
            );
            return vanAlbada_;
        }
    }
};


const limiterFunctions<NVDTVD>& scalarLimiters()
{
    static const limiterFunctions<NVDTVD> l;
    return l;
}


const limiterFunctions<NVDVTVDV>& vectorLimiters()
{
    static const limiterFunctions<NVDVTVDV> l;
    return l;
}


//- The limiter of one variable in the internal faces' loop chosen at run
//  time: type, with OpenFOAM's functions of its NVD family
template<class NVD>
struct runTimeLimiter
{
    //- The loop of the general schemes (the face frame and the
    //  characteristic reconstruction of U possible)
    static constexpr bool general = true;

    const limiterFunctions<NVD>& functions;
    const MUSCLReconstruction::limiterType type;

    bool multidimensional() const
    {
        return MUSCLReconstruction::multidimensional(type);
    }

    bool upwind() const
    {
        return type == MUSCLReconstruction::limiterType::upwind;
    }

    inline void weights
    (
        const scalar w,
        const typename NVD::phiType& phiP,
        const typename NVD::phiType& phiN,
        const typename NVD::gradPhiType& gradP,
        const typename NVD::gradPhiType& gradN,
        const vector& d,
        scalar& lambdaL,
        scalar& lambdaR
    ) const
    {
        functions.weights
        (
            type, w, phiP, phiN, gradP, gradN, d, lambdaL, lambdaR
        );
    }
};


//- A TVD limiter of the internal faces' loop known at compile time:
//  OpenFOAM's class Limiter (of NVDTVD or NVDVTVDV), its function and the
//  weights inlined into the loop, no switch or call per face and side
//  (issue 18 item 5d, perf45); the same bits as runTimeLimiter of its
//  type
template<class Limiter>
struct compiledLimiter
{
    //- The loop of one TVD limiter for rho, U and p
    static constexpr bool general = false;

    const Limiter& limiter;

    static constexpr bool multidimensional()
    {
        return false;
    }

    static constexpr bool upwind()
    {
        return false;
    }

    template<class Type, class GradType>
    inline void weights
    (
        const scalar w,
        const Type& phiP,
        const Type& phiN,
        const GradType& gradP,
        const GradType& gradN,
        const vector& d,
        scalar& lambdaL,
        scalar& lambdaR
    ) const
    {
        tvdWeights
        (
            [&](const scalar faceFlux)
            {
                return
                    limiter.limiter(w, faceFlux, phiP, phiN, gradP, gradN, d);
            },
            w, lambdaL, lambdaR
        );
    }
};


//- Owner-side and neighbour-side values of one internal face with the
//  limiter (runTimeLimiter or compiledLimiter)
template<class Limiter, class Type, class GradType>
inline void internalFaceValues
(
    const Limiter& limiter,
    const scalar w,
    const Type& phiP,
    const Type& phiN,
    const GradType& gradP,
    const GradType& gradN,
    const vector& d,
    const vector& dP,
    const vector& dN,
    Type& left,
    Type& right
)
{
    if (limiter.multidimensional())
    {
        // At the face centre from the limited gradients: dP = x_f - x_P,
        // dN = x_f - x_N
        left = phiP + (dP & gradP);
        right = phiN + (dN & gradN);
        return;
    }

    // upwind: the weights pos0(faceFlux) of OpenFOAM's upwind scheme
    scalar lambdaL = 1;
    scalar lambdaR = 0;
    if (!limiter.upwind())
    {
        limiter.weights(w, phiP, phiN, gradP, gradN, d, lambdaL, lambdaR);
    }
    left = lambdaL*(phiP - phiN) + phiN;
    right = lambdaR*(phiP - phiN) + phiN;
}


//- The boundary faces' terms of MUSCLReconstruction::gaussGrad of one
//  field on one patch, in its arithmetic and order
template<class Type>
inline void gaussGradPatch
(
    const fvPatch& patch,
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    Field<typename outerProduct<vector, Type>::type>& g
)
{
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    const label patchi = patch.index();
    const labelUList& faceCells = patch.faceCells();
    const vectorField& pSf = mesh.Sf().boundaryField()[patchi];
    const fvPatchField<Type>& pvf = vf.boundaryField()[patchi];

    if (pvf.coupled())
    {
        const scalarField& pw = mesh.weights().boundaryField()[patchi];
        const Field<Type> vP(pvf.patchInternalField());
        const Field<Type> vN(pvf.patchNeighbourField());
        forAll(faceCells, facei)
        {
            g[faceCells[facei]] +=
                pSf[facei]
               *(pw[facei]*vP[facei] + (1.0 - pw[facei])*vN[facei]);
        }
    }
    else
    {
        forAll(faceCells, facei)
        {
            g[faceCells[facei]] += pSf[facei]*pvf[facei];
        }
    }
}


//- MUSCLReconstruction::gaussGrad of rho, U and p with one loop over the
//  internal faces (each cell's sums of each field in the order of the
//  field's own loop: the same bits; the faces' addressing, areas and
//  weights read once for the three; issue 18 item 5d, perf45)
void gaussGrads
(
    const fvMesh& mesh,
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& p,
    volVectorField& gradRho,
    volTensorField& gradU,
    volVectorField& gradP
)
{
    const label nFaces = mesh.nInternalFaces();
    const label* const owner = mesh.owner().cdata();
    const label* const neighbour = mesh.neighbour().cdata();
    const vector* const Sf = mesh.Sf().primitiveField().cdata();
    const scalar* const w = mesh.weights().primitiveField().cdata();
    const scalar* const vRho = rho.primitiveField().cdata();
    const vector* const vU = U.primitiveField().cdata();
    const scalar* const vP = p.primitiveField().cdata();

    vectorField& gRhoF = gradRho.primitiveFieldRef();
    tensorField& gUF = gradU.primitiveFieldRef();
    vectorField& gPF = gradP.primitiveFieldRef();
    gRhoF = Zero;
    gUF = Zero;
    gPF = Zero;
    vector* const gRho = gRhoF.data();
    tensor* const gU = gUF.data();
    vector* const gP = gPF.data();

    for (label facei = 0; facei < nFaces; ++facei)
    {
        const label own = owner[facei];
        const label nei = neighbour[facei];
        const vector& S = Sf[facei];
        const scalar wf = w[facei];

        const vector sRho = S*(wf*(vRho[own] - vRho[nei]) + vRho[nei]);
        gRho[own] += sRho;
        gRho[nei] -= sRho;

        const tensor sU = S*(wf*(vU[own] - vU[nei]) + vU[nei]);
        gU[own] += sU;
        gU[nei] -= sU;

        const vector sP = S*(wf*(vP[own] - vP[nei]) + vP[nei]);
        gP[own] += sP;
        gP[nei] -= sP;
    }

    for (const fvPatch& patch : mesh.boundary())
    {
        gaussGradPatch(patch, rho, gRhoF);
        gaussGradPatch(patch, U, gUF);
        gaussGradPatch(patch, p, gPF);
    }

    const scalarField& V = mesh.V().field();
    gRhoF /= V;
    gUF /= V;
    gPF /= V;
}


//- Owner-side and neighbour-side values of the faces of a coupled patch
template<class NVD>
void coupledFaceValues
(
    const limiterFunctions<NVD>& limiters,
    const MUSCLReconstruction::limiterType type,
    const fvPatchField<typename NVD::phiType>& pf,
    const fvPatchField<typename NVD::gradPhiType>& gradPf,
    Field<typename NVD::phiType>& left,
    Field<typename NVD::phiType>& right
)
{
    typedef typename NVD::phiType Type;
    typedef typename NVD::gradPhiType GradType;

    const fvPatch& patch = pf.patch();
    const scalarField& w =
        patch.boundaryMesh().mesh().weights().boundaryField()[patch.index()];
    const Field<Type> phiP(pf.patchInternalField());
    const Field<Type> phiN(pf.patchNeighbourField());

    left.setSize(patch.size());
    right.setSize(patch.size());

    if (MUSCLReconstruction::multidimensional(type))
    {
        // At the face centre from the limited gradients of both sides:
        // x_f - x_N = (x_f - x_P) - delta (delta from P to N)
        const Field<GradType> gradP(gradPf.patchInternalField());
        const Field<GradType> gradN(gradPf.patchNeighbourField());
        const vectorField dP(patch.Cf() - patch.Cn());
        const vectorField dN(dP - patch.delta());
        forAll(w, facei)
        {
            left[facei] = phiP[facei] + (dP[facei] & gradP[facei]);
            right[facei] = phiN[facei] + (dN[facei] & gradN[facei]);
        }
        return;
    }

    const bool upwind = (type == MUSCLReconstruction::limiterType::upwind);
    Field<GradType> gradP;
    Field<GradType> gradN;
    vectorField d;
    if (!upwind)
    {
        gradP = gradPf.patchInternalField();
        gradN = gradPf.patchNeighbourField();
        d = patch.delta();
    }

    forAll(w, facei)
    {
        // upwind: the weights pos0(faceFlux) of OpenFOAM's upwind scheme
        scalar lambdaL = 1;
        scalar lambdaR = 0;
        if (!upwind)
        {
            limiters.weights
            (
                type, w[facei], phiP[facei], phiN[facei], gradP[facei],
                gradN[facei], d[facei], lambdaL, lambdaR
            );
        }
        left[facei] = lambdaL*phiP[facei] + (1.0 - lambdaL)*phiN[facei];
        right[facei] = lambdaR*phiP[facei] + (1.0 - lambdaR)*phiN[facei];
    }
}

//- The face's left and right velocities from their normal components unL,
//  unR and the cells' tangential parts U_t = U - u_n n limited by the
//  vector limiter tangentialType with the gradients grad(U) & (I - n n)
//  (upwind: the cell's own part); shared by faceFrameValues and the
//  characteristic reconstruction
inline void tangentialValues
(
    const limiterFunctions<NVDVTVDV>& vLim,
    const MUSCLReconstruction::limiterType tangentialType,
    const scalar w,
    const vector& UP,
    const vector& UN,
    const scalar unP,
    const scalar unN,
    const scalar unL,
    const scalar unR,
    const tensor& gradP,
    const tensor& gradN,
    const vector& d,
    const vector& n,
    vector& left,
    vector& right
)
{
    const vector utP(UP - unP*n);
    const vector utN(UN - unN*n);
    scalar lambdaL = 1;
    scalar lambdaR = 0;
    if (tangentialType != MUSCLReconstruction::limiterType::upwind)
    {
        const tensor T(I - sqr(n));
        vLim.weights
        (
            tangentialType, w, utP, utN, gradP & T, gradN & T, d,
            lambdaL, lambdaR
        );
    }
    left = unL*n + lambdaL*(utP - utN) + utN;
    right = unR*n + lambdaR*(utP - utN) + utN;
}


//- Owner-side and neighbour-side velocities of one face in its frame
//  (normalTangential N T): the normal component u_n = U.n by the scalar
//  limiter normalType on the cells' normal components with the gradients
//  grad(U) & n, the tangential part U_t = U - u_n n by the vector limiter
//  tangentialType on the cells' tangential parts with the gradients
//  grad(U) & (I - n n); upwind: the cell's own part. n is the face's unit
//  normal (owner to neighbour), d = x_N - x_P, w the face's linear weight
inline void faceFrameValues
(
    const limiterFunctions<NVDTVD>& sLim,
    const limiterFunctions<NVDVTVDV>& vLim,
    const MUSCLReconstruction::limiterType normalType,
    const MUSCLReconstruction::limiterType tangentialType,
    const scalar w,
    const vector& UP,
    const vector& UN,
    const tensor& gradP,
    const tensor& gradN,
    const vector& d,
    const vector& n,
    vector& left,
    vector& right
)
{
    typedef MUSCLReconstruction::limiterType limiterType;

    const scalar unP = UP & n;
    const scalar unN = UN & n;
    scalar lambdaL = 1;
    scalar lambdaR = 0;
    if (normalType != limiterType::upwind)
    {
        sLim.weights
        (
            normalType, w, unP, unN, gradP & n, gradN & n, d,
            lambdaL, lambdaR
        );
    }
    const scalar unL = lambdaL*(unP - unN) + unN;
    const scalar unR = lambdaR*(unP - unN) + unN;

    tangentialValues
    (
        vLim, tangentialType, w, UP, UN, unP, unN, unL, unR, gradP, gradN,
        d, n, left, right
    );
}


//- The faces of a coupled patch in their frames (faceFrameValues)
void coupledFaceFrameValues
(
    const MUSCLReconstruction::vectorScheme& scheme,
    const fvPatchField<vector>& pf,
    const fvPatchField<tensor>& gradPf,
    vectorField& left,
    vectorField& right
)
{
    const fvPatch& patch = pf.patch();
    const scalarField& w =
        patch.boundaryMesh().mesh().weights().boundaryField()[patch.index()];
    const vectorField UP(pf.patchInternalField());
    const vectorField UN(pf.patchNeighbourField());
    const vectorField n(patch.nf());
    tensorField gradP(patch.size(), Zero);
    tensorField gradN(patch.size(), Zero);
    vectorField d(patch.size(), Zero);
    if (scheme.needsGradient())
    {
        gradP = gradPf.patchInternalField();
        gradN = gradPf.patchNeighbourField();
        d = patch.delta();
    }

    left.setSize(patch.size());
    right.setSize(patch.size());
    forAll(w, facei)
    {
        faceFrameValues
        (
            scalarLimiters(), vectorLimiters(), scheme.limiter,
            scheme.tangential, w[facei], UP[facei], UN[facei], gradP[facei],
            gradN[facei], d[facei], n[facei], left[facei], right[facei]
        );
    }
}


//- Owner-side and neighbour-side rho, U, p of one face limited in the
//  characteristic variables of the 1D problem normal to the face
//  (characteristic N T), frozen at the face's mean state (rho_f =
//  (rho_P + rho_N)/2, c_f = (c_P + c_N)/2, Z = rho_f c_f):
//      w1 = p - Z u_n,  w2 = p + Z u_n,  w3 = rho - p/c_f^2,  U_t
//  (the acoustic waves running against and along n, the entropy wave, the
//  shear). w1, w2, w3 of both cells and their gradients (the same linear
//  map of the primitive ones) are limited one by one by the scalar
//  limiter waveType, U_t as faceFrameValues' tangential part by
//  shearType; the face state is the inverse map
//      p = (w1 + w2)/2,  u_n = (w2 - w1)/(2 Z),  rho = w3 + p/c_f^2,
//      U = u_n n + U_t
//  n is the face's unit normal (owner to neighbour), d = x_N - x_P, w the
//  face's linear weight
inline void characteristicValues
(
    const limiterFunctions<NVDTVD>& sLim,
    const limiterFunctions<NVDVTVDV>& vLim,
    const MUSCLReconstruction::limiterType waveType,
    const MUSCLReconstruction::limiterType shearType,
    const scalar w,
    const scalar rhoP,
    const scalar rhoN,
    const vector& UP,
    const vector& UN,
    const scalar pP,
    const scalar pN,
    const scalar cP,
    const scalar cN,
    const vector& gradRhoP,
    const vector& gradRhoN,
    const tensor& gradUP,
    const tensor& gradUN,
    const vector& gradPP,
    const vector& gradPN,
    const vector& d,
    const vector& n,
    scalar& rhoL,
    scalar& rhoR,
    vector& UL,
    vector& UR,
    scalar& pL,
    scalar& pR
)
{
    typedef MUSCLReconstruction::limiterType limiterType;

    const scalar c = 0.5*(cP + cN);
    const scalar Z = 0.5*(rhoP + rhoN)*c;
    const scalar rc2 = 1/sqr(c);

    const scalar unP = UP & n;
    const scalar unN = UN & n;
    const vector gradUnP(gradUP & n);
    const vector gradUnN(gradUN & n);

    const scalar wP[3] = {pP - Z*unP, pP + Z*unP, rhoP - rc2*pP};
    const scalar wN[3] = {pN - Z*unN, pN + Z*unN, rhoN - rc2*pN};
    const vector gradWP[3] =
    {
        gradPP - Z*gradUnP, gradPP + Z*gradUnP, gradRhoP - rc2*gradPP
    };
    const vector gradWN[3] =
    {
        gradPN - Z*gradUnN, gradPN + Z*gradUnN, gradRhoN - rc2*gradPN
    };

    scalar wL[3];
    scalar wR[3];
    for (label k = 0; k < 3; ++k)
    {
        scalar lambdaL = 1;
        scalar lambdaR = 0;
        if (waveType != limiterType::upwind)
        {
            sLim.weights
            (
                waveType, w, wP[k], wN[k], gradWP[k], gradWN[k], d,
                lambdaL, lambdaR
            );
        }
        wL[k] = lambdaL*(wP[k] - wN[k]) + wN[k];
        wR[k] = lambdaR*(wP[k] - wN[k]) + wN[k];
    }

    pL = 0.5*(wL[0] + wL[1]);
    pR = 0.5*(wR[0] + wR[1]);
    const scalar unL = (wL[1] - wL[0])/(2*Z);
    const scalar unR = (wR[1] - wR[0])/(2*Z);
    rhoL = wL[2] + rc2*pL;
    rhoR = wR[2] + rc2*pR;

    tangentialValues
    (
        vLim, shearType, w, UP, UN, unP, unN, unL, unR, gradUP, gradUN,
        d, n, UL, UR
    );
}


//- The faces of a coupled patch limited in characteristic variables
//  (characteristicValues)
void coupledCharacteristicValues
(
    const MUSCLReconstruction::vectorScheme& scheme,
    const label patchi,
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& p,
    const volScalarField& c,
    const volVectorField& gradRho,
    const volTensorField& gradU,
    const volVectorField& gradP,
    MUSCLReconstruction::states& L,
    MUSCLReconstruction::states& R
)
{
    const fvPatch& patch = rho.mesh().boundary()[patchi];
    const scalarField& w = rho.mesh().weights().boundaryField()[patchi];
    const fvPatchScalarField& rhop = rho.boundaryField()[patchi];
    const fvPatchVectorField& Up = U.boundaryField()[patchi];
    const fvPatchScalarField& pp = p.boundaryField()[patchi];
    const fvPatchScalarField& cp = c.boundaryField()[patchi];
    const scalarField rhoP(rhop.patchInternalField());
    const scalarField rhoN(rhop.patchNeighbourField());
    const vectorField UP(Up.patchInternalField());
    const vectorField UN(Up.patchNeighbourField());
    const scalarField pP(pp.patchInternalField());
    const scalarField pN(pp.patchNeighbourField());
    const scalarField cP(cp.patchInternalField());
    const scalarField cN(cp.patchNeighbourField());
    const vectorField n(patch.nf());

    vectorField gRhoP(patch.size(), Zero);
    vectorField gRhoN(patch.size(), Zero);
    tensorField gUP(patch.size(), Zero);
    tensorField gUN(patch.size(), Zero);
    vectorField gPP(patch.size(), Zero);
    vectorField gPN(patch.size(), Zero);
    vectorField d(patch.size(), Zero);
    if (scheme.needsGradient())
    {
        gRhoP = gradRho.boundaryField()[patchi].patchInternalField();
        gRhoN = gradRho.boundaryField()[patchi].patchNeighbourField();
        gUP = gradU.boundaryField()[patchi].patchInternalField();
        gUN = gradU.boundaryField()[patchi].patchNeighbourField();
        gPP = gradP.boundaryField()[patchi].patchInternalField();
        gPN = gradP.boundaryField()[patchi].patchNeighbourField();
        d = patch.delta();
    }

    for (MUSCLReconstruction::states* s : {&L, &R})
    {
        s->rho.setSize(patch.size());
        s->U.setSize(patch.size());
        s->p.setSize(patch.size());
    }
    forAll(w, facei)
    {
        characteristicValues
        (
            scalarLimiters(), vectorLimiters(), scheme.limiter,
            scheme.tangential, w[facei], rhoP[facei], rhoN[facei],
            UP[facei], UN[facei], pP[facei], pN[facei], cP[facei],
            cN[facei], gRhoP[facei], gRhoN[facei], gUP[facei], gUN[facei],
            gPP[facei], gPN[facei], d[facei], n[facei],
            L.rho[facei], R.rho[facei], L.U[facei], R.U[facei],
            L.p[facei], R.p[facei]
        );
    }
}


//- The multidimensional limiter of one face of a cell, per component:
//  psi = min(psi, f(Delta1, Delta2)) with Delta2 the unlimited increment
//  to the face centre, Delta1 the room to the neighbourhood's max (Delta2
//  > 0) or min (Delta2 < 0); eps2 [units of phi^2] Venkatakrishnan's eps^2.
//  An increment at the rounding level of the cell's values (below 1e-12
//  of |phi_P| + max - min: a face along which the variable does not
//  change, whose Delta2 and Delta1 are both rounding noise) limits
//  nothing: its noise ratio would cut the gradient of the other faces
inline void limitFace
(
    const MUSCLReconstruction::limiterType type,
    const scalar eps2,
    const scalar phiP,
    const scalar maxDelta,
    const scalar minDelta,
    const scalar delta2,
    scalar& psi
)
{
    if (mag(delta2) <= 1e-12*(mag(phiP) + maxDelta - minDelta))
    {
        return;
    }
    const scalar delta1 = delta2 > 0 ? maxDelta : minDelta;

    if (type == MUSCLReconstruction::limiterType::BarthJespersen)
    {
        // delta1/delta2 >= 0 (delta1 has delta2's sign or is 0)
        psi = min(psi, min(scalar(1), delta1/delta2));
    }
    else
    {
        // Venkatakrishnan (1995): a smooth min(1, delta1/delta2)
        const scalar d11 = delta1*delta1;
        const scalar d22 = delta2*delta2;
        const scalar d12 = delta1*delta2;
        psi = min
        (
            psi,
            (d11 + eps2 + 2*d12)/(d11 + 2*d22 + d12 + eps2)
        );
    }
}


inline void limitFace
(
    const MUSCLReconstruction::limiterType type,
    const scalar eps2,
    const vector& phiP,
    const vector& maxDelta,
    const vector& minDelta,
    const vector& delta2,
    vector& psi
)
{
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        limitFace
        (
            type, eps2, phiP[d], maxDelta[d], minDelta[d], delta2[d],
            psi[d]
        );
    }
}


//- The gradient times the limiter: per component for a vector's (the
//  gradient's column of U_j, grad U = d_i U_j, scaled by psi_j)
inline void scaleGradient(const scalar psi, vector& g)
{
    g *= psi;
}


inline void scaleGradient(const vector& psi, tensor& g)
{
    g = tensor
    (
        cmptMultiply(psi, g.x()),
        cmptMultiply(psi, g.y()),
        cmptMultiply(psi, g.z())
    );
}


//- The states of the internal faces start to start + size - 1 into L and
//  R (sized), rho and p with the limiters rhoLimiter and pLimiter, U with
//  ULimiter; with runTimeLimiters also UScheme's face frame or
//  characteristic reconstruction (c: the cells' sound speed of the
//  latter). One loop for both kinds of limiter: a compiledLimiter's loop
//  has no branch, switch or call per face and side, and computes no face
//  centre offsets; the fields' addresses are held in locals
template<class SLimiter, class VLimiter>
void internalFaceStates
(
    const fvMesh& mesh,
    const label start,
    const label size,
    const SLimiter& rhoLimiter,
    const VLimiter& ULimiter,
    const SLimiter& pLimiter,
    const MUSCLReconstruction::vectorScheme& UScheme,
    const scalarField* c,
    const scalarField& rho,
    const vectorField& U,
    const scalarField& p,
    const vectorField& gradRho,
    const tensorField& gradU,
    const vectorField& gradP,
    MUSCLReconstruction::states& L,
    MUSCLReconstruction::states& R
)
{
    constexpr bool general = SLimiter::general;
    static_assert(general == VLimiter::general, "one kind of limiter");

    const label* const owner = mesh.owner().cdata() + start;
    const label* const neighbour = mesh.neighbour().cdata() + start;
    const scalar* const w = mesh.weights().primitiveField().cdata() + start;
    const vector* const C = mesh.C().primitiveField().cdata();
    // The face centres, areas and normals: the general schemes' only
    const vector* const Cf =
        general ? mesh.Cf().primitiveField().cdata() + start : nullptr;
    const vector* const Sf =
        general ? mesh.Sf().primitiveField().cdata() + start : nullptr;
    const scalar* const magSf =
        general ? mesh.magSf().primitiveField().cdata() + start : nullptr;
    const scalar* const rhoc = rho.cdata();
    const vector* const Uc = U.cdata();
    const scalar* const pc = p.cdata();
    const vector* const gRho = gradRho.cdata();
    const tensor* const gU = gradU.cdata();
    const vector* const gP = gradP.cdata();
    scalar* const Lrho = L.rho.data();
    scalar* const Rrho = R.rho.data();
    vector* const LU = L.U.data();
    vector* const RU = R.U.data();
    scalar* const Lp = L.p.data();
    scalar* const Rp = R.p.data();

    for (label i = 0; i < size; ++i)
    {
        const label own = owner[i];
        const label nei = neighbour[i];
        const scalar wf = w[i];
        const vector d(C[nei] - C[own]);

        if constexpr (general)
        {
            if (UScheme.characteristic)
            {
                characteristicValues
                (
                    rhoLimiter.functions, ULimiter.functions, UScheme.limiter,
                    UScheme.tangential, wf, rhoc[own], rhoc[nei], Uc[own],
                    Uc[nei], pc[own], pc[nei], (*c)[own], (*c)[nei],
                    gRho[own], gRho[nei], gU[own], gU[nei], gP[own], gP[nei],
                    d, Sf[i]/magSf[i], Lrho[i], Rrho[i], LU[i], RU[i], Lp[i],
                    Rp[i]
                );
                continue;
            }
        }

        // The face centre's offsets from the cells (multidimensional
        // limiters only)
        vector dP(Zero), dN(Zero);
        if constexpr (general)
        {
            dP = Cf[i] - C[own];
            dN = Cf[i] - C[nei];
        }

        internalFaceValues
        (
            rhoLimiter, wf, rhoc[own], rhoc[nei], gRho[own], gRho[nei], d,
            dP, dN, Lrho[i], Rrho[i]
        );
        if constexpr (general)
        {
            if (UScheme.faceFrame)
            {
                faceFrameValues
                (
                    rhoLimiter.functions, ULimiter.functions, UScheme.limiter,
                    UScheme.tangential, wf, Uc[own], Uc[nei], gU[own],
                    gU[nei], d, Sf[i]/magSf[i], LU[i], RU[i]
                );
            }
            else
            {
                internalFaceValues
                (
                    ULimiter, wf, Uc[own], Uc[nei], gU[own], gU[nei], d, dP,
                    dN, LU[i], RU[i]
                );
            }
        }
        else
        {
            internalFaceValues
            (
                ULimiter, wf, Uc[own], Uc[nei], gU[own], gU[nei], d, dP, dN,
                LU[i], RU[i]
            );
        }
        internalFaceValues
        (
            pLimiter, wf, pc[own], pc[nei], gP[own], gP[nei], d, dP, dN,
            Lp[i], Rp[i]
        );
    }
}


//- faces(rhoLimiter, ULimiter, pLimiter) with OpenFOAM's class Limiter
//  (its NVDTVD form for rho and p, its NVDVTVDV form for U) as
//  compiledLimiters
template<template<class> class Limiter, class Faces>
inline void withCompiledLimiter(const Faces& faces)
{
    const compiledLimiter<Limiter<NVDTVD>> s
    {
        scalarLimiters().template get<Limiter>()
    };
    const compiledLimiter<Limiter<NVDVTVDV>> v
    {
        vectorLimiters().template get<Limiter>()
    };
    faces(s, v, s);
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::MUSCLReconstruction::limiterType
Foam::MUSCLReconstruction::readLimiter
(
    const fvMesh& mesh,
    const word& fieldName,
    const Enum<limiterType>& names
)
{
    const word entry("reconstruct(" + fieldName + ')');
    ITstream& is = mesh.interpolationScheme(entry);
    const word name(is);
    if (!names.found(name) || !is.eof())
    {
        FatalIOErrorInFunction(mesh.schemesDict())
            << "system/fvSchemes: interpolationSchemes/" << entry
            << " is '" << is.toString().c_str() << "'; the reconstruction"
            << " of the Riemann fluxes takes " << names
            << (
                   &names == &vectorNames
                 ? " or normalTangential N T (N, T: upwind MUSCL vanLeer"
                   " Minmod vanAlbada)"
                 : ""
               )
            << nl << exit(FatalIOError);
    }
    const limiterType type = names.get(name);
    if (type != limiterType::upwind)
    {
        checkGradScheme(mesh, fieldName, name);
    }
    return type;
}


void Foam::MUSCLReconstruction::checkGradScheme
(
    const fvMesh& mesh,
    const word& fieldName,
    const word& schemeName
)
{
    // The limiter's gradient: the one of OpenFOAM's limited schemes, or
    // a least-squares one
    const word gradEntry("grad(" + fieldName + ')');
    ITstream& gis = mesh.gradScheme(gradEntry);
    if (!gradientNames.found(gis.toString()))
    {
        FatalIOErrorInFunction(mesh.schemesDict())
            << "system/fvSchemes: gradSchemes/" << gradEntry << " is '"
            << gis.toString().c_str() << "'; the " << schemeName
            << " reconstruction of the Riemann fluxes takes one of ("
            << gradientNames[0].c_str() << ')';
        for (label i = 1; i < gradientNames.size(); ++i)
        {
            FatalIOError<< " (" << gradientNames[i].c_str() << ')';
        }
        FatalIOError<< nl << exit(FatalIOError);
    }
}


template<class Type>
Foam::tmp<Foam::fv::gradScheme<Type>>
Foam::MUSCLReconstruction::leastSquaresScheme
(
    const fvMesh& mesh,
    const word& fieldName,
    const bool needed
)
{
    if (!needed)
    {
        return tmp<fv::gradScheme<Type>>();
    }
    ITstream& gis = mesh.gradScheme("grad(" + fieldName + ')');
    if (gis.toString() == gradientNames[0])
    {
        return tmp<fv::gradScheme<Type>>();
    }
    gis.rewind();
    return fv::gradScheme<Type>::New(mesh, gis);
}


Foam::MUSCLReconstruction::vectorScheme
Foam::MUSCLReconstruction::readVectorScheme(const fvMesh& mesh)
{
    static const word frameName("normalTangential");
    static const word characteristicName("characteristic");
    const word entry("reconstruct(U)");
    ITstream& is = mesh.interpolationScheme(entry);

    // Peek at the first word: the face frame's or the characteristic
    // keyword, or a limiter
    const word first
    (
        is.size() > 0 && is[0].isWord() ? is[0].wordToken() : word::null
    );
    const bool characteristic = (first == characteristicName);
    const bool faceFrame = characteristic || (first == frameName);
    if (!faceFrame)
    {
        const limiterType type = readLimiter(mesh, "U", vectorNames);
        return vectorScheme{type, type, false, false};
    }

    // normalTangential N T, characteristic N T: N and T TVD limiters of
    // the scalar names
    limiterType parts[2] = {limiterType::upwind, limiterType::upwind};
    bool valid = (is.size() == 3);
    for (label i = 1; valid && i < 3; ++i)
    {
        valid =
            is[i].isWord()
         && scalarNames.found(is[i].wordToken())
         && !multidimensional(scalarNames.get(is[i].wordToken()));
        if (valid)
        {
            parts[i - 1] = scalarNames.get(is[i].wordToken());
        }
    }
    if (!valid)
    {
        FatalIOErrorInFunction(mesh.schemesDict())
            << "system/fvSchemes: interpolationSchemes/" << entry
            << " is '" << is.toString().c_str() << "'; the face frame's"
            << " reconstruction takes " << frameName
            << " N T (N: the normal component, T: the tangential part) or "
            << characteristicName
            << " N T (N: the acoustic and entropy waves, T: the tangential"
            << " part), N and T each one of (upwind MUSCL vanLeer Minmod"
            << " vanAlbada)" << nl << exit(FatalIOError);
    }
    const vectorScheme scheme{parts[0], parts[1], true, characteristic};
    if (scheme.needsGradient())
    {
        checkGradScheme(mesh, "U", first);
    }
    return scheme;
}


template<class Type>
void Foam::MUSCLReconstruction::cellGradient
(
    const tmp<fv::gradScheme<Type>>& scheme,
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    GeometricField
    <
        typename outerProduct<vector, Type>::type,
        fvPatchField,
        volMesh
    >& grad
) const
{
    if (scheme.valid())
    {
        grad.primitiveFieldRef() =
            scheme().calcGrad(vf, "grad(" + vf.name() + ')')()
           .primitiveField();
    }
    else
    {
        gaussGrad(vf, grad);
    }
}


template<class Type>
void Foam::MUSCLReconstruction::gaussGrad
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    GeometricField
    <
        typename outerProduct<vector, Type>::type,
        fvPatchField,
        volMesh
    >& grad
) const
{
    typedef typename outerProduct<vector, Type>::type GradType;

    const labelUList& owner = mesh_.owner();
    const labelUList& neighbour = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const scalarField& w = mesh_.weights();
    const Field<Type>& v = vf;

    Field<GradType>& g = grad.primitiveFieldRef();
    g = Zero;

    forAll(owner, facei)
    {
        const label own = owner[facei];
        const label nei = neighbour[facei];
        const GradType Sfssf = Sf[facei]*(w[facei]*(v[own] - v[nei]) + v[nei]);
        g[own] += Sfssf;
        g[nei] -= Sfssf;
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& faceCells = patch.faceCells();
        const vectorField& pSf = mesh_.Sf().boundaryField()[patchi];
        const fvPatchField<Type>& pvf = vf.boundaryField()[patchi];

        if (pvf.coupled())
        {
            const scalarField& pw = mesh_.weights().boundaryField()[patchi];
            const Field<Type> vP(pvf.patchInternalField());
            const Field<Type> vN(pvf.patchNeighbourField());
            forAll(faceCells, facei)
            {
                g[faceCells[facei]] +=
                    pSf[facei]
                   *(pw[facei]*vP[facei] + (1.0 - pw[facei])*vN[facei]);
            }
        }
        else
        {
            forAll(faceCells, facei)
            {
                g[faceCells[facei]] += pSf[facei]*pvf[facei];
            }
        }
    }

    g /= mesh_.V().field();
}


template<class Type>
void Foam::MUSCLReconstruction::limitGradient
(
    const limiterType type,
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    GeometricField
    <
        typename outerProduct<vector, Type>::type,
        fvPatchField,
        volMesh
    >& grad
) const
{
    typedef typename outerProduct<vector, Type>::type GradType;

    const labelUList& owner = mesh_.owner();
    const labelUList& neighbour = mesh_.neighbour();
    const vectorField& C = mesh_.C();
    const vectorField& Cf = mesh_.Cf();
    const scalarField& V = mesh_.V();
    const Field<Type>& v = vf;
    Field<GradType>& g = grad.primitiveFieldRef();

    // The max and min over the cell and its face neighbours, internal and
    // coupled (the neighbour processor's or cyclic's cells)
    Field<Type> maxV(v);
    Field<Type> minV(v);
    forAll(owner, facei)
    {
        const label own = owner[facei];
        const label nei = neighbour[facei];
        maxV[own] = max(maxV[own], v[nei]);
        minV[own] = min(minV[own], v[nei]);
        maxV[nei] = max(maxV[nei], v[own]);
        minV[nei] = min(minV[nei], v[own]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatchField<Type>& pvf = vf.boundaryField()[patchi];
        if (pvf.coupled())
        {
            const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
            const Field<Type> vN(pvf.patchNeighbourField());
            forAll(faceCells, facei)
            {
                const label c = faceCells[facei];
                maxV[c] = max(maxV[c], vN[facei]);
                minV[c] = min(minV[c], vN[facei]);
            }
        }
    }
    maxV -= v;
    minV -= v;

    // Venkatakrishnan's eps^2 = (K h)^3, h = V^(1/3)
    scalarField eps2(V.size(), 0);
    if (type == limiterType::venkatakrishnan)
    {
        forAll(eps2, celli)
        {
            eps2[celli] = pow3(venkatakrishnanK*cbrt(V[celli]));
        }
    }

    Field<Type> psi(v.size(), pTraits<Type>::one);
    forAll(owner, facei)
    {
        const label own = owner[facei];
        const label nei = neighbour[facei];
        limitFace
        (
            type, eps2[own], v[own], maxV[own], minV[own],
            (Cf[facei] - C[own]) & g[own], psi[own]
        );
        limitFace
        (
            type, eps2[nei], v[nei], maxV[nei], minV[nei],
            (Cf[facei] - C[nei]) & g[nei], psi[nei]
        );
    }
    forAll(mesh_.boundary(), patchi)
    {
        if (vf.boundaryField()[patchi].coupled())
        {
            const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
            const vectorField& pCf = mesh_.Cf().boundaryField()[patchi];
            forAll(faceCells, facei)
            {
                const label c = faceCells[facei];
                limitFace
                (
                    type, eps2[c], v[c], maxV[c], minV[c],
                    (pCf[facei] - C[c]) & g[c], psi[c]
                );
            }
        }
    }

    forAll(g, celli)
    {
        scaleGradient(psi[celli], g[celli]);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::MUSCLReconstruction::MUSCLReconstruction(const fvMesh& mesh)
:
    mesh_(mesh),
    rhoLimiter_(readLimiter(mesh, "rho", scalarNames)),
    UScheme_(readVectorScheme(mesh)),
    ULimiter_(UScheme_.limiter),
    pLimiter_(readLimiter(mesh, "p", scalarNames)),
    coupled_
    (
        returnReduce
        (
            [&mesh]()
            {
                for (const fvPatch& patch : mesh.boundary())
                {
                    if (patch.coupled())
                    {
                        return true;
                    }
                }
                return false;
            }(),
            orOp<bool>()
        )
    ),
    gradRho_
    (
        IOobject("MUSCLReconstruction:grad(rho)", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimDensity/dimLength, Zero),
        calculatedFvPatchField<vector>::typeName
    ),
    gradU_
    (
        IOobject("MUSCLReconstruction:grad(U)", mesh.time().timeName(), mesh),
        mesh,
        dimensionedTensor(dimVelocity/dimLength, Zero),
        calculatedFvPatchField<tensor>::typeName
    ),
    gradP_
    (
        IOobject("MUSCLReconstruction:grad(p)", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimPressure/dimLength, Zero),
        calculatedFvPatchField<vector>::typeName
    ),
    rhoGradScheme_
    (
        leastSquaresScheme<scalar>
        (
            mesh, "rho", rhoLimiter_ != limiterType::upwind
        )
    ),
    UGradScheme_
    (
        leastSquaresScheme<vector>(mesh, "U", UScheme_.needsGradient())
    ),
    pGradScheme_
    (
        leastSquaresScheme<scalar>(mesh, "p", pLimiter_ != limiterType::upwind)
    ),
    gradientsPending_(false),
    c_(nullptr)
{
    // The characteristic reconstruction limits rho, U and p together with
    // N: reconstruct(rho) and reconstruct(p) must name it (so that their
    // gradients are computed and no other limiter is implied)
    if
    (
        UScheme_.characteristic
     && (rhoLimiter_ != UScheme_.limiter || pLimiter_ != UScheme_.limiter)
    )
    {
        FatalIOErrorInFunction(mesh.schemesDict())
            << "system/fvSchemes: interpolationSchemes/reconstruct(U) is"
            << " 'characteristic " << scalarNames[UScheme_.limiter]
            << ' ' << scalarNames[UScheme_.tangential]
            << "', which limits rho, U and p together: reconstruct(rho)"
            << " and reconstruct(p) must be "
            << scalarNames[UScheme_.limiter] << " too (they are "
            << scalarNames[rhoLimiter_] << " and "
            << scalarNames[pLimiter_] << ')' << nl << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

const Foam::volScalarField& Foam::MUSCLReconstruction::soundSpeedField() const
{
    if (!c_)
    {
        FatalErrorInFunction
            << "the characteristic reconstruction needs the sound speed"
            << " (soundSpeed(c) before reconstruct)" << abort(FatalError);
    }
    return *c_;
}


void Foam::MUSCLReconstruction::startCellGradients
(
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& p
)
{
    if (gradientsPending_)
    {
        FatalErrorInFunction
            << "the cell gradients' exchange of the last call is not"
            << " finished (finishCellGradients)" << abort(FatalError);
    }

    // The neighbour cells' gradients on processor and cyclic patches: the
    // three fields' exchanges started together, waited for once; only the
    // coupled patches' gradient values are read (reconstructCoupled), so
    // only they are evaluated (a symmetry plane's transform of gradU in
    // every stage on 2 ranks, none serially: issue 18 item 5, eff18e)
    gradientExchange_ = foamTools::boundaryEvaluation();

    // The three Gauss-linear gradients in one face loop when each is
    // needed and none is a least-squares one (the default schemes)
    const bool together =
        rhoLimiter_ != limiterType::upwind
     && UScheme_.needsGradient()
     && pLimiter_ != limiterType::upwind
     && !rhoGradScheme_.valid()
     && !UGradScheme_.valid()
     && !pGradScheme_.valid();
    if (together)
    {
        gaussGrads(mesh_, rho, U, p, gradRho_, gradU_, gradP_);
    }

    if (rhoLimiter_ != limiterType::upwind)
    {
        if (!together)
        {
            cellGradient(rhoGradScheme_, rho, gradRho_);
        }
        if (multidimensional(rhoLimiter_))
        {
            limitGradient(rhoLimiter_, rho, gradRho_);
        }
        if (coupled_)
        {
            gradientExchange_.startCoupled(gradRho_);
        }
    }
    if (UScheme_.needsGradient())
    {
        if (!together)
        {
            cellGradient(UGradScheme_, U, gradU_);
        }
        if (multidimensional(ULimiter_))
        {
            limitGradient(ULimiter_, U, gradU_);
        }
        if (coupled_)
        {
            gradientExchange_.startCoupled(gradU_);
        }
    }
    if (pLimiter_ != limiterType::upwind)
    {
        if (!together)
        {
            cellGradient(pGradScheme_, p, gradP_);
        }
        if (multidimensional(pLimiter_))
        {
            limitGradient(pLimiter_, p, gradP_);
        }
        if (coupled_)
        {
            gradientExchange_.startCoupled(gradP_);
        }
    }
    gradientsPending_ = true;
}


void Foam::MUSCLReconstruction::finishCellGradients()
{
    if (!gradientsPending_)
    {
        FatalErrorInFunction
            << "no cell gradients started (startCellGradients)"
            << abort(FatalError);
    }
    gradientsPending_ = false;
    if (!coupled_)
    {
        return;
    }
    if (rhoLimiter_ != limiterType::upwind)
    {
        gradientExchange_.finishCoupled(gradRho_);
    }
    if (UScheme_.needsGradient())
    {
        gradientExchange_.finishCoupled(gradU_);
    }
    if (pLimiter_ != limiterType::upwind)
    {
        gradientExchange_.finishCoupled(gradP_);
    }
}


void Foam::MUSCLReconstruction::cellGradients
(
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& p
)
{
    startCellGradients(rho, U, p);
    finishCellGradients();
}


void Foam::MUSCLReconstruction::reconstruct
(
    const label start,
    const label size,
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& p,
    states& L,
    states& R
) const
{
    if (start < 0 || size < 0 || start + size > mesh_.nInternalFaces())
    {
        FatalErrorInFunction
            << "Faces " << start << " to " << start + size - 1
            << " are not internal faces (0 to "
            << mesh_.nInternalFaces() - 1 << ')' << exit(FatalError);
    }

    for (states* s : {&L, &R})
    {
        s->rho.setSize(size);
        s->U.setSize(size);
        s->p.setSize(size);
    }

    const scalarField* c = nullptr;
    if (UScheme_.characteristic)
    {
        c = &soundSpeedField().primitiveField();
    }
    auto faces = [&]
    (
        const auto& rhoLimiter,
        const auto& ULimiter,
        const auto& pLimiter
    )
    {
        internalFaceStates
        (
            mesh_, start, size, rhoLimiter, ULimiter, pLimiter, UScheme_, c,
            rho, U, p, gradRho_, gradU_, gradP_, L, R
        );
    };

    // The default schemes (one TVD limiter for rho, U and p): the loop
    // with the limiter compiled in, the same arithmetic
    if
    (
        !UScheme_.faceFrame
     && !UScheme_.characteristic
     && rhoLimiter_ == ULimiter_
     && pLimiter_ == ULimiter_
    )
    {
        switch (ULimiter_)
        {
            case limiterType::MUSCL:
                withCompiledLimiter<MUSCLLimiter>(faces);
                return;
            case limiterType::vanLeer:
                withCompiledLimiter<vanLeerLimiter>(faces);
                return;
            case limiterType::Minmod:
                withCompiledLimiter<MinmodLimiter>(faces);
                return;
            case limiterType::vanAlbada:
                withCompiledLimiter<vanAlbadaLimiter>(faces);
                return;
            default:
                break;
        }
    }

    faces
    (
        runTimeLimiter<NVDTVD>{scalarLimiters(), rhoLimiter_},
        runTimeLimiter<NVDVTVDV>{vectorLimiters(), ULimiter_},
        runTimeLimiter<NVDTVD>{scalarLimiters(), pLimiter_}
    );
}


void Foam::MUSCLReconstruction::reconstruct
(
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& p,
    states& L,
    states& R
)
{
    cellGradients(rho, U, p);
    reconstruct(0, mesh_.nInternalFaces(), rho, U, p, L, R);
}


void Foam::MUSCLReconstruction::reconstructCoupled
(
    const label patchi,
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& p,
    states& L,
    states& R
) const
{
    if (UScheme_.characteristic)
    {
        coupledCharacteristicValues
        (
            UScheme_, patchi, rho, U, p, soundSpeedField(), gradRho_,
            gradU_, gradP_, L, R
        );
        return;
    }

    coupledFaceValues
    (
        scalarLimiters(), rhoLimiter_, rho.boundaryField()[patchi],
        gradRho_.boundaryField()[patchi], L.rho, R.rho
    );
    if (UScheme_.faceFrame)
    {
        coupledFaceFrameValues
        (
            UScheme_, U.boundaryField()[patchi],
            gradU_.boundaryField()[patchi], L.U, R.U
        );
    }
    else
    {
        coupledFaceValues
        (
            vectorLimiters(), ULimiter_, U.boundaryField()[patchi],
            gradU_.boundaryField()[patchi], L.U, R.U
        );
    }
    coupledFaceValues
    (
        scalarLimiters(), pLimiter_, p.boundaryField()[patchi],
        gradP_.boundaryField()[patchi], L.p, R.p
    );
}


// ************************************************************************* //
