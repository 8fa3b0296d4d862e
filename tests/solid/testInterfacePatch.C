// solid::InterfacePatch: the interface measures over a patch of fixed size
// (issue 17 item 5). A known field on a small mesh: a uniform field gives
// its value; a linear profile along the interface the analytic mean of
// the window at the end, to the window's end facets (error <= g h^2/(4 L),
// falling as h^2); a field piecewise constant on 1 um pieces the same mean
// on meshes refined under the patch; the two sides and a boundary; 3D: a
// uniform field, and a bump whose disc mean converges with refinement
// (second order in the facet size). Fixed places (issue 17 item 4): the
// window around the interface's point nearest a given point, clamped to
// the curve; the same mean on every mesh for a field piecewise constant
// on coarse pieces; 3D: the disc around the nearest sub-cell centre.
// Bad sizes, regions and places are parameter errors.
#include "InterfacePatch.H"
#include "PointProbe.H"
#include "SolidError.H"

#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace solid;

namespace
{

const double um = 1e-6;

// r-z rectangle [1, 5] x [0, 10] um of nr x nz quads; elements with a
// centroid r < 3 um are region "inner" (1), the others "outer" (0): the
// interface is the line r = 3 um, 10 um long (nr even)
Mesh strip(int nr, int nz)
{
    Mesh m = Mesh::rectangle(nr, nz, 1*um, 5*um, 0, 10*um);
    m.regionNames = {"outer", "inner"};
    for (int e = 0; e < m.nElements(); ++e)
    {
        m.region[e] = PointProbe::centroid(m, e)(0) < 3*um ? 1 : 0;
    }
    return m;
}

// Element stresses from a function of the element's centroid and region
std::vector<ElementStress> field
(
    const Mesh& m,
    const std::function<ElementStress(const Vec3&, int)>& f
)
{
    std::vector<ElementStress> s(m.nElements());
    for (int e = 0; e < m.nElements(); ++e)
    {
        Vec3 c(Vec3::Zero());
        for (int k = 0; k < m.nen(); ++k) c += m.X[m.element(e)[k]];
        s[e] = f(c/m.nen(), m.region[e]);
    }
    return s;
}

InterfaceMeasures measure
(
    const InterfacePatch& ip,
    const std::vector<ElementStress>& s
)
{
    return ip.evaluate([&](int e) -> const ElementStress& { return s[e]; });
}

ElementStress pressure(double p)
{
    ElementStress s;
    s.p = p;
    s.sigma = -p*Mat3::Identity();
    return s;
}

} // namespace


TEST(InterfacePatch, uniformFieldGivesItsValue)
{
    const Mesh m = strip(4, 10);
    const InterfacePatch ip(m, 0, 1, 1*um);
    EXPECT_EQ(ip.facets().size(), 10u);
    EXPECT_EQ(ip.nChains(), 1u);
    // 8 band elements of 1 um each side... the two columns next to r = 3
    EXPECT_EQ(ip.band().size(), 20u);
    ElementStress u;
    u.p = 5;
    u.sigma << -7, 2, 0,
                2, -4, 0,
                0, 0, -4;
    const auto s = field(m, [&](const Vec3&, int) { return u; });
    const InterfaceMeasures r = measure(ip, s);
    const double vm = tensor::vonMises(u.sigma);
    // Normal (1, 0, 0): traction (-7, 2, 0), shear 2
    EXPECT_DOUBLE_EQ(InterfacePatch::shear(u.sigma, Vec3(1, 0, 0)), 2);
    EXPECT_NEAR(r.pPatch, 5, 1e-12);
    EXPECT_NEAR(r.vonMisesPatch, vm, 1e-12*vm);
    EXPECT_NEAR(r.shearPatch, 2, 1e-12);
    EXPECT_DOUBLE_EQ(r.pMax, 5);
    EXPECT_DOUBLE_EQ(r.vonMisesMax, vm);
    EXPECT_NEAR(r.shearMax, 2, 1e-12);
}


