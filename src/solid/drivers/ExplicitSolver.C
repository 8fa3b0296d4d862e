#include "ExplicitSolver.H"
#include "SolidError.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{

//- A time [s] for messages: significant digits, not std::to_string's
//  fixed six decimals (which print nanoseconds as 0.000000)
std::string seconds(const double t)
{
    std::ostringstream os;
    os.precision(10);
    os << t << " s";
    return os.str();
}

//- Parametric coordinates (signs) of the nodes, gmsh order
const int quadSigns[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
const int hexSigns[8][3] =
{
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
    {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}
};

} // namespace


double solid::ExplicitSolver::hourglassCoefficient(int e) const
{
    const Mesh& mesh = model_.mesh();
    const auto it =
        set_.hourglassRegions.find(mesh.regionNames.at(mesh.region[e]));
    return it != set_.hourglassRegions.end() ? it->second : set_.hourglass;
}


void solid::ExplicitSolver::buildHourglass()
{
    Model& m = model_;
    const Mesh& mesh = m.mesh();
    const bool axi = mesh.axisymmetric();
    const int nen = mesh.nen(), dim = mesh.dim();
    const int nh = axi ? 1 : 4;
    hourglassDamping_.resize(mesh.nElements());
    hourglassStableDt_ = 1e300;
    const Eigen::VectorXd& mass = m.lumpedMass();
    for (int e = 0; e < mesh.nElements(); ++e)
    {
        const ElementGeometry& geo = m.geometry(e);
        const int* en = mesh.element(e);

        // Base vectors h_alpha (nen x nh)
        Eigen::MatrixXd H(nen, nh);
        for (int a = 0; a < nen; ++a)
        {
            if (axi)
            {
                H(a, 0) = quadSigns[a][0]*quadSigns[a][1];
            }
            else
            {
                const int* s = hexSigns[a];
                H(a, 0) = s[1]*s[2];
                H(a, 1) = s[0]*s[2];
                H(a, 2) = s[0]*s[1];
                H(a, 3) = s[0]*s[1]*s[2];
            }
        }

        // Volume-averaged gradients b (nen x dim), area of the r-z section
        Eigen::MatrixXd b(Eigen::MatrixXd::Zero(nen, dim));
        double area = 0;
        for (std::size_t q = 0; q < geo.w.size(); ++q)
        {
            b += geo.w[q]*geo.dNdX[q].leftCols(dim);
            if (axi) area += geo.w[q]/(2*M_PI*geo.R[q]);
        }
        b /= geo.V;

        // g_alpha = h_alpha - sum_i (h_alpha . X_i) b_i
        Eigen::MatrixXd X(nen, dim);
        for (int a = 0; a < nen; ++a)
            for (int i = 0; i < dim; ++i) X(a, i) = mesh.X[en[a]](i);
        const Eigen::MatrixXd G = H - b*(X.transpose()*H);
        const Eigen::MatrixXd P =
            G*(G.transpose()*G).inverse()*G.transpose();

        // D_e = kappa rho0 c S, c the initial dilatational wave speed
        const ElementOutput o = m.evaluateElement(e, 0);
        const double c = std::sqrt(o.c2);
        const double S =
            axi ? std::sqrt(2*M_PI*(geo.V/(2*M_PI*area))*geo.V)
                : std::pow(geo.V, 2.0/3.0);
        const double D = hourglassCoefficient(e)*m.material(e).rho0()*c*S;
        hourglassDamping_[e] = D*P;
        if (set_.shearViscosity > 0)
        {
            buildShearDamping(e, b, c, area);
        }
        if (!(D > 0)) continue;

        // Explicit limit of the damper (eigenvalue of P is 1): dt < 2 m/D
        for (int a = 0; a < nen; ++a)
        {
            hourglassStableDt_ =
                std::min(hourglassStableDt_, 2*mass(dim*en[a])/D);
        }
    }
}


