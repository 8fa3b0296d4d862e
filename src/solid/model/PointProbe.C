#include "PointProbe.H"
#include "SolidError.H"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace
{

//- How far outside [-1, 1] a parametric coordinate may lie and still count
//  as inside: a point on an element edge or face comes back from the
//  Newton iteration a few round-offs outside
const double insideTol = 1e-9;

//- The first dim coordinates of X (a fixed-size head of a dynamic length
//  trips GCC's array-bounds analysis)
Eigen::VectorXd head(const solid::Vec3& X, int dim)
{
    Eigen::VectorXd h(dim);
    for (int i = 0; i < dim; ++i) h(i) = X(i);
    return h;
}

std::string pointName(const solid::Vec3& X, int dim)
{
    std::ostringstream os;
    os.precision(10);
    os  << '(' << X(0) << ' ' << X(1);
    if (dim == 3) os << ' ' << X(2);
    os  << ") m";
    return os.str();
}

} // namespace


bool solid::PointProbe::inverseMap
(
    const Mesh& m,
    int e,
    const Vec3& X,
    Vec3& xi
)
{
    const int dim = m.dim();
    const int* en = m.element(e);
    xi.setZero();
    Eigen::VectorXd N;
    Eigen::MatrixXd dN;
    // Newton converges in a few iterations inside a reasonably shaped
    // element; points far outside may not converge at all (then they are
    // not in this element)
    for (int it = 0; it < 30; ++it)
    {
        shapeAt(m.type, xi, N, dN);
        Eigen::VectorXd r = head(X, dim);
        Eigen::MatrixXd J = Eigen::MatrixXd::Zero(dim, dim);
        for (int a = 0; a < m.nen(); ++a)
        {
            const Eigen::VectorXd Xa = head(m.X[en[a]], dim);
            r -= N(a)*Xa;
            J += Xa*dN.row(a);
        }
        const double det = J.determinant();
        if (!(std::abs(det) > 0)) return false;
        const Eigen::VectorXd d = J.partialPivLu().solve(r);
        for (int i = 0; i < dim; ++i) xi(i) += d(i);
        if (!(xi.cwiseAbs().maxCoeff() < 10)) return false;
        if (d.cwiseAbs().maxCoeff() < 1e-13) return true;
    }
    return false;
}


int solid::PointProbe::locate
(
    const Mesh& mesh,
    const Vec3& X,
    int region,
    Vec3& xi,
    std::set<int>& regionsFound
)
{
    const int nen = mesh.nen();
    double bestDepth = 1e300;
    int best = -1;
    for (int e = 0; e < mesh.nElements(); ++e)
    {
        if (region >= 0 && mesh.region[e] != region) continue;
        const int* en = mesh.element(e);
        Vec3 lo = mesh.X[en[0]], hi = mesh.X[en[0]];
        for (int a = 1; a < nen; ++a)
        {
            lo = lo.cwiseMin(mesh.X[en[a]]);
            hi = hi.cwiseMax(mesh.X[en[a]]);
        }
        const double tol = insideTol*(hi - lo).maxCoeff();
        // r-z: the third coordinates are all 0
        if
        (
            ((X - lo).array() < -tol).any()
         || ((hi - X).array() < -tol).any()
        )
        {
            continue;
        }
        Vec3 xie;
        if (!inverseMap(mesh, e, X, xie)) continue;
        const double depth = xie.cwiseAbs().maxCoeff();
        if (depth > 1 + insideTol) continue;
        regionsFound.insert(mesh.region[e]);
        if (depth < bestDepth)
        {
            bestDepth = depth;
            best = e;
            xi = xie;
        }
    }
    return best;
}


