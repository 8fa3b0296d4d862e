// solid::PointProbe: a probe at a fixed reference point. Location by the
// inverse isoparametric map on distorted r-z quads and hexahedra, shape-
// function interpolation of nodal fields, and the patch recovery of
// element quantities: exact for fields linear in X, also at a region
// interface and on the boundary; a linear displacement gives the exact
// deformation gradient at any point. A point outside is a clear error.
#include "PointProbe.H"
#include "SolidError.H"
#include "SolidTestUtils.H"

#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace solid;

namespace
{

const double um = 1e-6;

// r-z rectangle [1, 7] x [0, 5] um or box [0, 4]^3 um, interior nodes
// moved randomly by up to 0.25 of the element size; the elements whose
// reference centroid has x < 3.2 um form region "inner", the others
// "outer" (an interface that zigzags with the distortion)
Mesh distorted(bool axi)
{
    Mesh m = axi
        ? Mesh::rectangle(6, 5, 1*um, 7*um, 0, 5*um)
        : Mesh::box(4, 4, 4, Vec3(0, 0, 0), Vec3(4*um, 4*um, 4*um));
    solidTest::distortInterior(m, um, 0.25, axi ? 3 : 4);
    m.regionNames = {"outer", "inner"};
    for (int e = 0; e < m.nElements(); ++e)
    {
        m.region[e] = PointProbe::centroid(m, e)(0) < 3.2*um ? 1 : 0;
    }
    return m;
}

// The reference point of parametric coordinates xi in element e
Vec3 pointAt(const Mesh& m, int e, const Vec3& xi)
{
    Eigen::VectorXd N;
    Eigen::MatrixXd dN;
    shapeAt(m.type, xi, N, dN);
    Vec3 X(Vec3::Zero());
    for (int a = 0; a < m.nen(); ++a) X += N(a)*m.X[m.element(e)[a]];
    return X;
}

// Element average of the linear field f(X) = 2 + g.X over the reference
// volume, with the weights of the element kernel (r-z: ring 2 pi r)
const Vec3 g(3e5, -7e5, 2e5);
double f(const Vec3& X) { return 2 + g.dot(X); }
double average(const Mesh& m, int e)
{
    ElementGeometry geo;
    geo.build(m, e);
    double s = 0;
    for (std::size_t q = 0; q < geo.w.size(); ++q)
    {
        Vec3 Xq(Vec3::Zero());
        for (int a = 0; a < m.nen(); ++a)
        {
            Xq += geo.N[q](a)*m.X[m.element(e)[a]];
        }
        s += geo.w[q]*f(Xq);
    }
    return s/geo.V;
}

double recovered(const Mesh& m, const PointProbe& p)
{
    double s = 0;
    for (std::size_t i = 0; i < p.patch().size(); ++i)
    {
        s += p.weights()[i]*average(m, p.patch()[i]);
    }
    return s;
}

void locateAndRecover(bool axi)
{
    const Mesh m = distorted(axi);
    const int dim = m.dim();
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-0.95, 0.95);
    std::uniform_int_distribution<int> pick(0, m.nElements() - 1);
    for (int k = 0; k < 40; ++k)
    {
        const int e = pick(gen);
        Vec3 xi(u(gen), u(gen), axi ? 0 : u(gen));
        const Vec3 X = pointAt(m, e, xi);
        const PointProbe p(m, X, -1);
        ASSERT_EQ(p.element(), e) << "point " << X.transpose();
        EXPECT_NEAR((p.xi() - xi).head(dim).norm(), 0, 1e-12);
        EXPECT_EQ(p.region(), m.region[e]);
        EXPECT_NEAR(recovered(m, p), f(X), 1e-12*std::abs(f(X)));
        for (const int pe : p.patch()) EXPECT_EQ(m.region[pe], p.region());
    }
}

// A point of the region interface: a node shared by both regions
int interfaceNode(const Mesh& m)
{
    std::vector<int> seen(m.nNodes(), 0);
    for (int e = 0; e < m.nElements(); ++e)
    {
        for (int a = 0; a < m.nen(); ++a)
        {
            seen[m.element(e)[a]] |= 1 << m.region[e];
        }
    }
    for (int n = 0; n < m.nNodes(); ++n)
    {
        if (seen[n] == 3) return n;
    }
    return -1;
}

void interfaceSides(bool axi)
{
    const Mesh m = distorted(axi);
    const int n = interfaceNode(m);
    ASSERT_GE(n, 0);
    const Vec3 X = m.X[n];
    for (int side = 0; side < 2; ++side)
    {
        const PointProbe p(m, X, side);
        EXPECT_EQ(p.region(), side);
        // One-sided fit: exact for the linear field all the same
        EXPECT_NEAR(recovered(m, p), f(X), 1e-12*std::abs(f(X)));
    }
    try
    {
        const PointProbe p(m, X, -1);
        ADD_FAILURE() << "a point on the interface without a side";
    }
    catch (const SolidError& err)
    {
        EXPECT_EQ(err.kind(), SolidError::Kind::parameter);
        EXPECT_NE(std::string(err.what()).find("interface of regions"),
            std::string::npos) << err.what();
    }
}

