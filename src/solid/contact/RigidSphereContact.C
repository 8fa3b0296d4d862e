#include "RigidSphereContact.H"
#include "Model.H"
#include "SolidError.H"

#include <algorithm>
#include <cmath>

solid::RigidSphereContact::RigidSphereContact
(
    const std::string& faceSet,
    const RigidSphereSettings& settings
)
:
    faceSet_(faceSet),
    set_(settings)
{
    const std::string ctx = "rigid sphere contact on '" + faceSet + "'";
    checkParameter(ctx, "radius", set_.radius, 0, HUGE_VAL, "m");
    checkParameter(ctx, "tolerance", set_.tolerance, 0, HUGE_VAL, "m");
    checkParameter(ctx, "penaltyFactor", set_.penaltyFactor, 0, HUGE_VAL,
                   "-");
    if (!(set_.direction.norm() > 0) || !set_.depth)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            ctx + ": the motion direction must be non-zero and the depth "
            "function set"
        );
    }
    set_.direction.normalize();
}


solid::Vec3 solid::RigidSphereContact::centre(double t) const
{
    return set_.centre0 + set_.depth(t)*set_.direction;
}


void solid::RigidSphereContact::setup(const Model& model) const
{
    if (ready_) return;
    const Mesh& mesh = model.mesh();
    if
    (
        mesh.axisymmetric()
     && (set_.centre0(0) != 0 || set_.direction(0) != 0)
    )
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "rigid sphere contact on '" + faceSet_ + "': in r-z the centre "
            "must lie on the axis and move along it (centre0 r = 0, "
            "direction r = 0)"
        );
    }
    const auto& faces = mesh.faceSet(faceSet_);
    if (faces.empty())
    {
        throw SolidError
        (
            SolidError::Kind::mesh,
            "rigid sphere contact: face set '" + faceSet_ + "' is empty"
        );
    }
    // Adjacent element of each face: the one holding all its nodes
    std::vector<std::vector<int>> nodeElements(mesh.nNodes());
    for (int e = 0; e < mesh.nElements(); ++e)
    {
        for (int a = 0; a < mesh.nen(); ++a)
        {
            nodeElements[mesh.element(e)[a]].push_back(e);
        }
    }
    const ShapeRule& rule = faceRule(mesh.type);
    // Node -> point index; area weight and (area-weighted) penalty summed
    std::vector<int> pointOf(mesh.nNodes(), -1);
    points_.clear();
    std::vector<double> epsA;
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
        const auto& face = faces[f];
        int owner = -1;
        for (int e : nodeElements[face[0]])
        {
            const int* en = mesh.element(e);
            bool all = true;
            for (int n : face)
            {
                all = all && std::find(en, en + mesh.nen(), n)
                    != en + mesh.nen();
            }
            if (all)
            {
                owner = e;
                break;
            }
        }
        if (owner < 0)
        {
            throw SolidError
            (
                SolidError::Kind::mesh, "rigid sphere contact: face "
              + std::to_string(f) + " of set '" + faceSet_
              + "' belongs to no element"
            );
        }
        const double G =
            model.material(owner).isochoric().instantaneousShearModulus();
        // Row-sum (consistent) nodal areas int N_a dA0 and the face size
        std::vector<double> wa(face.size(), 0.0);
        double size = 0;
        for (int q = 0; q < rule.nqp(); ++q)
        {
            Vec3 X = Vec3::Zero(), Xa = Vec3::Zero(), Xb = Vec3::Zero();
            for (std::size_t a = 0; a < face.size(); ++a)
            {
                const Vec3& Xn = mesh.X[face[a]];
                X += rule.N[q](a)*Xn;
                Xa += rule.dNdxi[q](a, 0)*Xn;
                if (rule.pdim > 1) Xb += rule.dNdxi[q](a, 1)*Xn;
            }
            double dA;
            if (mesh.axisymmetric())
            {
                dA = 2*M_PI*X(0)*Xa.norm()*rule.w[q];
                size += Xa.norm()*rule.w[q];
            }
            else
            {
                dA = Xa.cross(Xb).norm()*rule.w[q];
                size += dA;
            }
            for (std::size_t a = 0; a < face.size(); ++a)
            {
                wa[a] += rule.N[q](a)*dA;
            }
        }
        const double h = mesh.axisymmetric() ? size : std::sqrt(size);
        if (!(h > 0))
        {
            throw SolidError
            (
                SolidError::Kind::mesh, "rigid sphere contact: face "
              + std::to_string(f) + " of set '" + faceSet_
              + "' has zero size"
            );
        }
        for (std::size_t a = 0; a < face.size(); ++a)
        {
            int& k = pointOf[face[a]];
            if (k < 0)
            {
                k = int(points_.size());
                points_.push_back({face[a], 0.0, 0.0, 0.0});
                epsA.push_back(0.0);
            }
            points_[k].dA0 += wa[a];
            epsA[k] += wa[a]*set_.penaltyFactor*G/h;
        }
    }
    for (std::size_t k = 0; k < points_.size(); ++k)
    {
        // Area average of the adjacent faces' kappa G/h; a node on the
        // axis (zero ring area) takes its only face's value
        points_[k].eps = points_[k].dA0 > 0
            ? epsA[k]/points_[k].dA0 : 0.0;
        points_[k].eps0 = points_[k].eps;
    }
    for (std::size_t k = 0; k < points_.size(); ++k)
    {
        if (!(points_[k].dA0 > 0))
        {
            throw SolidError
            (
                SolidError::Kind::mesh, "rigid sphere contact: node "
              + std::to_string(points_[k].node) + " of set '" + faceSet_
              + "' has zero contact area"
            );
        }
    }
    if (lambda_.size() != points_.size())
    {
        lambda_.assign(points_.size(), 0.0);
        lambdaCommitted_ = lambda_;
    }
    ready_ = true;
}