solid::PointProbe::PointProbe(const Mesh& mesh, const Vec3& X, int region)
:
    X_(X),
    region_(region),
    xi_(Vec3::Zero()),
    dim_(mesh.dim())
{
    if (region >= int(mesh.regionNames.size()))
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "region id " + std::to_string(region) + " not in the mesh"
        );
    }
    if (mesh.axisymmetric()) X_(2) = 0;
    const int nen = mesh.nen();
    std::set<int> regionsFound;
    element_ = locate(mesh, X_, region, xi_, regionsFound);
    if (element_ < 0)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "point " + pointName(X_, dim_) + " lies in no element"
          + (
                region >= 0
              ? " of region '" + mesh.regionNames[region] + "'"
              : std::string(" of the mesh")
            )
          + " (reference configuration)"
        );
    }
    if (regionsFound.size() > 1)
    {
        std::string names;
        for (const int r : regionsFound)
        {
            names += (names.empty() ? "'" : ", '") + mesh.regionNames[r] + "'";
        }
        throw SolidError
        (
            SolidError::Kind::parameter,
            "point " + pointName(X_, dim_) + " lies on the "
            "interface of regions " + names + ": name the region of the "
            "probe (the side whose fields it reports)"
        );
    }
    region_ = mesh.region[element_];
    nodes_.assign(mesh.element(element_), mesh.element(element_) + nen);
    Eigen::MatrixXd dN;
    shapeAt(mesh.type, xi_, N_, dN);

    // Patch: the containing element and the elements of its region that
    // share a node with it
    const int* host = mesh.element(element_);
    for (int e = 0; e < mesh.nElements(); ++e)
    {
        if (mesh.region[e] != region_) continue;
        const int* en = mesh.element(e);
        bool touches = false;
        for (int a = 0; a < nen && !touches; ++a)
        {
            touches = std::find(host, host + nen, en[a]) != host + nen;
        }
        if (touches) patch_.push_back(e);
    }

    // Linear least-squares fit over the centroids, in the directions they
    // span (offsets from X scaled by the patch size); the value at X is the
    // constant coefficient, a fixed linear combination of the samples
    const int n = int(patch_.size());
    Eigen::MatrixXd D(n, dim_);
    for (int i = 0; i < n; ++i)
    {
        D.row(i) = head(centroid(mesh, patch_[i]) - X_, dim_).transpose();
    }
    const double h = D.rowwise().norm().maxCoeff();
    if (h > 0) D /= h;
    const Eigen::MatrixXd C = D.rowwise() - D.colwise().mean();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeFullV);
    const Eigen::VectorXd& s = svd.singularValues();
    int k = 0;
    while (k < s.size() && s(k) > 1e-8*std::max(s(0), 1e-300)) ++k;
    Eigen::MatrixXd A(n, 1 + k);
    A.col(0).setOnes();
    A.rightCols(k) = D*svd.matrixV().leftCols(k);
    const Eigen::VectorXd e0 = Eigen::VectorXd::Unit(1 + k, 0);
    const Eigen::VectorXd w = A*(A.transpose()*A).ldlt().solve(e0);
    weights_.assign(w.data(), w.data() + n);
}


solid::Vec3 solid::PointProbe::centroid(const Mesh& mesh, int e)
{
    ElementGeometry g;
    g.build(mesh, e);
    const int* en = mesh.element(e);
    Vec3 c(Vec3::Zero());
    for (std::size_t q = 0; q < g.w.size(); ++q)
    {
        for (int a = 0; a < mesh.nen(); ++a)
        {
            c += g.w[q]*g.N[q](a)*mesh.X[en[a]];
        }
    }
    return c/g.V;
}


solid::Vec3 solid::PointProbe::interpolate(const Eigen::VectorXd& nodal) const
{
    Vec3 v(Vec3::Zero());
    for (int a = 0; a < int(N_.size()); ++a)
    {
        for (int i = 0; i < dim_; ++i) v(i) += N_(a)*nodal(dim_*nodes_[a] + i);
    }
    return v;
}


solid::ProbeValues solid::PointProbe::evaluate(Model& model) const
{
    std::vector<ProbeValues> samples(patch_.size());
    for (std::size_t i = 0; i < patch_.size(); ++i)
    {
        samples[i] = sample(model.evaluateElement(patch_[i], 0));
    }
    return recover(samples);
}


solid::ProbeValues solid::PointProbe::sample(const ElementOutput& o)
{
    ProbeValues s;
    s.p = o.p;
    s.sigma = o.sigma;
    s.F = o.F;
    s.theta = o.theta;
    s.temperatureRise = o.temperatureRise;
    return s;
}


solid::ProbeValues solid::PointProbe::recover
(
    const std::vector<ProbeValues>& samples
) const
{
    if (samples.size() != patch_.size())
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "probe recovery: "
          + std::to_string(samples.size()) + " samples for a patch of "
          + std::to_string(patch_.size()) + " elements"
        );
    }
    ProbeValues v;
    v.sigma.setZero();
    v.F.setZero();
    v.theta = 0;
    const std::vector<double>& wc = continuousWeights();
    for (std::size_t i = 0; i < patch_.size(); ++i)
    {
        const ProbeValues& o = samples[i];
        const double w = weights_[i];
        v.p += wc[i]*o.p;
        v.sigma += w*o.sigma;
        v.F += w*o.F;
        v.theta += wc[i]*o.theta;
        v.temperatureRise += w*o.temperatureRise;
    }
    return v;
}