void solid::ExplicitSolver::buildShearDamping
(
    int e,
    const Eigen::MatrixXd& b,
    double c,
    double area
)
{
    Model& m = model_;
    const Mesh& mesh = m.mesh();
    const bool axi = mesh.axisymmetric();
    const int nen = mesh.nen(), dim = mesh.dim(), nd = nen*dim;
    const ElementGeometry& geo = m.geometry(e);
    const int* en = mesh.element(e);
    if (!set_.shearViscosityFilter && shearDamping_.empty())
    {
        shearDamping_.resize(mesh.nElements());
    }

    // Mean strain-rate operators: normal rates (3 x nd; r-z: rr, zz and
    // the hoop rate v_r/R averaged over the ring volume) and tensor shear
    // rates (r-z: rz; 3D: xy, yz, zx)
    Eigen::MatrixXd Bn(Eigen::MatrixXd::Zero(3, nd));
    Eigen::MatrixXd Bs(Eigen::MatrixXd::Zero(axi ? 1 : 3, nd));
    for (int a = 0; a < nen; ++a)
    {
        for (int i = 0; i < dim; ++i) Bn(i, dim*a + i) = b(a, i);
        if (axi)
        {
            double hoop = 0;
            for (std::size_t q = 0; q < geo.w.size(); ++q)
            {
                hoop += geo.w[q]*geo.N[q](a)/geo.R[q];
            }
            Bn(2, dim*a) = hoop/geo.V;
            Bs(0, dim*a) = 0.5*b(a, 1);
            Bs(0, dim*a + 1) = 0.5*b(a, 0);
        }
        else
        {
            for (int k = 0; k < 3; ++k)
            {
                const int i = k, j = (k + 1) % 3;
                Bs(k, dim*a + i) = 0.5*b(a, j);
                Bs(k, dim*a + j) = 0.5*b(a, i);
            }
        }
    }
    const Eigen::Matrix3d Pdev =
        Eigen::Matrix3d::Identity() - Eigen::Matrix3d::Constant(1.0/3.0);
    const double h = axi ? std::sqrt(area) : std::cbrt(geo.V);
    const double eta = set_.shearViscosity*m.material(e).rho0()*c*h;
    Eigen::MatrixXd C =
        2*eta*geo.V*(Bn.transpose()*Pdev*Bn + 2*Bs.transpose()*Bs);
    C = 0.5*(C + C.transpose());
    if (set_.shearViscosityFilter)
    {
        // Rate operator in the deviatoric metric: |Bd v|^2 = |dev D|^2,
        // the shear rows counted twice (tensor components xy and yx)
        Eigen::MatrixXd Bd(Bn.rows() + Bs.rows(), nd);
        Bd.topRows(3) = Pdev*Bn;
        Bd.bottomRows(Bs.rows()) = std::sqrt(2.0)*Bs;
        if (shearRate_.empty())
        {
            shearRate_.resize(mesh.nElements());
            shearWeight_.assign(mesh.nElements(), 0);
            buildShearSlots();
            shearNodeWeight_.assign(shearSlots_, 0);
        }
        shearRate_[e] = Bd;
        shearWeight_[e] = 2*eta*geo.V;
        for (int a = 0; a < nen; ++a)
        {
            shearNodeWeight_[shearSlot_[nen*e + a]] += shearWeight_[e];
        }
    }
    else
    {
        shearDamping_[e] = C;
    }

    // Explicit limit of the damper: dt < 2 m / lambda_max(C), m the
    // element's smallest nodal mass
    const double lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>
        (
            C, Eigen::EigenvaluesOnly
        ).eigenvalues().maxCoeff();
    if (lambda > 0)
    {
        const Eigen::VectorXd& mass = m.lumpedMass();
        double mMin = 1e300;
        for (int a = 0; a < nen; ++a) mMin = std::min(mMin, mass(dim*en[a]));
        hourglassStableDt_ = std::min(hourglassStableDt_, 2*mMin/lambda);
    }
}


void solid::ExplicitSolver::buildShearSlots()
{
    const Mesh& mesh = model_.mesh();
    const int nen = mesh.nen(), ne = mesh.nElements();
    shearSlot_.assign(std::size_t(nen)*ne, -1);
    if (!set_.shearViscosityFilterByRegion)
    {
        for (int e = 0; e < ne; ++e)
        {
            const int* en = mesh.element(e);
            for (int a = 0; a < nen; ++a) shearSlot_[nen*e + a] = en[a];
        }
        shearSlots_ = mesh.nNodes();
        return;
    }
    // One slot per (node, region) pair met, numbered in element order
    std::map<std::pair<int, int>, int> slot;
    for (int e = 0; e < ne; ++e)
    {
        const int* en = mesh.element(e);
        for (int a = 0; a < nen; ++a)
        {
            const auto it =
                slot.emplace(std::make_pair(en[a], mesh.region[e]),
                             int(slot.size())).first;
            shearSlot_[nen*e + a] = it->second;
        }
    }
    shearSlots_ = int(slot.size());
}