TEST(InterfacePatch, linearProfileGivesTheAnalyticMean)
{
    // p = 3 Pa + g z along the interface: the largest window is the top
    // one, [S - L, S], with the mean 3 + g (S - L/2)
    const double g = 1e6;   // [Pa/m]: 1 Pa per um
    const double S = 10*um;
    for (const double L : {1*um, 2*um})
    {
        const Mesh m = strip(4, 10);
        const InterfacePatch ip(m, 0, 1, L);
        const auto s = field(m, [&](const Vec3& c, int)
        {
            return pressure(3 + g*c(1));
        });
        const InterfaceMeasures r = measure(ip, s);
        // Whole facets under the window: exact
        EXPECT_NEAR(r.pPatch, 3 + g*(S - L/2), 1e-12) << L;
        EXPECT_NEAR(r.vonMisesPatch, 0, 1e-9);
        EXPECT_NEAR(r.vonMisesPatchAt(0), 3*um, 1e-15);
    }
    // A window of 1.5 um on facets of h = 1, 0.5, 0.25 um: the end facets
    // of the window carry their midpoint value, error <= g h^2/(4 L),
    // falling as h^2 (exact once L is a multiple of h)
    const double L = 1.5*um;
    const double exact = 3 + g*(S - L/2);
    double previous = -1;
    for (const int nz : {10, 20, 40})
    {
        const double h = S/nz;
        const Mesh m = strip(4, nz);
        const InterfacePatch ip(m, 0, 1, L);
        const auto s = field(m, [&](const Vec3& c, int)
        {
            return pressure(3 + g*c(1));
        });
        const double err = std::abs(measure(ip, s).pPatch - exact);
        EXPECT_LE(err, g*h*h/(4*L) + 1e-12) << nz;
        if (previous > 0)
        {
            EXPECT_LE(err, previous/3 + 1e-12) << nz;
        }
        previous = err;
    }
}


TEST(InterfacePatch, refiningUnderThePatchKeepsTheMean)
{
    // Values constant on 1 um pieces of z (random), the same field on
    // meshes of 1, 1/2, 1/3 and 1/4 um along the interface; a window of
    // 1.7 um (its ends inside pieces): the same largest mean and centre
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> d(0, 100);
    std::vector<double> piece(10), other(10);
    for (int i = 0; i < 10; ++i)
    {
        piece[i] = d(gen);
        other[i] = d(gen);
    }
    double reference = 0;
    double vmReference = 0;
    for (const int nz : {10, 20, 30, 40})
    {
        const Mesh m = strip(2, nz);
        const InterfacePatch ip(m, 0, 1, 1.7*um);
        const auto s = field(m, [&](const Vec3& c, int region)
        {
            const int i = std::min(9, int(c(1)/um));
            ElementStress e = pressure(region == 0 ? piece[i] : other[i]);
            e.sigma(1, 1) -= 2*piece[i];    // von Mises 2 piece[i]
            return e;
        });
        const InterfaceMeasures r = measure(ip, s);
        if (nz == 10)
        {
            reference = r.pPatch;
            vmReference = r.vonMisesPatch;
            // The brute-force answer: the best start over a fine sweep,
            // each side
            double best = 0;
            for (int k = 0; k <= 8300; ++k)
            {
                const double x0 = k*1e-3*um;
                for (const auto* v : {&piece, &other})
                {
                    double sum = 0;
                    for (int i = 0; i < 10; ++i)
                    {
                        const double a = std::max(x0, i*um);
                        const double b = std::min(x0 + 1.7*um, (i + 1)*um);
                        if (b > a) sum += (*v)[i]*(b - a);
                    }
                    best = std::max(best, sum/(1.7*um));
                }
            }
            EXPECT_NEAR(reference, best, 1e-9*best);
        }
        EXPECT_NEAR(r.pPatch, reference, 1e-12*reference) << nz;
        EXPECT_NEAR(r.vonMisesPatch, vmReference, 1e-12*vmReference) << nz;
    }
}


