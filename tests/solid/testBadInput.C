// Bad input and failures during a solve: clear messages naming the
// element/region/entry, step cutting, no NaN left in the state.
#include "StaticSolver.H"
#include "Loads.H"
#include "MieGruneisenVolumetric.H"
#include "SolidError.H"
#include "SolidTestUtils.H"

#include <gtest/gtest.h>
#include <cstdio>

using namespace solid;

namespace
{

std::string messageOf(const std::function<void()>& f, SolidError::Kind k)
{
    try
    {
        f();
    }
    catch (const SolidError& e)
    {
        EXPECT_EQ(int(e.kind()), int(k)) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "no SolidError thrown";
    return "";
}

bool has(const std::string& s, const std::string& part)
{
    return s.find(part) != std::string::npos;
}

} // namespace


TEST(SolidBadInput, InvertedAndDegenerateReferenceElements)
{
    Mesh m = Mesh::rectangle(2, 2, 0, 1, 0, 1);
    std::swap(m.conn[4*3 + 1], m.conn[4*3 + 3]);    // element 3 inverted
    std::string msg = messageOf([&] { Model model(m); },
                                SolidError::Kind::mesh);
    EXPECT_TRUE(has(msg, "element 3")) << msg;
    EXPECT_TRUE(has(msg, "region 'solid'")) << msg;

    Mesh h = Mesh::box(1, 1, 1, Vec3(0, 0, 0), Vec3(1, 1, 1));
    h.X[h.conn[6]] = h.X[h.conn[0]];                // collapse a corner
    msg = messageOf([&] { Model model(h); }, SolidError::Kind::mesh);
    EXPECT_TRUE(has(msg, "element 0")) << msg;

    Mesh r = Mesh::rectangle(1, 1, -1, 1, 0, 1);
    msg = messageOf([&] { Model model(r); }, SolidError::Kind::mesh);
    EXPECT_TRUE(has(msg, "r < 0")) << msg;
}


TEST(SolidBadInput, RegionWithoutMaterialAndUnknownNames)
{
    Mesh m = Mesh::rectangle(2, 2, 0, 1, 0, 1);
    m.regionNames.push_back("nucleus");
    m.region[0] = 1;
    Model model(m);
    model.setMaterial("solid", solidTest::material(1, 1e-3));
    std::string msg = messageOf([&] { model.initialise(); },
                                SolidError::Kind::parameter);
    EXPECT_TRUE(has(msg, "region 'nucleus' (1 elements) has no material"))
        << msg;
    msg = messageOf([&] { model.setMaterial("membrane", nullptr); },
                    SolidError::Kind::mesh);
    EXPECT_TRUE(has(msg, "no region 'membrane'; regions: solid nucleus"))
        << msg;
    msg = messageOf([&] { model.fix("bottm", 1); }, SolidError::Kind::mesh);
    EXPECT_TRUE(has(msg, "bottom")) << msg;
    msg = messageOf([&] { model.fix("bottom", 2); },
                    SolidError::Kind::parameter);
    EXPECT_TRUE(has(msg, "component 2")) << msg;
}


namespace
{

std::unique_ptr<Model> compressionModel(double depth)
{
    const double L = 1e-5;
    Mesh m = Mesh::box(2, 2, 2, Vec3(0, 0, 0), Vec3(L, L, L));
    std::unique_ptr<Model> model(new Model(m));
    model->setMaterial("solid", solidTest::material(100, 1e-2));
    model->fix("xmin", 0);
    model->fix("ymin", 1);
    model->fix("zmin", 2);
    model->fix("zmax", 2, [=](double t) { return -t*depth*L; });
    model->initialise();
    return model;
}

} // namespace


TEST(SolidBadInput, StepCuttingRecoversAndMatchesSmallSteps)
{
    // Compression to 45 % in one step with at most 4 iterations: the
    // driver must cut the step and still reach the same solution
    auto ref = compressionModel(0.45);
    StaticSolver fine(*ref);
    for (int i = 0; i < 20; ++i) fine.step(0.05);

    auto model = compressionModel(0.45);
    NewtonSettings s;
    s.maxIterations = 4;
    StaticSolver coarse(*model, s);
    const StepReport rep = coarse.step(1.0);
    EXPECT_GT(rep.cuts, 0);
    EXPECT_NEAR(model->time, 1.0, 1e-12);
    EXPECT_LT((model->u - ref->u).norm(), 1e-8*ref->u.norm());
}


TEST(SolidBadInput, InversionDuringSolveGivesClearErrorAndCleanState)
{
    // Pushing the top below the bottom cannot succeed at any step size
    auto model = compressionModel(1.2);
    NewtonSettings s;
    s.maxCuts = 3;
    StaticSolver solver(*model, s);
    solver.step(0.5);               // 60 % compression: fine
    const std::string msg = messageOf([&] { solver.step(0.5); },
                                      SolidError::Kind::notConverged);
    EXPECT_TRUE(has(msg, "after 3 step cuts")) << msg;
    EXPECT_TRUE(has(msg, "inverted during the solve")) << msg;
    // The model stays at the last converged sub-step: finite, consistent
    // with its time (the top displacement is the prescribed one)
    EXPECT_TRUE(model->u.allFinite());
    EXPECT_GE(model->time, 0.5);
    EXPECT_LT(model->time, 1.0);
    // the time as the message prints it (%.9g: a short step is not
    // rounded to 0.000000)
    char from[64];
    std::snprintf(from, sizeof(from), "from t = %.9g s", model->time);
    EXPECT_TRUE(has(msg, from)) << msg;
    const int top = model->mesh().nodeSet("zmax")[0];
    EXPECT_NEAR(model->u(3*top + 2), -model->time*1.2e-5, 1e-20);
}


TEST(SolidBadInput, InvertedElementMessageNamesElement)
{
    auto model = compressionModel(0.1);
    Eigen::VectorXd x = model->u;
    // Flip one top node through the bottom
    const int n = model->mesh().element(0)[4];
    x(3*n + 2) = -2e-5;
    Assembly a;
    const std::string msg = messageOf
    (
        [&] { model->assemble(x, model->pressure, 0, 0, false, a); },
        SolidError::Kind::invertedElement
    );
    EXPECT_TRUE(has(msg, "element 0 (region 'solid') inverted")) << msg;
    EXPECT_TRUE(has(msg, "J = -")) << msg;
}


TEST(SolidBadInput, FoldedCornerWithPositiveGaussPointsIsInverted)
{
    // One hexahedron, its corner node 4 (0, 0, L) moved to t (L, L, -L)
    // + (0, 0, L): past the plane of its three neighbours for t > 1/3,
    // while the eight Gauss points keep J > 0 up to t = 0.5 (at t = 0.4
    // the smallest Gauss J is 0.25 and the corner's -0.2 of the cube's)
    const double L = 1e-6;
    Mesh m = Mesh::box(1, 1, 1, Vec3(0, 0, 0), Vec3(L, L, L));
    Model model(m);
    model.setMaterial("solid", solidTest::material(100, 1e-2));
    model.initialise();
    model.setCornerCheck(true);     // as ExplicitSolver sets it
    const int n = model.mesh().element(0)[4];
    ASSERT_NEAR(model.mesh().X[n](2), L, 1e-18);
    Assembly a;
    for (const double t : {0.3, 0.4})
    {
        Eigen::VectorXd x = model.u;
        x(3*n) = t*L;
        x(3*n + 1) = t*L;
        x(3*n + 2) = -t*L;
        if (t < 1.0/3)
        {
            // Distorted, not folded: assembles
            EXPECT_NO_THROW
            (
                model.assemble(x, model.pressure, 0, 0, false, a)
            );
            continue;
        }
        const std::string msg = messageOf
        (
            [&] { model.assemble(x, model.pressure, 0, 0, false, a); },
            SolidError::Kind::invertedElement
        );
        EXPECT_TRUE(has(msg, "element 0 (region 'solid') inverted")) << msg;
        EXPECT_TRUE(has(msg, "corner at node " + std::to_string(n)))
            << msg;
        EXPECT_TRUE(has(msg, "every Gauss point has J > 0")) << msg;
        // Without the corner check (the static driver) only the Gauss
        // points are tested
        model.setCornerCheck(false);
        EXPECT_NO_THROW(model.assemble(x, model.pressure, 0, 0, false, a));
        model.setCornerCheck(true);
    }
}


TEST(SolidBadInput, MieGruneisenOutsideDomain)
{
    eos::MieGruneisen::Parameters w;
    MieGruneisenVolumetric mg(w, 0.06, 1.2, "material 'nucleus'");
    std::vector<double> h(mg.nHistory()), hn(mg.nHistory());
    mg.initHistory(h.data());
    VolumetricInput in{0.45, 1e-9, 1e-6};   // past the limit 1 - 1/s
    const std::string msg = messageOf([&] { mg.evaluate(in, h.data(),
        hn.data()); }, SolidError::Kind::materialDomain);
    EXPECT_TRUE(has(msg, "material 'nucleus'")) << msg;
    EXPECT_TRUE(has(msg, "Hugoniot")) << msg;
    // Parameter errors of the EOS are reported with the material name
    w.C0 = -1;
    const std::string m2 = messageOf([&] { MieGruneisenVolumetric bad(w, 0,
        0, "material 'cytoplasm'"); }, SolidError::Kind::parameter);
    EXPECT_TRUE(has(m2, "cytoplasm") && has(m2, "C0")) << m2;
    const std::string m3 = messageOf([&] { MieGruneisenVolumetric bad(
        eos::MieGruneisen::Parameters(), -0.1, 0, "material 'x'"); },
        SolidError::Kind::parameter);
    EXPECT_TRUE(has(m3, "'b1' = -0.1")) << m3;
}
