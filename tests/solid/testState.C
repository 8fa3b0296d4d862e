// The model's state snapshot (ModelSnapshot): taken, advanced, restored
// bitwise; the checkpoint's round trip of it through a file; sizes of
// another model refused with the part named.
#include "Checkpoint.H"
#include "Loads.H"
#include "ModelSnapshot.H"
#include "SolidError.H"
#include "StaticSolver.H"
#include "SolidTestUtils.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

using namespace solid;

namespace
{

// A viscoelastic block under a ramped pressure: displacements, pressure
// multipliers and Maxwell histories all change from step to step
std::unique_ptr<Model> creepingBlock()
{
    std::unique_ptr<Model> model
    (
        new Model(Mesh::rectangle(3, 2, 0, 1e-5, 0, 1e-5))
    );
    model->setMaterial("solid", solidTest::material(13.33, 0,
                                                    {{862.22, 0.5}}));
    model->fix("left", 0);
    model->fix("bottom", 1);
    model->add(std::make_shared<PressureLoad>("top",
        [](double t) { return 50.0*std::min(t/0.2, 1.0); }));
    model->initialise();
    return model;
}

// The state as the model holds it, copied without the snapshot
struct Raw
{
    Eigen::VectorXd u, v, pressure;
    double time;
    std::vector<double> pointOld, pointCurrent, elementOld, elementCurrent;

    explicit Raw(Model& m)
    :
        u(m.u), v(m.v), pressure(m.pressure), time(m.time),
        pointOld(m.pointState().oldData()),
        pointCurrent(m.pointState().currentData()),
        elementOld(m.elementState().oldData()),
        elementCurrent(m.elementState().currentData())
    {}
};

bool sameBits(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
    return a.size() == b.size()
        && std::equal(a.data(), a.data() + a.size(), b.data());
}

void expectSame(const Raw& a, const Raw& b)
{
    EXPECT_TRUE(sameBits(a.u, b.u));
    EXPECT_TRUE(sameBits(a.v, b.v));
    EXPECT_TRUE(sameBits(a.pressure, b.pressure));
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.pointOld, b.pointOld);
    EXPECT_EQ(a.pointCurrent, b.pointCurrent);
    EXPECT_EQ(a.elementOld, b.elementOld);
    EXPECT_EQ(a.elementCurrent, b.elementCurrent);
}

std::string errorOf(const std::function<void()>& f)
{
    try
    {
        f();
    }
    catch (const SolidError& e)
    {
        return e.what();
    }
    return "";
}

} // namespace


TEST(ModelSnapshot, AdvanceAndRestoreIsBitwise)
{
    auto model = creepingBlock();
    StaticSolver solver(*model);
    for (int i = 0; i < 2; ++i) solver.step(0.1);
    const Raw atSnapshot(*model);
    const ModelSnapshot snapshot(*model);
    EXPECT_EQ(snapshot.time(), model->time);

    for (int i = 0; i < 2; ++i) solver.step(0.1);
    const Raw advanced(*model);
    // The steps changed every part of the state
    EXPECT_FALSE(sameBits(advanced.u, atSnapshot.u));
    EXPECT_FALSE(sameBits(advanced.pressure, atSnapshot.pressure));
    EXPECT_NE(advanced.pointOld, atSnapshot.pointOld);

    snapshot.restore(*model);
    expectSame(Raw(*model), atSnapshot);
    // and the same two steps from there give the same bits
    for (int i = 0; i < 2; ++i) solver.step(0.1);
    expectSame(Raw(*model), advanced);
}


TEST(ModelSnapshot, OtherModelRefusedNamingThePart)
{
    auto model = creepingBlock();
    const ModelSnapshot s(*model);
    Model other(Mesh::rectangle(2, 2, 0, 1, 0, 1));
    other.setMaterial("solid", solidTest::material(1, 1e-3));
    other.initialise();
    const std::string msg = errorOf([&] { s.restore(other); });
    EXPECT_NE(msg.find("'u' has"), std::string::npos) << msg;
}


TEST(Checkpoint, ModelRoundTripIsBitwise)
{
    auto model = creepingBlock();
    StaticSolver solver(*model);
    for (int i = 0; i < 3; ++i) solver.step(0.1);
    std::remove("state.h5");
    {
        Checkpoint c("state.h5");
        c.storeModel("model/", *model);
        c.set("row", 2.0);
        c.write();
    }
    const Checkpoint read = Checkpoint::read("state.h5");
    EXPECT_EQ(read.scalar("row"), 2.0);
    auto restored = creepingBlock();
    read.restoreModel("model/", *restored);
    expectSame(Raw(*restored), Raw(*model));
    // and continues bit for bit
    StaticSolver other(*restored);
    solver.step(0.1);
    other.step(0.1);
    expectSame(Raw(*restored), Raw(*model));

    // A checkpoint of another model: the file and the entry named
    Model small(Mesh::rectangle(2, 2, 0, 1, 0, 1));
    small.setMaterial("solid", solidTest::material(1, 1e-3));
    small.initialise();
    const std::string msg =
        errorOf([&] { read.restoreModel("model/", small); });
    EXPECT_NE(msg.find("state.h5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("model/u"), std::string::npos) << msg;
}