solid::RigidSphereContact::Kinematics solid::RigidSphereContact::kinematics
(
    const Model& model,
    const Eigen::VectorXd& u,
    const Vec3& c,
    std::size_t q
) const
{
    const Mesh& mesh = model.mesh();
    const int dim = mesh.dim();
    const Point& pt = points_[q];
    Kinematics k;
    k.x = mesh.X[pt.node];
    for (int i = 0; i < dim; ++i) k.x(i) += u(pt.node*dim + i);
    const Vec3 d = k.x - c;
    k.dist = d.norm();
    k.n = k.dist > 0 ? Vec3(d/k.dist) : Vec3(-set_.direction);
    k.gap = k.dist - set_.radius;
    k.p = std::max(0.0, lambda_[q] - pt.eps*k.gap);
    return k;
}


void solid::RigidSphereContact::addForce
(
    const Model& model,
    const Eigen::VectorXd& u,
    double t,
    Eigen::VectorXd& f,
    Triplets* K
) const
{
    setup(model);
    const Mesh& mesh = model.mesh();
    const int dim = mesh.dim();
    const Vec3 c = centre(t);
    for (std::size_t q = 0; q < points_.size(); ++q)
    {
        const Kinematics k = kinematics(model, u, c, q);
        if (k.p <= 0) continue;
        const Point& pt = points_[q];
        for (int i = 0; i < dim; ++i)
        {
            f(pt.node*dim + i) += k.p*k.n(i)*pt.dA0;
        }
        if (!K) continue;
        const Mat3 nn = k.n*k.n.transpose();
        const Mat3 D =
            (pt.eps*nn - k.p/k.dist*(Mat3::Identity() - nn))*pt.dA0;
        for (int i = 0; i < dim; ++i)
            for (int j = 0; j < dim; ++j)
                K->emplace_back(pt.node*dim + i, pt.node*dim + j, D(i, j));
    }
}


bool solid::RigidSphereContact::augment
(
    const Model& model,
    const Eigen::VectorXd& u,
    double t
)
{
    setup(model);
    const Vec3 c = centre(t);
    double maxPen = 0;
    std::vector<double> p(points_.size());
    for (std::size_t q = 0; q < points_.size(); ++q)
    {
        const Kinematics k = kinematics(model, u, c, q);
        p[q] = k.p;
        if (k.p > 0) maxPen = std::max(maxPen, -k.gap);
    }
    // Keep the multipliers of the last solve when it is accepted, so that
    // report() is in equilibrium with the converged state
    if (maxPen <= set_.tolerance) return false;
    if (maxPen > 0.3*lastMaxPen_)
    {
        // Slow contraction: stiffen the penalty where it still penetrates
        ++nPenaltyRaises_;
        for (std::size_t q = 0; q < points_.size(); ++q)
        {
            const Kinematics k = kinematics(model, u, c, q);
            if (k.p > 0 && -k.gap > set_.tolerance)
            {
                points_[q].eps =
                    std::min(4*points_[q].eps, 4096*points_[q].eps0);
            }
        }
    }
    lastMaxPen_ = maxPen;
    lambda_ = p;
    return true;
}


void solid::RigidSphereContact::resetPenalties()
{
    for (Point& pt : points_) pt.eps = pt.eps0;
    lastMaxPen_ = HUGE_VAL;
}


void solid::RigidSphereContact::commit
(
    const Model& model,
    const Eigen::VectorXd&,
    double
)
{
    setup(model);
    lambdaCommitted_ = lambda_;
    resetPenalties();
}


void solid::RigidSphereContact::revert()
{
    lambda_ = lambdaCommitted_;
    resetPenalties();
}


std::vector<double> solid::RigidSphereContact::penalties
(
    const Model& model
) const
{
    setup(model);
    std::vector<double> e(points_.size());
    for (std::size_t q = 0; q < points_.size(); ++q) e[q] = points_[q].eps;
    return e;
}


void solid::RigidSphereContact::setMultipliers(const std::vector<double>& l)
{
    if (ready_ && l.size() != points_.size())
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "rigid sphere contact: "
          + std::to_string(l.size()) + " multipliers for "
          + std::to_string(points_.size()) + " contact points"
        );
    }
    lambda_ = l;
    lambdaCommitted_ = l;
}


solid::ContactReport solid::RigidSphereContact::report
(
    const Model& model,
    const Eigen::VectorXd& u,
    double t
) const
{
    setup(model);
    const Vec3 c = centre(t);
    const Vec3& e = set_.direction;
    ContactReport r;
    for (std::size_t q = 0; q < points_.size(); ++q)
    {
        const Kinematics k = kinematics(model, u, c, q);
        if (k.p <= 0) continue;
        r.nActive++;
        r.force += k.p*k.n.dot(e)*points_[q].dA0;
        const Vec3 d = k.x - c;
        Vec3 lateral = d - d.dot(e)*e;
        if (model.mesh().axisymmetric())
        {
            // The centre is on the axis: the ring radius is r itself
            lateral = Vec3(k.x(0), 0, 0);
        }
        r.contactRadius = std::max(r.contactRadius, lateral.norm());
        r.maxPenetration = std::max(r.maxPenetration, -k.gap);
    }
    return r;
}
