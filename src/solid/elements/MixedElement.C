#include "MixedElement.H"
#include "SolidError.H"

#include <cmath>
#include <sstream>

namespace
{

// Largest face measure of an element: the longest edge (r-z) or the
// largest face area (3D); the arithmetic of the general loop over
// elementFaces, on fixed-size data (x: node coordinates, node major)
double longestEdge(const double* x)
{
    static const int q[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    double amax = 0;
    for (int k = 0; k < 4; ++k)
    {
        const solid::Vec3 d
        (
            x[2*q[k][1]] - x[2*q[k][0]], x[2*q[k][1] + 1] - x[2*q[k][0] + 1],
            0
        );
        amax = std::max(amax, d.norm());
    }
    return amax;
}

double largestFace(const double* x)
{
    static const int h[6][4] =
        {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5},
         {2, 3, 7, 6}, {3, 0, 4, 7}};
    const auto p = [&](int a)
    {
        return solid::Vec3(x[3*a], x[3*a + 1], x[3*a + 2]);
    };
    double amax = 0;
    for (int k = 0; k < 6; ++k)
    {
        const solid::Vec3 d1 = p(h[k][2]) - p(h[k][0]);
        const solid::Vec3 d2 = p(h[k][3]) - p(h[k][1]);
        amax = std::max(amax, 0.5*d1.cross(d2).norm());
    }
    return amax;
}

} // namespace


double solid::characteristicLength
(
    ElementType type,
    const Eigen::Ref<const Eigen::VectorXd>& xe,
    double volume
)
{
    const bool axi = type == ElementType::quad4Axi;
    const double* x = xe.data();
    if (axi)
    {
        const double amax = longestEdge(x);
        const double d10 = x[4] - x[0], d11 = x[5] - x[1];
        const double d20 = x[6] - x[2], d21 = x[7] - x[3];
        return 0.5*std::abs(d10*d21 - d11*d20)/amax;
    }
    const double amax = largestFace(x);
    double vol = volume;
    if (!(vol > 0))
    {
        const ShapeRule& rule = volumeRule(type);
        vol = 0;
        for (int q = 0; q < rule.nqp(); ++q)
        {
            Mat3 Jm = Mat3::Zero();
            for (int a = 0; a < rule.nen; ++a)
            {
                Jm += Vec3(x[3*a], x[3*a + 1], x[3*a + 2])
                   *rule.dNdxi[q].row(a);
            }
            vol += rule.w[q]*Jm.determinant();
        }
    }
    return vol/amax;
}