void solid::ExplicitSolver::buildShearNeighbourhood()
{
    const Mesh& mesh = model_.mesh();
    const int nen = mesh.nen(), ne = mesh.nElements();
    const int* slot = shearSlot_.data();
    // Elements with a slot in marked, in increasing order
    auto touching = [&](const std::vector<bool>& marked)
    {
        std::vector<int> elements;
        for (int e = 0; e < ne; ++e)
        {
            for (int a = 0; a < nen; ++a)
            {
                if (marked[slot[nen*e + a]])
                {
                    elements.push_back(e);
                    break;
                }
            }
        }
        return elements;
    };
    // Slots of elements
    auto slotsOf = [&](const std::vector<int>& elements)
    {
        std::vector<bool> marked(shearSlots_, false);
        for (const int e : elements)
        {
            for (int a = 0; a < nen; ++a) marked[slot[nen*e + a]] = true;
        }
        return marked;
    };
    shearMeanElements_ = touching(slotsOf(model_.ownedElements()));
    shearRateElements_ = touching(slotsOf(shearMeanElements_));
    const std::vector<bool> used = slotsOf(shearRateElements_);
    shearUsedSlots_.clear();
    for (int k = 0; k < shearSlots_; ++k)
    {
        if (used[k]) shearUsedSlots_.push_back(k);
    }
    const int ns = shearRate_[0].rows();
    shearD_.resize(ns, ne);
    shearNodal_.resize(ns, shearSlots_);
    shearBack_.resize(ns, shearSlots_);
}


template<int NS, int NEN, int DIM>
void solid::ExplicitSolver::addFilteredShearForce
(
    const Eigen::VectorXd& v,
    Eigen::VectorXd& f
) const
{
    const Mesh& mesh = model_.mesh();
    constexpr int nen = NEN, dim = DIM, ns = NS;
    Eigen::VectorXd ve(nen*dim);
    // Per-element rate vectors (ns <= 6): on the stack, not allocated in
    // the element loops of every step; the column operations below are
    // element-wise (each entry the same arithmetic as Eigen's column
    // expressions), the two products Eigen's (noalias: no temporary)
    using Rate = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;

    // Element rates d_e and their w-weighted averages at the nodes
    // (the averages per slot: a node, or a node and region pair), of
    // the elements the own elements' forces need (buildShearNeighbourhood:
    // the slots read below get all their terms, in the serial order)
    const int* slot = shearSlot_.data();
    Eigen::MatrixXd& d = shearD_;
    Eigen::MatrixXd& nodal = shearNodal_;
    Eigen::MatrixXd& back = shearBack_;
    double* const dp = d.data();
    double* const np = nodal.data();
    double* const bp = back.data();
    for (const int k : shearUsedSlots_)
    {
        for (int i = 0; i < ns; ++i)
        {
            np[ns*k + i] = 0;
            bp[ns*k + i] = 0;
        }
    }
    for (const int e : shearRateElements_)
    {
        const int* en = mesh.element(e);
        for (int a = 0; a < nen; ++a)
            for (int i = 0; i < dim; ++i) ve(dim*a + i) = v(dim*en[a] + i);
        d.col(e).noalias() = shearRate_[e]*ve;
        const double w = shearWeight_[e];
        const double* de = dp + ns*e;
        for (int a = 0; a < nen; ++a)
        {
            double* nk = np + ns*slot[nen*e + a];
            for (int i = 0; i < ns; ++i) nk[i] += w*de[i];
        }
    }
    for (const int k : shearUsedSlots_)
    {
        const double W = shearNodeWeight_[k];
        if (W > 0)
        {
            for (int i = 0; i < ns; ++i) np[ns*k + i] /= W;
        }
    }

    // s = W (I - A) d, and the slot sums of s/(nen W_a) for A^T s
    double* const sp = dp;     // s overwrites d, element by element
    double mean[NS];
    for (const int e : shearMeanElements_)
    {
        for (int i = 0; i < ns; ++i) mean[i] = 0;
        for (int a = 0; a < nen; ++a)
        {
            const double* nk = np + ns*slot[nen*e + a];
            for (int i = 0; i < ns; ++i) mean[i] += nk[i];
        }
        const double w = shearWeight_[e];
        double* se = sp + ns*e;
        for (int i = 0; i < ns; ++i) se[i] = w*(se[i] - mean[i]/nen);
        for (int a = 0; a < nen; ++a)
        {
            const int k = slot[nen*e + a];
            const double den = nen*shearNodeWeight_[k];
            double* bk = bp + ns*k;
            for (int i = 0; i < ns; ++i) bk[i] += se[i]/den;
        }
    }

    // g = (I - A)^T s, f_e = -Bd_e^T g_e: this part's elements
    Rate g(ns);
    for (const int e : model_.ownedElements())
    {
        const int* en = mesh.element(e);
        const double* se = sp + ns*e;
        for (int i = 0; i < ns; ++i) g(i) = se[i];
        const double w = shearWeight_[e];
        for (int a = 0; a < nen; ++a)
        {
            const double* bk = bp + ns*slot[nen*e + a];
            for (int i = 0; i < ns; ++i) g(i) -= w*bk[i];
        }
        ve.noalias() = shearRate_[e].transpose()*g;
        for (int a = 0; a < nen; ++a)
            for (int i = 0; i < dim; ++i) f(dim*en[a] + i) -= ve(dim*a + i);
    }
}


