#include "Loads.H"
#include "Model.H"
#include "SolidError.H"

#include <algorithm>
#include <cmath>
#include <sstream>

solid::NodalLoad::NodalLoad
(
    const std::vector<int>& nodes,
    int component,
    TimeFunction f
)
:
    nodes_(nodes),
    givenForces_(false),
    component_(component),
    force_(std::move(f)),
    dim_(0)
{}


solid::NodalLoad::NodalLoad(const std::vector<int>& nodes, int dim)
:
    nodes_(nodes),
    givenForces_(true),
    component_(-1),
    dim_(dim),
    forces0_(nodes.size()*dim, 0.0),
    forces_(nodes.size()*dim, 0.0),
    time0_(0),
    time1_(0)
{}


void solid::NodalLoad::checkForces(const std::vector<double>& forces) const
{
    if (!givenForces_)
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "nodal load: its force is a "
            "function of time, not set by setForces()"
        );
    }
    if (forces.size() != forces_.size())
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "nodal load: "
          + std::to_string(forces.size()) + " forces for "
          + std::to_string(forces_.size()) + " node components"
        );
    }
}


void solid::NodalLoad::setForces(const std::vector<double>& forces)
{
    checkForces(forces);
    forces0_ = forces;
    forces_ = forces;
    time0_ = time1_ = 0;
}


void solid::NodalLoad::setForces
(
    const std::vector<double>& forces0,
    double t0,
    const std::vector<double>& forces1,
    double t1
)
{
    checkForces(forces0);
    checkForces(forces1);
    if (!(t1 > t0))
    {
        std::ostringstream os;
        os.precision(17);
        os << "nodal load: forces linear in time need t1 > t0, got t0 = "
           << t0 << " s, t1 = " << t1 << " s";
        throw SolidError(SolidError::Kind::parameter, os.str());
    }
    forces0_ = forces0;
    forces_ = forces1;
    time0_ = t0;
    time1_ = t1;
}


void solid::NodalLoad::addForce
(
    const Model& model,
    const Eigen::VectorXd&,
    double t,
    Eigen::VectorXd& f,
    Triplets*
) const
{
    const int dim = model.mesh().dim();
    if (givenForces_)
    {
        if (dim_ != dim)
        {
            throw SolidError
            (
                SolidError::Kind::parameter, "nodal load: forces of "
              + std::to_string(dim_) + " components per node on a mesh of "
                "dimension " + std::to_string(dim)
            );
        }
        // Weight of the end forces: 1 for a constant load and from
        // (within round-off of) t1 on
        const double w = time1_ > time0_
          ? std::max(0.0, (t - time0_)/(time1_ - time0_))
          : 1;
        for (std::size_t i = 0; i < nodes_.size(); ++i)
        {
            for (int d = 0; d < dim; ++d)
            {
                const std::size_t k = dim*i + d;
                f(dim*nodes_[i] + d) += w >= 1 - 1e-9
                  ? forces_[k]
                  : (1 - w)*forces0_[k] + w*forces_[k];
            }
        }
        return;
    }
    if (component_ < 0 || component_ >= dim)
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "nodal load: component "
          + std::to_string(component_) + " out of range [0, "
          + std::to_string(dim) + ")"
        );
    }
    const double F = force_(t);
    for (int n : nodes_) f(n*dim + component_) += F;
}


solid::PressureLoad::PressureLoad(const std::string& faceSet, TimeFunction p)
:
    faceSet_(faceSet),
    pressure_(std::move(p))
{}


void solid::PressureLoad::addForce
(
    const Model& model,
    const Eigen::VectorXd& u,
    double t,
    Eigen::VectorXd& f,
    Triplets* K
) const
{
    addForce(model.mesh(), u, t, f, K);
}


void solid::PressureLoad::addForce
(
    const Mesh& mesh,
    const Eigen::VectorXd& u,
    double t,
    Eigen::VectorXd& f,
    Triplets* K
) const
{
    const int dim = mesh.dim();
    const double p0 = pressure_(t);
    const auto& faces = mesh.faceSet(faceSet_);
    if (!facePressure_.empty() && facePressure_.size() != faces.size())
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "pressure load on '" + faceSet_
          + "': " + std::to_string(facePressure_.size())
          + " face values for " + std::to_string(faces.size()) + " faces"
        );
    }
    const ShapeRule& rule = faceRule(mesh.type);
    const int nf = rule.nen;
    const auto skew = [](const Vec3& a)
    {
        Mat3 S;
        S << 0, -a(2), a(1),
             a(2), 0, -a(0),
             -a(1), a(0), 0;
        return S;
    };
    for (std::size_t fi = 0; fi < faces.size(); ++fi)
    {
        const auto& face = faces[fi];
        const double p = facePressure_.empty() ? p0 : p0*facePressure_[fi];
        if (p == 0) continue;
        std::vector<Vec3> x(nf);
        for (int a = 0; a < nf; ++a)
        {
            x[a] = mesh.X[face[a]];
            for (int i = 0; i < dim; ++i) x[a](i) += u(face[a]*dim + i);
        }
        for (int q = 0; q < rule.nqp(); ++q)
        {
            const Eigen::VectorXd& N = rule.N[q];
            const Eigen::MatrixXd& d = rule.dNdxi[q];
            const double w = rule.w[q];
            if (mesh.axisymmetric())
            {
                double r = 0, rx = 0, zx = 0;
                for (int a = 0; a < nf; ++a)
                {
                    r += N(a)*x[a](0);
                    rx += d(a, 0)*x[a](0);
                    zx += d(a, 0)*x[a](1);
                }
                const double c = 2*M_PI*w*p;
                for (int a = 0; a < nf; ++a)
                {
                    const int ra = face[a]*dim;
                    f(ra) -= c*N(a)*r*zx;
                    f(ra + 1) += c*N(a)*r*rx;
                    if (!K) continue;
                    for (int b = 0; b < nf; ++b)
                    {
                        const int rb = face[b]*dim;
                        // -df/dx
                        K->emplace_back(ra, rb, c*N(a)*N(b)*zx);
                        K->emplace_back(ra, rb + 1, c*N(a)*r*d(b, 0));
                        K->emplace_back
                        (
                            ra + 1, rb, -c*N(a)*(N(b)*rx + r*d(b, 0))
                        );
                    }
                }
            }
            else
            {
                Vec3 xa = Vec3::Zero(), xb = Vec3::Zero();
                for (int a = 0; a < nf; ++a)
                {
                    xa += d(a, 0)*x[a];
                    xb += d(a, 1)*x[a];
                }
                const Vec3 n = xa.cross(xb);
                for (int a = 0; a < nf; ++a)
                {
                    const int ra = face[a]*dim;
                    for (int i = 0; i < 3; ++i) f(ra + i) -= p*w*N(a)*n(i);
                    if (!K) continue;
                    for (int b = 0; b < nf; ++b)
                    {
                        const int rb = face[b]*dim;
                        // dn/dx_b = -N_b,xi [x,eta]x + N_b,eta [x,xi]x
                        const Mat3 dn = -d(b, 0)*skew(xb) + d(b, 1)*skew(xa);
                        for (int i = 0; i < 3; ++i)
                        for (int k = 0; k < 3; ++k)
                        {
                            K->emplace_back
                            (
                                ra + i, rb + k, p*w*N(a)*dn(i, k)
                            );
                        }
                    }
                }
            }
        }
    }
}