solid::PointProbe::PointProbe
(
    const Mesh& mesh,
    const Vec3& X,
    int region,
    double radius,
    int subCells
)
:
    PointProbe(mesh, X, region)
{
    if (!(std::isfinite(radius) && radius >= 0))
    {
        std::ostringstream os;
        os.precision(10);
        os  << "probe at " << pointName(X_, dim_) << ": radius " << radius
            << " m: a ball probe's radius must be finite and >= 0 (0: the"
            << " point)";
        throw SolidError(SolidError::Kind::parameter, os.str());
    }
    if (radius == 0) return;
    radius_ = radius;
    const int n = subCells > 0 ? subCells : (dim_ == 2 ? 16 : 8);
    const bool axi = mesh.axisymmetric();
    const int nen = mesh.nen();
    const double R2 = radius*radius;
    const double cell = std::pow(2.0/n, dim_);
    std::vector<int> patch;
    std::vector<double> volumes;
    Eigen::VectorXd N;
    Eigen::MatrixXd dN;
    for (int e = 0; e < mesh.nElements(); ++e)
    {
        if (mesh.region[e] != region_) continue;
        const int* en = mesh.element(e);
        // Nearest and farthest node distances from X: an element whose
        // box misses the ball is out, one whose nodes all lie inside is in
        // whole (a quad4 or hex8 lies in its nodes' convex hull)
        Vec3 lo = mesh.X[en[0]], hi = mesh.X[en[0]];
        bool allIn = true;
        for (int a = 0; a < nen; ++a)
        {
            lo = lo.cwiseMin(mesh.X[en[a]]);
            hi = hi.cwiseMax(mesh.X[en[a]]);
            allIn = allIn && (mesh.X[en[a]] - X_).squaredNorm() <= R2;
        }
        const Vec3 nearest = X_.cwiseMax(lo).cwiseMin(hi);
        if ((nearest - X_).squaredNorm() > R2) continue;
        double v = 0;
        if (allIn)
        {
            ElementGeometry g;
            g.build(mesh, e);
            v = g.V;
        }
        else
        {
            // Midpoint rule on n^dim sub-cells of [-1, 1]^dim
            const int nz = dim_ == 3 ? n : 1;
            for (int k = 0; k < nz; ++k)
            for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
            {
                const Vec3 xi
                (
                    -1 + (2*i + 1.0)/n,
                    -1 + (2*j + 1.0)/n,
                    dim_ == 3 ? -1 + (2*k + 1.0)/n : 0.0
                );
                shapeAt(mesh.type, xi, N, dN);
                Vec3 Xq(Vec3::Zero());
                Eigen::MatrixXd J = Eigen::MatrixXd::Zero(dim_, dim_);
                for (int a = 0; a < nen; ++a)
                {
                    Xq += N(a)*mesh.X[en[a]];
                    J += head(mesh.X[en[a]], dim_)*dN.row(a);
                }
                if ((Xq - X_).squaredNorm() > R2) continue;
                v += std::abs(J.determinant())*cell
                    *(axi ? 2*M_PI*Xq(0) : 1.0);
            }
        }
        if (v > 0)
        {
            patch.push_back(e);
            volumes.push_back(v);
        }
    }
    // X lies in an element of the region: the ball meets it
    for (const double v : volumes) volume_ += v;
    if (!(volume_ > 0))
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "probe at " + pointName(X_, dim_) + ": its ball meets no volume"
            " of region '" + mesh.regionNames[region_] + "'"
        );
    }
    patch_ = patch;
    weights_.resize(volumes.size());
    for (std::size_t i = 0; i < volumes.size(); ++i)
    {
        weights_[i] = volumes[i]/volume_;
    }
}


solid::PointProbe::PointProbe
(
    const Mesh& mesh,
    const Vec3& X,
    int region,
    AcrossRegion across
)
:
    PointProbe(mesh, X, region)
{
    const int nRegions = int(mesh.regionNames.size());
    if (region < 0 || across.region < 0 || across.region >= nRegions)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "interface probe at " + pointName(X_, dim_) + ": "
          + (
                region < 0
              ? std::string("its region must be named")
              : "region id " + std::to_string(across.region)
              + " across the interface not in the mesh"
            )
        );
    }
    if (across.region == region_)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "interface probe at " + pointName(X_, dim_) + ": region '"
          + mesh.regionNames[region_] + "' across itself; name the other "
            "region of the interface"
        );
    }
    Vec3 xi;
    std::set<int> found;
    const int b = locate(mesh, X_, across.region, xi, found);
    if (b < 0)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "interface probe at " + pointName(X_, dim_) + ": the point "
            "lies in no element of region '"
          + mesh.regionNames[across.region] + "' (reference configuration):"
            " it is not on the interface of regions '"
          + mesh.regionNames[region_] + "' and '"
          + mesh.regionNames[across.region] + "'"
        );
    }
    across_ = across.region;
    acrossElement_ = b;

    // Linear between the two hosts' centroids at X's projection on their
    // segment, clipped to it: convex weights
    const Vec3 ca = centroid(mesh, element_);
    const Vec3 cb = centroid(mesh, b);
    const Vec3 d = cb - ca;
    const double s =
        std::min(1.0, std::max(0.0, (X_ - ca).dot(d)/d.squaredNorm()));

    // The patch: the one-sided one, then the other side's host (another
    // region's element, so not in it)
    patch_.push_back(b);
    weights_.push_back(0);
    continuousWeights_.assign(patch_.size(), 0);
    const std::size_t host =
        std::find(patch_.begin(), patch_.end(), element_) - patch_.begin();
    continuousWeights_[host] = 1 - s;
    continuousWeights_.back() = s;
}