void solid::ExplicitSolver::addFilteredShearForce
(
    const Eigen::VectorXd& v,
    Eigen::VectorXd& f
) const
{
    if (model_.mesh().axisymmetric())
    {
        addFilteredShearForce<4, 4, 2>(v, f);
    }
    else
    {
        addFilteredShearForce<6, 8, 3>(v, f);
    }
}


namespace
{

// The viscous hourglass and (unfiltered) shear damping forces of the own
// elements, f -= D_e v_e, on fixed-size data; the arithmetic of the
// general loops, in their order
template<int NEN, int DIM>
void addDampingForces
(
    const solid::Mesh& mesh,
    const std::vector<int>& elements,
    const std::vector<Eigen::MatrixXd>& hourglass,
    const std::vector<Eigen::MatrixXd>& shear,
    const Eigen::VectorXd& v,
    Eigen::VectorXd& f
)
{
    double ve[NEN][DIM];
    for (const int e : elements)
    {
        const int* en = mesh.element(e);
        for (int a = 0; a < NEN; ++a)
            for (int i = 0; i < DIM; ++i) ve[a][i] = v(DIM*en[a] + i);
        const double* DP = hourglass[e].data();     // NEN x NEN
        for (int a = 0; a < NEN; ++a)
        {
            for (int i = 0; i < DIM; ++i)
            {
                double s = 0;
                for (int k = 0; k < NEN; ++k) s += DP[k*NEN + a]*ve[k][i];
                f(DIM*en[a] + i) -= s;
            }
        }
        if (shear.empty()) continue;
        const double* C = shear[e].data();          // NEN DIM square
        constexpr int nd = NEN*DIM;
        for (int a = 0; a < NEN; ++a)
        {
            for (int i = 0; i < DIM; ++i)
            {
                double s = 0;
                for (int k = 0; k < NEN; ++k)
                    for (int j = 0; j < DIM; ++j)
                        s += C[(DIM*k + j)*nd + DIM*a + i]*ve[k][j];
                f(DIM*en[a] + i) -= s;
            }
        }
    }
}

} // namespace


Eigen::VectorXd solid::ExplicitSolver::hourglassForce
(
    const Eigen::VectorXd& v
) const
{
    Eigen::VectorXd f(Eigen::VectorXd::Zero(v.size()));
    if (hourglassDamping_.empty()) return f;
    if (!shearRate_.empty()) addFilteredShearForce(v, f);
    const Mesh& mesh = model_.mesh();
    if (mesh.axisymmetric())
    {
        addDampingForces<4, 2>
        (
            mesh, model_.ownedElements(), hourglassDamping_, shearDamping_,
            v, f
        );
    }
    else
    {
        addDampingForces<8, 3>
        (
            mesh, model_.ownedElements(), hourglassDamping_, shearDamping_,
            v, f
        );
    }
    return f;
}