TEST(InterfacePatch, theLargerSideAndABoundary)
{
    const Mesh m = strip(4, 10);
    const InterfacePatch ip(m, 0, 1, 1*um);
    // The inner side twice the outer: the measure is the inner's
    const auto s = field(m, [&](const Vec3& c, int region)
    {
        ElementStress e = pressure((region == 1 ? 2 : 1)*(1 + c(1)/um));
        e.sigma(1, 1) -= 2*e.p;     // von Mises 2 p
        return e;
    });
    EXPECT_NEAR(measure(ip, s).pPatch, 2*(1 + 9.5), 1e-12);
    // The outer region's faces on r = 5 um: one side, 10 facets
    std::vector<char> right(m.nNodes(), 0);
    for (const int n : m.nodeSets.at("right")) right[n] = 1;
    const InterfacePatch wall(m, 0, right, 1*um);
    EXPECT_FALSE(wall.twoSided());
    EXPECT_EQ(wall.facets().size(), 10u);
    EXPECT_EQ(wall.band().size(), 10u);
    const InterfaceMeasures r = measure(wall, s);
    EXPECT_NEAR(r.pPatch, 1 + 9.5, 1e-12);
    EXPECT_NEAR(r.vonMisesPatchAt(0), 5*um, 1e-15);
    EXPECT_NEAR(r.vonMisesPatchAt(1), 9.5*um, 1e-15);
    // The inner region has no face on r = 5 um
    EXPECT_THROW(InterfacePatch(m, 1, right, 1*um), SolidError);
}


TEST(InterfacePatch, threeDimensionalDisc)
{
    // Box [0, 4] x [0, 4] x [0, 8] um, regions split at x = 2 um: the
    // interface is a 4 x 8 um plane. A disc of diameter L = 2 um; odd
    // refinements keep a facet centroid at the bump's centre
    double previous = -1;
    double previousErr = -1;
    for (const int k : {1, 3, 5})
    {
        Mesh m = Mesh::box(4*k, 4*k, 8*k, Vec3(0, 0, 0),
            Vec3(4*um, 4*um, 8*um));
        m.regionNames = {"a", "b"};
        for (int e = 0; e < m.nElements(); ++e)
        {
            m.region[e] = PointProbe::centroid(m, e)(0) < 2*um ? 1 : 0;
        }
        const InterfacePatch ip(m, 0, 1, 2*um);
        EXPECT_EQ(ip.facets().size(), std::size_t(32*k*k));
        const auto u = field(m, [](const Vec3&, int) { return pressure(4); });
        EXPECT_NEAR(measure(ip, u).pPatch, 4, 1e-12);
        // A bump 10 - |X - X0|^2/um^2 around a point of the plane: the
        // disc's mean 10 - R^2/2 (R = 1 um)
        const Vec3 X0(2*um, 2.5*um, 4.5*um);
        const auto b = field(m, [&](const Vec3& c, int)
        {
            const Vec3 on(2*um, c(1), c(2));
            return pressure(10 - (on - X0).squaredNorm()/(um*um));
        });
        const double mean = measure(ip, b).pPatch;
        const double err = std::abs(mean - 9.5);
        // Facet values at the centroids, the ball's area by sub-cells:
        // second order in the facet size h = 1/k um (measured 0.286,
        // 0.0237, 0.0081 for k = 1, 3, 5)
        EXPECT_LT(err, 0.3/(k*k)) << k;
        if (previousErr >= 0)
        {
            EXPECT_LT(err, previousErr) << k;
        }
        previousErr = err;
        previous = mean;
    }
    (void)previous;
}