void outside(bool axi)
{
    const Mesh m = distorted(axi);
    // Beyond the outer boundary, and in region "outer" asked for "inner"
    const Vec3 far(7.5*um, 2*um, axi ? 0 : 2*um);
    const Vec3 X = PointProbe::centroid(m, m.nElements() - 1);
    ASSERT_EQ(m.region[m.nElements() - 1], 0);
    for (const auto& c : {std::make_pair(far, -1), std::make_pair(X, 1)})
    {
        try
        {
            const PointProbe p(m, c.first, c.second);
            ADD_FAILURE() << "no error for " << c.first.transpose();
        }
        catch (const SolidError& err)
        {
            EXPECT_EQ(err.kind(), SolidError::Kind::parameter);
            const std::string w(err.what());
            EXPECT_NE(w.find("lies in no element"), std::string::npos) << w;
            if (c.second == 1)
            {
                EXPECT_NE(w.find("region 'inner'"), std::string::npos) << w;
            }
        }
    }
}

// A linear displacement u = H X (r-z: u_r = a r so that the hoop stretch
// 1 + u_r/r is uniform too) gives F = I + H at any point, on either side
// of the interface and next to the boundary
void linearDisplacement(bool axi)
{
    const Mesh m = distorted(axi);
    Model model(m);
    model.setMaterial("outer", solidTest::material(100, 1e-9));
    model.setMaterial("inner", solidTest::material(800, 1e-9));
    model.initialise();
    Mat3 H;
    if (axi) H << 0.02, 0, 0,  -0.03, -0.05, 0,  0, 0, 0.02;
    else H << 0.02, 0.01, -0.004,  -0.03, -0.05, 0.007,  0.003, 0.006, 0.01;
    const int dim = m.dim();
    for (int a = 0; a < m.nNodes(); ++a)
    {
        const Vec3 ua = H*m.X[a];
        for (int i = 0; i < dim; ++i) model.u(dim*a + i) = ua(i);
    }
    const Mat3 F = Mat3::Identity() + H;
    const int axial = dim - 1;
    const Vec3 onInterface = m.X[interfaceNode(m)];
    const std::vector<std::pair<Vec3, int>> cases =
    {
        {onInterface, 0},
        {onInterface, 1},
        {axi ? Vec3(6.99*um, 4.2*um, 0) : Vec3(3.99*um, 1.3*um, 2.7*um), -1},
        {axi ? Vec3(2.3*um, 0.4*um, 0) : Vec3(0.7*um, 3.1*um, 0.2*um), -1}
    };
    for (const auto& c : cases)
    {
        const Vec3& X = c.first;
        const PointProbe p(m, X, c.second);
        const ProbeValues v = p.evaluate(model);
        // Round-off only: the element gradients difference displacements
        // of 1e-8 m over 1e-6 m, and at a boundary edge the fit
        // extrapolates (weights of a few units)
        const double tol = 1e-11;
        EXPECT_NEAR((v.F - F).norm(), 0, tol) << X.transpose();
        EXPECT_NEAR(v.theta, F.determinant(), tol);
        EXPECT_NEAR
        (
            std::log(v.F.col(axial).norm()),
            std::log(F.col(axial).norm()),
            tol
        );
        EXPECT_NEAR((p.interpolate(model.u) - H*X).norm(), 0, 1e-18);
    }
}

} // namespace


TEST(PointProbe, LocatesAndRecoversLinearFieldsOnDistortedQuads)
{
    locateAndRecover(true);
}


TEST(PointProbe, LocatesAndRecoversLinearFieldsOnDistortedHexes)
{
    locateAndRecover(false);
}


TEST(PointProbe, InterfacePointNeedsASideAndIsExactOnEach)
{
    interfaceSides(true);
    interfaceSides(false);
}


TEST(PointProbe, PointOutsideTheRegionIsAnError)
{
    outside(true);
    outside(false);
}


TEST(PointProbe, LinearDisplacementGivesTheExactStrainAnywhere)
{
    linearDisplacement(true);
    linearDisplacement(false);
}


TEST(PointProbe, InterpolatesLinearNodalFields)
{
    for (const bool axi : {true, false})
    {
        const Mesh m = distorted(axi);
        const int dim = m.dim();
        Eigen::VectorXd v(m.nNodes()*dim);
        for (int a = 0; a < m.nNodes(); ++a)
        {
            for (int i = 0; i < dim; ++i) v(dim*a + i) = (i + 1)*f(m.X[a]);
        }
        const Vec3 X = pointAt(m, 7, Vec3(0.3, -0.6, axi ? 0 : 0.8));
        const PointProbe p(m, X, -1);
        const Vec3 w = p.interpolate(v);
        for (int i = 0; i < dim; ++i)
        {
            EXPECT_NEAR(w(i), (i + 1)*f(X), 1e-12*std::abs(f(X)));
        }
    }
}