void solid::ExplicitSolver::forces
(
    const double t,
    const double dt,
    const Eigen::VectorXd& v,
    Eigen::VectorXd& fhg
)
{
    Model& m = model_;
    if (m.partition().serial())
    {
        m.assemble(m.u, m.pressure, t, dt, false, asm_);
        fhg = hourglassForce(v);
        return;
    }
    // This part's elements; an element's failure on one part stops every
    // part (the exchange below is collective): the flag goes with the
    // forces, the part that failed rethrows its own error
    std::string error;
    SolidError::Kind kind = SolidError::Kind::parameter;
    try
    {
        m.assemble(m.u, m.pressure, t, dt, false, asm_, false);
    }
    catch (const SolidError& e)
    {
        error = e.what();
        kind = e.kind();
        asm_.fint = Eigen::VectorXd::Zero(m.nDisplacementDofs());
        asm_.constraint = Eigen::VectorXd::Zero(m.nMultipliers());
        asm_.fext = Eigen::VectorXd::Zero(m.nDisplacementDofs());
    }
    // The parts that failed and the sum of their kinds (+ 1)
    const long n = m.nDisplacementDofs();
    Eigen::VectorXd more(n + 2);
    more.head(n) = hourglassForce(v);
    more(n) = error.empty() ? 0 : 1;
    more(n + 1) = error.empty() ? 0 : 1 + int(kind);
    m.combineParts(asm_, &more);
    fhg = more.head(n);
    if (!error.empty())
    {
        throw SolidError(kind, error);
    }
    if (more(n) > 0)
    {
        throw SolidError
        (
            more(n) == 1
          ? SolidError::Kind(int(more(n + 1)) - 1)
          : SolidError::Kind::invertedElement,
            "an element owned by another part of the parallel solid "
            "failed (that part reports which)"
        );
    }
}


solid::ExplicitSolver::ExplicitSolver
(
    Model& model,
    const ExplicitSettings& settings
)
:
    model_(model),
    set_(settings)
{
    Model& m = model_;
    const Mesh& mesh = m.mesh();
    for (int e = 0; e < mesh.nElements(); ++e)
    {
        if (m.material(e).volumetric().isConstraint())
        {
            throw SolidError
            (
                SolidError::Kind::parameter,
                "explicit solver: region '"
              + mesh.regionNames[mesh.region[e]] + "' (material '"
              + m.material(e).name() + "') is incompressible (d0 = 0); "
                "the explicit solver needs d0 > 0 or volumetric "
                "mieGruneisen"
            );
        }
    }
    checkParameter("explicit solver", "safety", set_.safety, 0, 1, "-");
    if (set_.hourglass != 0)
    {
        checkParameter
        (
            "explicit solver", "hourglass", set_.hourglass, 0, 1, "-"
        );
    }
    if (set_.shearViscosity != 0)
    {
        checkParameter
        (
            "explicit solver", "shearViscosity", set_.shearViscosity, 0, 1,
            "-"
        );
    }
    bool anyHourglass = set_.hourglass > 0 || set_.shearViscosity > 0;
    for (const auto& r : set_.hourglassRegions)
    {
        const auto& names = m.mesh().regionNames;
        if (std::find(names.begin(), names.end(), r.first) == names.end())
        {
            std::string list;
            for (const auto& n : names) list += " '" + n + "'";
            throw SolidError
            (
                SolidError::Kind::parameter,
                "explicit solver: hourglass viscosity of region '" + r.first
              + "': the mesh has no such region (regions:" + list + ")"
            );
        }
        checkParameter
        (
            "explicit solver", "hourglass of region '" + r.first + "'",
            r.second, 0, 1, "-", true
        );
        anyHourglass |= r.second > 0;
    }
    m.condensePressure(true);
    m.setCornerCheck(true);
    fixed_ = m.prescribedDofs();
    invMass_ = m.lumpedMass().cwiseInverse();
    if (anyHourglass) buildHourglass();
    if (!shearRate_.empty()) buildShearNeighbourhood();
    forces(m.time, 0, m.v, fhg_);
    m.commit();
    fint_ = asm_.fint;
    fext_ = asm_.fext;
    a_ = (fext_ - fint_ + fhg_).cwiseProduct(invMass_);
    for (int d : fixed_) a_(d) = 0;
    stableDt_ = std::min(asm_.stableDt, hourglassStableDt_);
    dt_ = set_.fixedDt > 0 ? set_.fixedDt : set_.safety*stableDt_;
    energy_.kinetic = 0.5*m.v.dot(m.lumpedMass().cwiseProduct(m.v));
    energy_.internal = asm_.energy;
    energy_.initial = energy_.kinetic + energy_.internal;
}


void solid::ExplicitSolver::updateEnergy
(
    const Eigen::VectorXd& du,
    const Eigen::VectorXd& fint,
    const Eigen::VectorXd& fext,
    const Eigen::VectorXd& fhg
)
{
    energy_.internalWork += 0.5*du.dot(fint_ + fint);
    energy_.externalWork += 0.5*du.dot(fext_ + fext);
    // Reactions at prescribed dofs: r = f_int - f_ext - f_hg
    // (quasi-static part)
    for (int d : fixed_)
    {
        energy_.externalWork +=
            0.5*du(d)
           *(
                (fint_(d) - fext_(d) - fhg_(d))
              + (fint(d) - fext(d) - fhg(d))
            );
    }

}