TEST(InterfacePatch, fixedPlacesOnAStraightInterface)
{
    // p = 3 Pa + g z along the interface r = 3 um, z in [0, 10] um,
    // facets of 1 um, window L = 1 um; the inner side twice the outer
    const double g = 1e6;
    const Mesh m = strip(4, 10);
    InterfacePatch ip(m, 0, 1, 1*um);
    // On the interface, off it (nearest point (3, 4.3) um), below and
    // above its ends (the end windows)
    EXPECT_EQ(ip.addPlace(Vec3(3*um, 4.5*um, 0)), 0u);
    EXPECT_EQ(ip.addPlace(Vec3(0, 4.3*um, 0)), 1u);
    EXPECT_EQ(ip.addPlace(Vec3(3*um, -5*um, 0)), 2u);
    EXPECT_EQ(ip.addPlace(Vec3(8*um, 50*um, 0)), 3u);
    EXPECT_EQ(ip.nPlaces(), 4u);
    const auto s = field(m, [&](const Vec3& c, int region)
    {
        ElementStress e = pressure((region == 1 ? 2 : 1)*(3 + g*c(1)));
        e.sigma(1, 1) -= 2*e.p;     // von Mises 2 p
        return e;
    });
    const InterfaceMeasures r = measure(ip, s);
    ASSERT_EQ(r.pAt.size(), 4u);
    // The window's mean of the facets' midpoint values: 3 + g z at its
    // centre (whole facets or one of length L: exact for a linear field),
    // the inner side's (twice)
    const double centre[4] = {4.5, 4.3, 0.5, 9.5};
    for (int i = 0; i < 4; ++i)
    {
        EXPECT_NEAR(r.pAt[i], 2*(3 + centre[i]), 1e-12) << i;
        EXPECT_NEAR(r.vonMisesAt[i], 2*r.pAt[i], 1e-9) << i;
        EXPECT_NEAR(r.shearAt[i], 0, 1e-9) << i;
        EXPECT_NEAR(ip.placeCentre(i)(0), 3*um, 1e-15) << i;
        EXPECT_NEAR(ip.placeCentre(i)(1), centre[i]*um, 1e-15) << i;
        // never above the largest mean over places
        EXPECT_LE(r.pAt[i], r.pPatch + 1e-12) << i;
    }
    EXPECT_NEAR(r.pPatch, r.pAt[3], 1e-12);
    // A window longer than the curve: its whole mean
    InterfacePatch whole(m, 0, 1, 20*um);
    whole.addPlace(Vec3(3*um, 2*um, 0));
    EXPECT_NEAR(measure(whole, s).pAt[0], 2*(3 + 5), 1e-12);
}


TEST(InterfacePatch, aFixedPlaceKeepsItsMeanUnderRefinement)
{
    // Values constant on 1 um pieces of z (random); a window of 1.7 um
    // around z = 4.35 um (its ends inside pieces): the same mean on
    // meshes of 1, 1/2, 1/3 and 1/4 um, the integral of the pieces; a
    // linear profile: the window's mean within g h^2/(4 L)
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> d(0, 100);
    std::vector<double> piece(10);
    for (double& v : piece) v = d(gen);
    const double L = 1.7*um, z0 = 4.35*um;
    double exact = 0;
    for (int i = 0; i < 10; ++i)
    {
        const double a = std::max(z0 - L/2, i*um);
        const double b = std::min(z0 + L/2, (i + 1)*um);
        if (b > a) exact += piece[i]*(b - a)/L;
    }
    const double g = 1e6;
    for (const int nz : {10, 20, 30, 40})
    {
        const Mesh m = strip(2, nz);
        InterfacePatch ip(m, 0, 1, L);
        ip.addPlace(Vec3(2*um, z0, 0));
        const auto s = field(m, [&](const Vec3& c, int)
        {
            return pressure(piece[std::min(9, int(c(1)/um))]);
        });
        EXPECT_NEAR(measure(ip, s).pAt[0], exact, 1e-12*exact) << nz;
        const auto lin = field(m, [&](const Vec3& c, int)
        {
            return pressure(g*c(1));
        });
        const double h = 10*um/nz;
        const double err = std::abs(measure(ip, lin).pAt[0] - g*z0);
        // (the bound falls as h^2; the error itself with the window's
        // ends' positions in their facets: 0.0088 Pa at h = 1 um, 0.0176
        // Pa at 0.5 um)
        EXPECT_LE(err, g*h*h/(4*L) + 1e-12) << nz;
    }
}