namespace
{

// Corner Jacobian at node a: the determinant of its edges to its
// neighbours along xi, eta (, zeta), right-handed for a valid element in
// the gmsh node order (the corners of Verdict's hexahedron Jacobian);
// xe: the element's node coordinates (nen dim)
double cornerJacobian
(
    solid::ElementType type,
    const Eigen::Ref<const Eigen::VectorXd>& xe,
    int a
)
{
    static const int hex[8][3] =
    {
        {1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
        {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}
    };
    if (type == solid::ElementType::quad4Axi)
    {
        const int b = (a + 1) % 4, c = (a + 3) % 4;
        return (xe(2*b) - xe(2*a))*(xe(2*c + 1) - xe(2*a + 1))
             - (xe(2*b + 1) - xe(2*a + 1))*(xe(2*c) - xe(2*a));
    }
    const auto x = [&](int n) { return solid::Vec3(xe.segment<3>(3*n)); };
    const solid::Vec3 o = x(a);
    return (x(hex[a][0]) - o).dot((x(hex[a][1]) - o).cross(x(hex[a][2]) - o));
}

} // namespace


namespace
{

// An element inverted during the solve: J <= 0 at Gauss point q
[[noreturn]] void throwInverted
(
    const solid::Mesh& mesh,
    const int e,
    const double J,
    const std::size_t q
)
{
    std::ostringstream os;
    os  << "element " << e << " (region '"
        << mesh.regionNames.at(mesh.region[e])
        << "') inverted during the solve: J = " << J
        << " at Gauss point " << q;
    throw solid::SolidError
    (
        solid::SolidError::Kind::invertedElement, os.str()
    );
}


// An element whose corner at node `node` is folded (corner Jacobian jc,
// reference j0 > 0) while every Gauss point keeps J > 0 (smallest Jmin)
[[noreturn]] void throwFoldedCorner
(
    const solid::Mesh& mesh,
    const int e,
    const int node,
    const double jc,
    const int dim,
    const double j0,
    const double Jmin
)
{
    std::ostringstream os;
    os  << "element " << e << " (region '"
        << mesh.regionNames.at(mesh.region[e])
        << "') inverted during the solve: its corner at node "
        << node << " is folded (corner Jacobian " << jc
        << " m^" << dim << " against " << j0 << " in the"
        " reference) while every Gauss point has J > 0"
        " (smallest " << Jmin << ")";
    throw solid::SolidError
    (
        solid::SolidError::Kind::invertedElement, os.str()
    );
}


// The volumetric part of an element's response, on its dilatation
// theta = v/V (out.theta) and the Maxwell heat of the step (heatStep,
// J): p, q, c^2 (the law's K/rho plus 4/3 mu/rho), zeta, the temperature
// rise, the volumetric energy and the shock heat into out. A constraint
// (d0 = 0) or the two-field u-p multiplier (useMultiplier) takes p from
// pMultiplier. One function for the general and the explicit path, so
// the two stay bitwise equal. Returns the law's response (zero for a
// constraint): the general path's tangent takes dp/dtheta from it
solid::VolumetricResponse volumetricPart
(
    const solid::VolumetricLaw& vol,
    const solid::ElementGeometry& geo,
    const double mu,
    const double rho,
    const bool useMultiplier,
    const double pMultiplier,
    const double dt,
    const double heatStep,
    const double* elemOld,
    double* elemNew,
    solid::ElementOutput& out
)
{
    using namespace solid;
    if (vol.isConstraint())
    {
        out.p = pMultiplier;
        out.q = 0;
        out.c2 = 0;
        out.zeta = 0;
        out.temperatureRise = 0;
        return VolumetricResponse();
    }
    VolumetricInput in;
    in.theta = out.theta;
    in.dt = dt;
    in.length = geo.length;
    if (vol.absorbsHeat())
    {
        // Adiabatic: the Maxwell dissipation heats the EOS energy
        in.heat = heatStep/geo.V;
        out.viscousHeat = out.dissipated;
        out.dissipated = 0;
    }
    const VolumetricResponse vr = vol.evaluate(in, elemOld, elemNew);
    out.energy += vr.energy*geo.V;
    out.shockHeat = vol.dissipated(elemNew)*geo.V;
    out.temperatureRise = vr.temperatureRise;
    out.c2 = vr.c2 + 4.0/3.0*mu/rho;
    out.zeta = vr.zeta;
    if (useMultiplier)
    {
        out.p = pMultiplier;
    }
    else
    {
        out.p = vr.p;
        out.q = vr.q;
    }
    return vr;
}


// The explicit evaluation (no tangent, the volumetric law on the element
// dilatation): the arithmetic of the general path of
// MixedElement::evaluate below, operation for operation in the same
// order, on fixed-size data (NEN nodes, DIM coordinates), so the results
// are bitwise those of the general path (tests/solid/testElements.C)
template<int NEN, int DIM>
void evaluateExplicit
(
    const solid::Mesh& mesh,
    const int e,
    const solid::ElementGeometry& geo,
    const solid::Material& mat,
    const Eigen::VectorXd& uev,
    const bool useMultiplier,
    const double pMultiplier,
    const double dt,
    const double* pointOld,
    double* pointNew,
    const double* elemOld,
    double* elemNew,
    solid::ElementOutput& out,
    const bool checkCorners
)
{
    using namespace solid;
    constexpr int nd = NEN*DIM;
    constexpr bool axi = DIM == 2;
    const IsochoricModel& iso = mat.isochoric();
    const VolumetricLaw& vol = mat.volumetric();
    const int nh = iso.nHistory();
    const double mu = iso.instantaneousShearModulus();
    const double* ue = uev.data();

    Eigen::Matrix<double, nd, 1> f = Eigen::Matrix<double, nd, 1>::Zero();
    Eigen::Matrix<double, nd, 1> g = Eigen::Matrix<double, nd, 1>::Zero();
    out.v = 0;
    out.energy = 0;
    out.dissipated = 0;
    out.shockHeat = 0;
    out.viscousHeat = 0;
    double heatStep = 0;
    out.Jmin = 1e300;
    out.sigma.setZero();
    out.F.setZero();

    const std::size_t nqp = geo.w.size();
    for (std::size_t q = 0; q < nqp; ++q)
    {
        // dNdX: NEN x 3, column major; r-z: its third column is zero (the
        // general path adds u_a x 0 to F_i2 and P_i2 x 0 to f_ai, which
        // leaves F_i2 = +0 and f_ai as they are: sums that start at +0
        // are never -0), so the loops over it stop at DIM
        const double* G = geo.dNdX[q].data();
        const double* Nq = axi ? geo.N[q].data() : nullptr;
        const double Nr = axi ? 1.0/geo.R[q] : 0.0;
        Mat3 F = Mat3::Identity();
        for (int a = 0; a < NEN; ++a)
        {
            for (int i = 0; i < DIM; ++i)
            {
                const double ua = ue[a*DIM + i];
                for (int Jc = 0; Jc < DIM; ++Jc) F(i, Jc) += ua*G[Jc*NEN + a];
            }
            if (axi) F(2, 2) += ue[a*DIM]*Nq[a]*Nr;
        }
        const double J = F.determinant();
        out.Jmin = std::min(out.Jmin, J);
        if (!(J > 0))
        {
            throwInverted(mesh, e, J, q);
        }
        const Mat3 Fi = F.inverse();
        const double wq = geo.w[q];

        IsoResponse r;
        iso.stress
        (
            F.transpose()*F, dt, pointOld + q*nh, pointNew + q*nh, r
        );
        const Mat3 P = F*r.S;
        const Mat3 JFiT = J*Fi.transpose();
        for (int a = 0; a < NEN; ++a)
        {
            for (int i = 0; i < DIM; ++i)
            {
                double fa = 0, ga = 0;
                for (int Jc = 0; Jc < DIM; ++Jc)
                {
                    fa += P(i, Jc)*G[Jc*NEN + a];
                    ga += JFiT(i, Jc)*G[Jc*NEN + a];
                }
                f(a*DIM + i) += wq*fa;
                g(a*DIM + i) += wq*ga;
            }
            if (axi)
            {
                f(a*DIM) += wq*P(2, 2)*Nq[a]*Nr;
                g(a*DIM) += wq*JFiT(2, 2)*Nq[a]*Nr;
            }
        }
        out.v += J*wq;
        out.F += wq*F;
        out.energy += r.psi*wq;
        const double dNew = iso.dissipated(pointNew + q*nh);
        const double dOld = iso.dissipated(pointOld + q*nh);
        out.dissipated += dNew*wq;
        heatStep += (dNew - dOld)*wq;
        out.sigma += wq*(P*F.transpose());     // J sigma_iso dV
    }
    out.theta = out.v/geo.V;
    out.F /= geo.V;

    {
        Eigen::Matrix<double, nd, 1> xe;
        const int* en = mesh.element(e);
        for (int a = 0; a < NEN; ++a)
            for (int i = 0; i < DIM; ++i)
                xe(a*DIM + i) = mesh.X[en[a]](i) + ue[a*DIM + i];
        out.length = characteristicLength
        (
            mesh.type, Eigen::Map<const Eigen::VectorXd>(xe.data(), nd),
            axi ? 0 : out.v
        );
        for (int a = 0; checkCorners && a < NEN; ++a)
        {
            const Eigen::Map<const Eigen::VectorXd> xm(xe.data(), nd);
            const double jc = cornerJacobian(mesh.type, xm, a);
            if (jc > 0) continue;
            Eigen::Matrix<double, nd, 1> x0;
            for (int b = 0; b < NEN; ++b)
                for (int i = 0; i < DIM; ++i)
                    x0(b*DIM + i) = mesh.X[en[b]](i);
            const double j0 = cornerJacobian
            (
                mesh.type, Eigen::Map<const Eigen::VectorXd>(x0.data(), nd), a
            );
            if (!(j0 > 0)) continue;
            throwFoldedCorner(mesh, e, en[a], jc, DIM, j0, out.Jmin);
        }
    }

    volumetricPart
    (
        vol, geo, mu, mat.rho0()/out.theta, useMultiplier, pMultiplier, dt,
        heatStep, elemOld, elemNew, out
    );
    f -= out.p*g;
    out.f = f;
    out.g = g;
    out.sigma = out.sigma/out.v - out.p*Mat3::Identity();
}

} // namespace


void solid::ElementGeometry::build(const Mesh& mesh, int e)
{
    const ShapeRule& rule = volumeRule(mesh.type);
    const int nen = rule.nen, pdim = rule.pdim;
    const int* en = mesh.element(e);
    dNdX.clear();
    N.clear();
    w.clear();
    R.clear();
    V = 0;
    lumpedMass = Eigen::VectorXd::Zero(nen);
    for (int q = 0; q < rule.nqp(); ++q)
    {
        Eigen::MatrixXd J0 = Eigen::MatrixXd::Zero(pdim, pdim);
        for (int a = 0; a < nen; ++a)
        for (int i = 0; i < pdim; ++i)
        for (int j = 0; j < pdim; ++j)
        {
            J0(i, j) += mesh.X[en[a]](i)*rule.dNdxi[q](a, j);
        }
        const double det = J0.determinant();
        if (!(det > 0))
        {
            std::ostringstream os;
            os  << "element " << e << " (region '"
                << mesh.regionNames.at(mesh.region[e])
                << "') is inverted or degenerate in the reference "
                "configuration (det J0 = " << det << ")";
            throw SolidError(SolidError::Kind::mesh, os.str());
        }
        Eigen::MatrixXd d = Eigen::MatrixXd::Zero(nen, 3);
        d.leftCols(pdim) = rule.dNdxi[q]*J0.inverse();
        double wq = rule.w[q]*det;
        double r = 0;
        if (mesh.axisymmetric())
        {
            for (int a = 0; a < nen; ++a) r += rule.N[q](a)*mesh.X[en[a]](0);
            wq *= 2*M_PI*r;
        }
        dNdX.push_back(d);
        N.push_back(rule.N[q]);
        w.push_back(wq);
        R.push_back(r);
        V += wq;
        lumpedMass += wq*rule.N[q];
    }
    Eigen::VectorXd xe(rule.nen*mesh.dim());
    for (int a = 0; a < rule.nen; ++a)
        for (int i = 0; i < mesh.dim(); ++i) xe(a*mesh.dim() + i) = mesh.X[en[a]](i);
    length = characteristicLength(mesh.type, xe, mesh.axisymmetric() ? 0 : V);
}


void solid::MixedElement::evaluate
(
    const Mesh& mesh,
    int e,
    const ElementGeometry& geo,
    const Material& mat,
    const Eigen::VectorXd& ue,
    bool useMultiplier,
    double pMultiplier,
    double dt,
    const double* pointOld,
    double* pointNew,
    const double* elemOld,
    double* elemNew,
    bool tangent,
    ElementOutput& out,
    bool checkCorners,
    bool pointVolumetric
)
{
    const int nen = mesh.nen();
    const int dim = mesh.dim();
    const int nd = nen*dim;
    const bool axi = mesh.axisymmetric();
    const IsochoricModel& iso = mat.isochoric();
    const VolumetricLaw& vol = mat.volumetric();
    const int nh = iso.nHistory();
    const int nv = vol.nHistory();
    pointVolumetric = pointVolumetric && !vol.isConstraint();
    if (pointVolumetric && (tangent || useMultiplier))
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "the point-wise volumetric integration is explicit only (no "
            "tangent, no pressure unknown)"
        );
    }
    if (!tangent && !pointVolumetric)
    {
        if (mesh.type == ElementType::quad4Axi)
        {
            evaluateExplicit<4, 2>
            (
                mesh, e, geo, mat, ue, useMultiplier, pMultiplier, dt,
                pointOld, pointNew, elemOld, elemNew, out, checkCorners
            );
        }
        else
        {
            evaluateExplicit<8, 3>
            (
                mesh, e, geo, mat, ue, useMultiplier, pMultiplier, dt,
                pointOld, pointNew, elemOld, elemNew, out, checkCorners
            );
        }
        return;
    }
    const double mu = iso.instantaneousShearModulus();
    // Point-wise volumetric response: sums over the Gauss points
    double pJw = 0, qJw = 0, c2max = 0, zetaMax = 0, dTw = 0;

    out.f = Eigen::VectorXd::Zero(nd);
    out.g = Eigen::VectorXd::Zero(nd);
    if (tangent) out.K = Eigen::MatrixXd::Zero(nd, nd);
    Eigen::MatrixXd H;
    if (tangent) H = Eigen::MatrixXd::Zero(nd, nd);
    out.v = 0;
    out.energy = 0;
    out.dissipated = 0;
    out.shockHeat = 0;
    out.viscousHeat = 0;
    double heatStep = 0;
    out.Jmin = 1e300;
    out.sigma.setZero();
    out.F.setZero();

    Eigen::Matrix<double, 9, Eigen::Dynamic> B;
    if (tangent) B.resize(9, nd);
    for (std::size_t q = 0; q < geo.w.size(); ++q)
    {
        const Eigen::MatrixXd& G = geo.dNdX[q];
        const double Nr = axi ? 1.0/geo.R[q] : 0.0;
        // F = I + sum_a u_a (x) G_a (+ u_r N_a/R in the hoop direction)
        Mat3 F = Mat3::Identity();
        for (int a = 0; a < nen; ++a)
        {
            for (int i = 0; i < dim; ++i)
            {
                const double ua = ue(a*dim + i);
                for (int Jc = 0; Jc < 3; ++Jc) F(i, Jc) += ua*G(a, Jc);
            }
            if (axi) F(2, 2) += ue(a*dim)*geo.N[q](a)*Nr;
        }
        if (tangent)
        {
            // B: columns vec(dF/du_ai)
            B.setZero();
            for (int a = 0; a < nen; ++a)
            {
                for (int i = 0; i < dim; ++i)
                    for (int Jc = 0; Jc < 3; ++Jc)
                        B(3*i + Jc, a*dim + i) = G(a, Jc);
                if (axi) B(8, a*dim) = geo.N[q](a)*Nr;
            }
        }
        const double J = F.determinant();
        out.Jmin = std::min(out.Jmin, J);
        if (!(J > 0))
        {
            throwInverted(mesh, e, J, q);
        }
        const Mat3 Fi = F.inverse();
        const double wq = geo.w[q];

        IsoResponse r;
        if (tangent)
        {
            iso.evaluate
            (
                F.transpose()*F, dt, pointOld + q*nh, pointNew + q*nh, r
            );
        }
        else
        {
            iso.stress
            (
                F.transpose()*F, dt, pointOld + q*nh, pointNew + q*nh, r
            );
        }
        double pq = 0;
        if (pointVolumetric)
        {
            VolumetricInput in;
            in.theta = J;
            in.dt = dt;
            in.length = geo.length;
            const double dq =
                iso.dissipated(pointNew + q*nh)
              - iso.dissipated(pointOld + q*nh);
            if (vol.absorbsHeat())
            {
                in.heat = dq;
                out.viscousHeat += iso.dissipated(pointNew + q*nh)*wq;
            }
            const VolumetricResponse vr =
                vol.evaluate(in, elemOld + q*nv, elemNew + q*nv);
            pq = vr.p;
            pJw += vr.p*J*wq;
            qJw += vr.q*J*wq;
            out.energy += vr.energy*wq;
            out.shockHeat += vol.dissipated(elemNew + q*nv)*wq;
            dTw += vr.temperatureRise*wq;
            c2max = std::max(c2max, vr.c2 + 4.0/3.0*mu*J/mat.rho0());
            zetaMax = std::max(zetaMax, vr.zeta);
        }
        Mat3 P = F*r.S;
        if (pointVolumetric) P -= pq*J*Fi.transpose();
        const Mat3 JFiT = J*Fi.transpose();
        // f_ai = int P : dF/du_ai, g_ai = int J F^-T : dF/du_ai
        for (int a = 0; a < nen; ++a)
        {
            for (int i = 0; i < dim; ++i)
            {
                double fa = 0, ga = 0;
                for (int Jc = 0; Jc < 3; ++Jc)
                {
                    fa += P(i, Jc)*G(a, Jc);
                    ga += JFiT(i, Jc)*G(a, Jc);
                }
                out.f(a*dim + i) += wq*fa;
                out.g(a*dim + i) += wq*ga;
            }
            if (axi)
            {
                out.f(a*dim) += wq*P(2, 2)*geo.N[q](a)*Nr;
                out.g(a*dim) += wq*JFiT(2, 2)*geo.N[q](a)*Nr;
            }
        }
        out.v += J*wq;
        out.F += wq*F;
        out.energy += r.psi*wq;
        out.dissipated += iso.dissipated(pointNew + q*nh)*wq;
        heatStep +=
            (iso.dissipated(pointNew + q*nh) - iso.dissipated(pointOld + q*nh))
           *wq;
        out.sigma += wq*(P*F.transpose());     // J sigma_iso dV
        if (tangent)
        {
            const Mat9 A = tensor::firstElasticity(F, r.S, r.CC);
            out.K.noalias() += wq*(B.transpose()*A*B);
            H.noalias() += wq*(B.transpose()*tensor::d2Jacobian(Fi, J)*B);
        }
    }
    out.theta = out.v/geo.V;
    out.F /= geo.V;

    {
        // No heap allocation in the explicit hot loop (24 = 8 nodes x 3)
        Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 24, 1> xe(nen*dim);
        const int* en = mesh.element(e);
        for (int a = 0; a < nen; ++a)
            for (int i = 0; i < dim; ++i)
                xe(a*dim + i) = mesh.X[en[a]](i) + ue(a*dim + i);
        out.length = characteristicLength(mesh.type, xe, axi ? 0 : out.v);

        // A corner folded while every Gauss point keeps J > 0 (a node of
        // a thin element pushed through the opposite face): the corner
        // Jacobians, checked against the reference ones (a reference
        // corner that is not positive is the mesh's, not the solve's)
        for (int a = 0; checkCorners && a < nen; ++a)
        {
            const double jc = cornerJacobian(mesh.type, xe, a);
            if (jc > 0) continue;
            Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 24, 1> x0(nen*dim);
            for (int b = 0; b < nen; ++b)
                for (int i = 0; i < dim; ++i)
                    x0(b*dim + i) = mesh.X[en[b]](i);
            const double j0 = cornerJacobian(mesh.type, x0, a);
            if (!(j0 > 0)) continue;
            throwFoldedCorner(mesh, e, en[a], jc, dim, j0, out.Jmin);
        }
    }

    const double rho = mat.rho0()/out.theta;
    if (pointVolumetric)
    {
        if (vol.absorbsHeat()) out.dissipated = 0;
        out.p = pJw/out.v;
        out.q = qJw/out.v;
        out.c2 = c2max;
        out.zeta = zetaMax;
        out.temperatureRise = dTw/geo.V;
        // out.f and out.sigma already hold the pressure
        out.sigma = out.sigma/out.v;
        return;
    }
    // Two-field u-p (useMultiplier): p is an unknown, theta(p) = v/V is
    // the element equation (assembled by Model)
    const VolumetricResponse vr = volumetricPart
    (
        vol, geo, mu, rho, useMultiplier, pMultiplier, dt, heatStep,
        elemOld, elemNew, out
    );
    if (tangent && !vol.isConstraint() && !useMultiplier)
    {
        out.K.noalias() -= (vr.dpdtheta/geo.V)*out.g*out.g.transpose();
    }
    out.f -= out.p*out.g;
    if (tangent) out.K.noalias() -= out.p*H;
    out.sigma = out.sigma/out.v - out.p*Mat3::Identity();
}