double solid::ExplicitSolver::step()
{
    Model& m = model_;
    const double dt = dt_;
    if (set_.fixedDt > 0 && dt > stableDt_)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "explicit solver: fixed time step " + seconds(dt)
          + " exceeds the stable time step " + seconds(stableDt_)
        );
    }
    const double t1 = m.time + dt;
    const Eigen::VectorXd u0 = m.u;
    const Eigen::VectorXd v0 = m.v;
    Eigen::VectorXd vh = m.v + 0.5*dt*a_;
    m.u += dt*vh;
    m.applyDirichlet(m.u, t1);
    for (int d : fixed_) vh(d) = (m.u(d) - u0(d))/dt;

    // Internal and viscous hourglass forces (from the mid-step velocity)
    Eigen::VectorXd fhg;
    try
    {
        forces(t1, dt, vh, fhg);
    }
    catch (const SolidError& e)
    {
        m.revert();
        m.u = u0;
        throw SolidError
        (
            e.kind(), "explicit step at t = " + seconds(m.time)
          + " (dt = " + seconds(dt) + "): " + e.what()
        );
    }
    Eigen::VectorXd a =
        (asm_.fext - asm_.fint + fhg).cwiseProduct(invMass_);
    for (int d : fixed_) a(d) = 0;
    m.v = vh + 0.5*dt*a;
    for (int d : fixed_) m.v(d) = vh(d);
    updateEnergy(m.u - u0, asm_.fint, asm_.fext, fhg);
    // Dissipation of the hourglass dampers: their work on the step-average
    // velocity, dt/2 (f_n + f_n+1).(v_n + v_n+1)/2, the exact share of the
    // kinetic energy change of velocity Verlet (the force changes within a
    // few steps for a strongly damped pattern, so du = dt v_n+1/2 is not
    // accurate enough for it)
    energy_.hourglass -= 0.25*dt*(fhg_ + fhg).dot(v0 + m.v);
    fint_ = asm_.fint;
    fext_ = asm_.fext;
    fhg_ = fhg;
    a_ = a;
    m.time = t1;
    m.commit();
    ++steps_;

    energy_.kinetic = 0.5*m.v.dot(m.lumpedMass().cwiseProduct(m.v));
    energy_.internal = asm_.energy;
    energy_.dissipated = asm_.dissipated;
    energy_.shockHeat = asm_.shockHeat;
    energy_.viscousHeat = asm_.viscousHeat;
    stableDt_ = std::min(asm_.stableDt, hourglassStableDt_);
    dt_ = set_.fixedDt > 0 ? set_.fixedDt : set_.safety*stableDt_;
    return dt;
}


long solid::ExplicitSolver::advanceTo(double tEnd, bool equalSteps)
{
    const long steps0 = steps_;
    while (model_.time < tEnd*(1 - 1e-12))
    {
        // Steps the interval left needs (1e-12: an interval of m stable
        // steps to round-off is m steps); one: the default's arithmetic
        const double n = equalSteps
          ? std::ceil((tEnd - model_.time)/dt_*(1 - 1e-12))
          : 1;
        if (n > 1)
        {
            dt_ = (tEnd - model_.time)/n;
        }
        else if (model_.time + dt_ > tEnd)
        {
            dt_ = tEnd - model_.time;
        }
        step();
    }
    return steps_ - steps0;
}


solid::ExplicitState solid::ExplicitSolver::state() const
{
    ExplicitState s;
    s.a = a_;
    s.fint = fint_;
    s.fext = fext_;
    s.fhg = fhg_;
    s.dt = dt_;
    s.stableDt = stableDt_;
    s.steps = steps_;
    s.energy = energy_;
    return s;
}


void solid::ExplicitSolver::setState(const ExplicitState& s)
{
    const long n = a_.size();
    if
    (
        s.a.size() != n || s.fint.size() != n || s.fext.size() != n
     || s.fhg.size() != n
    )
    {
        throw SolidError
        (
            SolidError::Kind::io, "explicit solver: restart state has "
          + std::to_string(s.a.size()) + " dofs, the model "
          + std::to_string(n)
        );
    }
    a_ = s.a;
    fint_ = s.fint;
    fext_ = s.fext;
    fhg_ = s.fhg;
    dt_ = s.dt;
    stableDt_ = s.stableDt;
    steps_ = s.steps;
    energy_ = s.energy;
}