TEST(InterfacePatch, aFixedPlaceIn3D)
{
    // The box of threeDimensionalDisc: the bump's disc mean 9.5 at its
    // centre X0, given by a point off the interface (nearest: X0 to
    // within the sub-cells' spacing h/6)
    double previousErr = -1;
    for (const int k : {1, 3, 5})
    {
        Mesh m = Mesh::box(4*k, 4*k, 8*k, Vec3(0, 0, 0),
            Vec3(4*um, 4*um, 8*um));
        m.regionNames = {"a", "b"};
        for (int e = 0; e < m.nElements(); ++e)
        {
            m.region[e] = PointProbe::centroid(m, e)(0) < 2*um ? 1 : 0;
        }
        InterfacePatch ip(m, 0, 1, 2*um);
        const Vec3 X0(2*um, 2.5*um, 4.5*um);
        ip.addPlace(X0 + Vec3(0.7*um, 0, 0));
        EXPECT_NEAR(ip.placeCentre(0)(0), 2*um, 1e-15);
        EXPECT_LE((ip.placeCentre(0) - X0).norm(), 1.0/(6*k)*um) << k;
        const auto u = field(m, [](const Vec3&, int) { return pressure(4); });
        EXPECT_NEAR(measure(ip, u).pAt[0], 4, 1e-12);
        const auto b = field(m, [&](const Vec3& c, int)
        {
            const Vec3 on(2*um, c(1), c(2));
            return pressure(10 - (on - X0).squaredNorm()/(um*um));
        });
        const double err = std::abs(measure(ip, b).pAt[0] - 9.5);
        EXPECT_LT(err, 0.3/(k*k)) << k;
        if (previousErr >= 0)
        {
            EXPECT_LT(err, previousErr) << k;
        }
        previousErr = err;
    }
}


TEST(InterfacePatch, badInputIsAParameterError)
{
    const Mesh m = strip(4, 10);
    const auto kind = [&](const std::function<void()>& f)
    {
        try
        {
            f();
        }
        catch (const SolidError& e)
        {
            return e.kind();
        }
        return SolidError::Kind::io;
    };
    EXPECT_EQ(kind([&] { InterfacePatch(m, 0, 1, 0); }),
        SolidError::Kind::parameter);
    EXPECT_EQ(kind([&] { InterfacePatch(m, 0, 1, -1e-6); }),
        SolidError::Kind::parameter);
    EXPECT_EQ(kind([&] { InterfacePatch(m, 0, 0, 1e-6); }),
        SolidError::Kind::parameter);
    EXPECT_EQ(kind([&] { InterfacePatch(m, 0, 2, 1e-6); }),
        SolidError::Kind::parameter);
    // Regions without a shared face
    Mesh three = strip(6, 10);
    three.regionNames = {"outer", "inner", "middle"};
    for (int e = 0; e < three.nElements(); ++e)
    {
        const double r = PointProbe::centroid(three, e)(0);
        three.region[e] = r < 2.4*um ? 1 : (r < 3.7*um ? 2 : 0);
    }
    EXPECT_EQ(kind([&] { InterfacePatch(three, 0, 1, 1e-6); }),
        SolidError::Kind::parameter);
    // Places: a point not finite, an index beyond them, values of the
    // wrong size
    InterfacePatch ip(m, 0, 1, 1e-6);
    EXPECT_EQ(kind([&] { ip.addPlace(Vec3(NAN, 0, 0)); }),
        SolidError::Kind::parameter);
    ip.addPlace(Vec3(3e-6, 1e-6, 0));
    EXPECT_EQ(kind([&] { ip.placeCentre(1); }),
        SolidError::Kind::parameter);
    EXPECT_EQ(kind([&] { ip.meanAt(std::vector<double>(10, 0), 1); }),
        SolidError::Kind::parameter);
    EXPECT_EQ(kind([&] { ip.meanAt(std::vector<double>(3, 0), 0); }),
        SolidError::Kind::parameter);
}
