// Mesh input (our MSH 4.1/2.2 reader against the gmsh API reader,
// physical groups, bad files), HDF5/XDMF output and restart.
#include "GmshReader.H"
#include "ResultWriter.H"
#include "StaticSolver.H"
#include "Loads.H"
#include "SolidError.H"
#include "SolidTestUtils.H"
#include "gmshApiReader.H"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

using namespace solid;

namespace
{

// Two stacked rectangles in r-z (nucleus below, cytoplasm above), quads
void writeAxisymmetricMesh
(
    const std::string& file,
    bool recombine = true,
    double version = 4.1
)
{
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::model::add("axi");
    namespace geo = gmsh::model::geo;
    const double R = 8, H1 = 2, H2 = 5;
    const int p1 = geo::addPoint(0, 0, 0), p2 = geo::addPoint(R, 0, 0),
        p3 = geo::addPoint(R, H1, 0), p4 = geo::addPoint(0, H1, 0),
        p5 = geo::addPoint(R, H2, 0), p6 = geo::addPoint(0, H2, 0);
    const int bottom = geo::addLine(p1, p2), r1 = geo::addLine(p2, p3),
        mid = geo::addLine(p3, p4), a1 = geo::addLine(p4, p1),
        r2 = geo::addLine(p3, p5), top = geo::addLine(p5, p6),
        a2 = geo::addLine(p6, p4);
    const int s1 = geo::addPlaneSurface({geo::addCurveLoop({bottom, r1, mid,
                                                            a1})});
    // Clockwise loop on purpose: the reader must reorient the quads
    const int s2 = geo::addPlaneSurface({geo::addCurveLoop({-a2, -top, -r2,
                                                            mid})});
    for (int c : {bottom, mid, top}) geo::mesh::setTransfiniteCurve(c, 9);
    for (int c : {r1, a1}) geo::mesh::setTransfiniteCurve(c, 3);
    for (int c : {r2, a2}) geo::mesh::setTransfiniteCurve(c, 4);
    for (int s : {s1, s2})
    {
        geo::mesh::setTransfiniteSurface(s);
        if (recombine) geo::mesh::setRecombine(2, s);
    }
    geo::synchronize();
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {s1}),
                                 "nucleus");
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {s2}),
                                 "cytoplasm");
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1,
        {bottom}), "fixedBottom");
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {top}),
                                 "top");
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1,
        {a1, a2}), "axis");
    gmsh::model::mesh::generate(2);
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::write(file);
    gmsh::finalize();
}

void writeHexMesh(const std::string& file, double version = 4.1)
{
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::model::add("hex");
    namespace geo = gmsh::model::geo;
    const int p1 = geo::addPoint(0, 0, 0), p2 = geo::addPoint(2, 0, 0),
        p3 = geo::addPoint(2, 1, 0), p4 = geo::addPoint(0, 1, 0);
    const int l1 = geo::addLine(p1, p2), l2 = geo::addLine(p2, p3),
        l3 = geo::addLine(p3, p4), l4 = geo::addLine(p4, p1);
    const int s = geo::addPlaneSurface({geo::addCurveLoop({l1, l2, l3, l4})});
    for (int c : {l1, l3}) geo::mesh::setTransfiniteCurve(c, 5);
    for (int c : {l2, l4}) geo::mesh::setTransfiniteCurve(c, 3);
    geo::mesh::setTransfiniteSurface(s);
    geo::mesh::setRecombine(2, s);
    gmsh::vectorpair out;
    geo::extrude({{2, s}}, 0, 0, 3, out, {4}, {}, true);
    geo::synchronize();
    int vol = -1, top = -1;
    for (const auto& dt : out)
    {
        if (dt.first == 3) vol = dt.second;
    }
    top = out[0].second;
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {vol}),
                                 "block");
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {s}),
                                 "bottom");
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {top}),
                                 "top");
    gmsh::model::mesh::generate(3);
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::write(file);
    gmsh::finalize();
}

double meshVolume(const Mesh& m)
{
    double V = 0;
    for (int e = 0; e < m.nElements(); ++e)
    {
        ElementGeometry g;
        g.build(m, e);
        V += g.V;
    }
    return V;
}

} // namespace


TEST(SolidIo, GmshAxisymmetricRegionsAndSets)
{
    writeAxisymmetricMesh("axi.msh");
    const Mesh m = readGmsh("axi.msh", 1e-6);
    ASSERT_TRUE(m.axisymmetric());
    EXPECT_EQ(m.nElements(), 8*2 + 8*3);
    ASSERT_EQ(m.regionNames.size(), 2u);
    int nNuc = 0;
    for (int r : m.region) nNuc += m.regionNames[r] == "nucleus";
    EXPECT_EQ(nNuc, 16);
    EXPECT_EQ(m.nodeSet("fixedBottom").size(), 9u);
    EXPECT_EQ(m.nodeSet("axis").size(), 6u);
    EXPECT_EQ(m.faceSet("top").size(), 8u);
    // Volume of the cylinder r = 8 um, h = 5 um (exact for straight edges)
    const double V = M_PI*64*5*1e-18;
    EXPECT_NEAR(meshVolume(m), V, 1e-12*V);
    // Outward top faces: a unit pressure gives the force -pi R^2 e_z
    Model model(m);
    auto mat = solidTest::material(10, 1e-3);
    model.setMaterial("nucleus", mat);
    model.setMaterial("cytoplasm", mat);
    model.initialise();
    PressureLoad load("top", [](double) { return 1.0; });
    Eigen::VectorXd f = Eigen::VectorXd::Zero(model.nDisplacementDofs());
    load.addForce(model, model.u, 0, f, nullptr);
    double Fz = 0;
    for (int n = 0; n < m.nNodes(); ++n) Fz += f(2*n + 1);
    EXPECT_NEAR(Fz, -M_PI*64e-12, 1e-12*M_PI*64e-12);
}


TEST(SolidIo, GmshCellLayersSolveWithPaperParameters)
{
    // Nucleus below cytoplasm (Table 2, d0 = 0), fixed bottom, symmetry
    // axis, follower pressure ramped on the top then held (creep): every
    // step converges and the support carries the pressure on the deformed
    // top surface
    writeAxisymmetricMesh("cell.msh");
    const Mesh m = readGmsh("cell.msh", 1e-6);
    Model model(m);
    // C10 [Pa], d0 [1/Pa], Maxwell mu1 [Pa] and tau1 [s] of Table 2 (as
    // etc/caseDicts/cellMaterials/table)
    model.setMaterial
    (
        "cytoplasm", solidTest::material(1.67, 0, {{107.78, 0.01}})
    );
    model.setMaterial
    (
        "nucleus", solidTest::material(13.33, 0, {{862.22, 0.5}})
    );
    model.fix("fixedBottom", 0);
    model.fix("fixedBottom", 1);
    model.fix("axis", 0);
    const double P = 2.0;
    model.add(std::make_shared<PressureLoad>("top",
        [=](double t) { return P*std::min(t/0.1, 1.0); }));
    model.initialise();
    StaticSolver solver(model);
    int maxIts = 0;
    double zTopOld = 0;
    for (int i = 0; i < 8; ++i)
    {
        const StepReport r = solver.step(0.05);
        maxIts = std::max(maxIts, r.iterations);
        EXPECT_EQ(r.cuts, 0);
        const double zTop = model.u(2*m.nodeSet("top")[0] + 1);
        if (i >= 3)
        {
            EXPECT_LT(zTop, zTopOld);           // creep under the hold
        }
        zTopOld = zTop;
    }
    EXPECT_LE(maxIts, 6);
    const Eigen::VectorXd r = solver.reactions();
    double Fz = 0;
    for (int n : m.nodeSet("fixedBottom")) Fz += r(2*n + 1);
    double area = 0;
    for (const auto& f : m.faceSet("top"))
    {
        const double r0 = m.X[f[0]](0) + model.u(2*f[0]);
        const double r1 = m.X[f[1]](0) + model.u(2*f[1]);
        // axial component of the ring area: pi (r0^2 - r1^2) for a face
        // running towards the axis (outward normal +z)
        area += M_PI*(r0*r0 - r1*r1);
    }
    EXPECT_NEAR(Fz, P*area, 1e-8*P*area);
}


TEST(SolidIo, GmshHexahedraAndUnsupportedElements)
{
    writeHexMesh("hex.msh");
    const Mesh m = readGmsh("hex.msh");
    ASSERT_FALSE(m.axisymmetric());
    EXPECT_EQ(m.nElements(), 4*2*4);
    EXPECT_NEAR(meshVolume(m), 6.0, 1e-12);
    EXPECT_EQ(m.faceSet("top").size(), 8u);
    EXPECT_EQ(m.nodeSet("bottom").size(), 15u);

    writeAxisymmetricMesh("tri.msh", false);
    try
    {
        readGmsh("tri.msh");
        FAIL() << "triangles accepted";
    }
    catch (const SolidError& e)
    {
        EXPECT_NE(std::string(e.what()).find("region 'nucleus'"),
                  std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("Triangle"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(readGmsh("doesNotExist.msh"), SolidError);
}


namespace
{

// The two readers give the same mesh: coordinates bit for bit, elements,
// regions and face sets in the same order, node sets as sets (and in the
// same order where gmsh lists the nodes in file order: MSH 4.1)
void expectSameMesh(const Mesh& a, const Mesh& b, bool sameNodeSetOrder)
{
    ASSERT_EQ(a.type, b.type);
    ASSERT_EQ(a.X.size(), b.X.size());
    for (std::size_t i = 0; i < a.X.size(); ++i)
    {
        EXPECT_EQ(a.X[i], b.X[i]) << "node " << i;
    }
    EXPECT_EQ(a.conn, b.conn);
    EXPECT_EQ(a.region, b.region);
    EXPECT_EQ(a.regionNames, b.regionNames);
    EXPECT_EQ(a.faceSets, b.faceSets);
    ASSERT_EQ(a.nodeSets.size(), b.nodeSets.size());
    for (const auto& s : a.nodeSets)
    {
        ASSERT_TRUE(b.nodeSets.count(s.first)) << s.first;
        const auto& t = b.nodeSets.at(s.first);
        if (sameNodeSetOrder)
        {
            EXPECT_EQ(s.second, t) << s.first;
        }
        EXPECT_EQ(std::set<int>(s.second.begin(), s.second.end()),
                  std::set<int>(t.begin(), t.end())) << s.first;
    }
}

std::string readError(const std::string& file, const std::string& text)
{
    std::ofstream(file) << text;
    try
    {
        readGmsh(file);
    }
    catch (const SolidError& e)
    {
        return e.what();
    }
    return "no error";
}

} // namespace


TEST(SolidIo, MshReaderEqualsGmshApiReader)
{
    for (const double version : {4.1, 2.2})
    {
        SCOPED_TRACE("MSH " + std::to_string(version));
        writeAxisymmetricMesh("cmpAxi.msh", true, version);
        expectSameMesh(readGmsh("cmpAxi.msh", 1e-6),
            solidTest::readGmshApi("cmpAxi.msh", 1e-6), version > 4);
        writeHexMesh("cmpHex.msh", version);
        expectSameMesh(readGmsh("cmpHex.msh"),
            solidTest::readGmshApi("cmpHex.msh"), version > 4);
    }
}


TEST(SolidIo, MshReaderBadFilesNameFileLineAndCause)
{
    const std::string head = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    const std::string nodes =
        "$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n";
    const std::string entities =
        "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n";
    const std::string elements =
        "$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 3 4\n$EndElements\n";
    // physical group 8 (1D) named name, 7 (2D) named "solid"
    const auto names = [](const std::string& name)
    {
        return "$PhysicalNames\n2\n1 8 \"" + name + "\"\n2 7 \"solid\"\n"
            "$EndPhysicalNames\n";
    };
    const std::string edged =
        "$Entities\n0 1 1 0\n1 0 0 0 1 0 0 1 8 0\n"
        "1 0 0 0 1 1 0 1 7 0\n$EndEntities\n";
    const std::string edgedElements =
        "$Elements\n2 2 1 2\n1 1 1 1\n2 1 2\n2 1 3 1\n1 1 2 3 4\n"
        "$EndElements\n";
    struct Case { const char* what; std::string text; const char* expect; };
    const Case cases[] =
    {
        {"not a mesh", "not a mesh\n", "must start with $MeshFormat"},
        {"empty", "", "must start with $MeshFormat"},
        {"binary", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n",
            "reads ASCII MSH 4.1 and 2.2"},
        {"MSH 4.0", "$MeshFormat\n4 0 8\n$EndMeshFormat\n",
            "reads ASCII MSH 4.1 and 2.2"},
        {"truncated nodes", head + entities + "$Nodes\n1 4 1 4\n2 1 0 4\n1\n",
            "line 11: the file ends inside section $Nodes"},
        {"letters for a node tag", head + entities
          + "$Nodes\n1 1 1 1\n2 1 0 1\nx\n", "line 11: expected integers"},
        {"NaN coordinate", head + entities
          + "$Nodes\n1 1 1 1\n2 1 0 1\n1\nnan 0 0\n$EndNodes\n",
            "node 1 has a non-finite coordinate"},
        {"node count", head + entities
          + "$Nodes\n1 5 1 4\n2 1 0 4\n1\n2\n3\n4\n"
            "0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n",
            "$Nodes announces 5 nodes, its blocks hold 4"},
        {"no elements", head + entities + nodes, "has no $Elements section"},
        {"huge node count", head + entities
          + "$Nodes\n1 4 1 4\n2 1 0 999999999999999999\n1\n",
            "line 11: the file ends inside section $Nodes"},
        {"unknown node", head + entities + nodes
          + "$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 3 9\n$EndElements\n",
            "element refers to unknown node 9"},
        {"triangle node count in a quad block", head + entities + nodes
          + "$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 3\n$EndElements\n",
            "has 3 nodes, expected 4"},
        {"more elements than counted", head + entities + nodes
          + "$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 3 4\n2 1 2 3 4\n"
            "$EndElements\n", "expected $EndElements"},
        {"no physical group", head
          + "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 0 0\n$EndEntities\n"
          + nodes + elements, "has no 2D or 3D physical group"},
        {"2.2 malformed element", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
            "$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n1 3 5\n"
            "$EndElements\n", "line 10: malformed element line"},
        // issue 19, adversarial pass: both were read silently (the first
        // definition of the node kept; the element run degenerate)
        {"a node tag defined twice", head + entities
          + "$Nodes\n1 5 1 4\n2 1 0 5\n1\n2\n3\n4\n2\n"
            "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n$EndNodes\n" + elements,
            "node 2 is defined twice"},
        {"a quad with a repeated node", head + entities + nodes
          + "$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 2 4\n$EndElements\n",
            "element 1 of region 'region7' lists node 2 twice"},
        {"a face set named like a region", head + names("solid") + edged
          + nodes + edgedElements, "the physical name 'solid' is given to "
            "two physical groups, the 1D group (boundary faces) of tag 8 "
            "and the 2D group (a region) of tag 7"},
    };
    // A curve (physical group 8) on the quad's bottom edge: read as a face
    // set when it has a name of its own
    {
        std::ofstream("edged.msh")
            << head + names("bottom") + edged + nodes + edgedElements;
        const Mesh m = readGmsh("edged.msh");
        EXPECT_EQ(m.regionNames, std::vector<std::string>{"solid"});
        EXPECT_EQ(m.faceSet("bottom").size(), 1u);
    }
    // The good file reads (one quad in the unnamed region 7)
    std::ofstream("good.msh") << head + entities + nodes + elements;
    const Mesh good = readGmsh("good.msh");
    EXPECT_EQ(good.nElements(), 1);
    EXPECT_EQ(good.regionNames, std::vector<std::string>{"region7"});
    for (const Case& c : cases)
    {
        const std::string msg = readError("bad.msh", c.text);
        EXPECT_NE(msg.find(c.expect), std::string::npos)
            << c.what << ": " << msg;
        EXPECT_NE(msg.find("bad.msh"), std::string::npos)
            << c.what << ": " << msg;
    }
}

namespace
{

std::unique_ptr<Model> creepModel()
{
    Mesh m = Mesh::rectangle(3, 3, 0, 1e-5, 0, 1e-5);
    std::unique_ptr<Model> model(new Model(m));
    model->setMaterial("solid", solidTest::material(13.33, 0,
                                                    {{862.22, 0.5}}));
    model->fix("left", 0);
    model->fix("bottom", 1);
    model->add(std::make_shared<PressureLoad>("top",
        [](double t) { return 50.0*std::min(t/0.2, 1.0); }));
    model->initialise();
    return model;
}

} // namespace


TEST(SolidIo, Hdf5XdmfOutputAndRestart)
{
    auto ref = creepModel();
    StaticSolver s1(*ref);
    ResultWriter w("creep", *ref);
    w.write(*ref);
    for (int i = 0; i < 6; ++i)
    {
        s1.step(0.1);
        w.write(*ref);
    }
    const auto steps = ResultWriter::steps("creep.h5");
    ASSERT_EQ(steps.size(), 7u);
    EXPECT_NEAR(steps[3].second, 0.3, 1e-12);

    // Restart from step 3 and redo the last three steps
    auto rs = creepModel();
    ResultWriter::restart("creep.h5", 3, *rs);
    EXPECT_NEAR(rs->time, 0.3, 1e-12);
    StaticSolver s2(*rs);
    for (int i = 0; i < 3; ++i) s2.step(0.1);
    EXPECT_LT((rs->u - ref->u).cwiseAbs().maxCoeff(),
              1e-12*ref->u.cwiseAbs().maxCoeff());
    EXPECT_LT((rs->pressure - ref->pressure).cwiseAbs().maxCoeff(),
              1e-10*ref->pressure.cwiseAbs().maxCoeff());
    // Creep happened between the restart point and the end
    auto mid = creepModel();
    ResultWriter::restart("creep.h5", 3, *mid);
    EXPECT_GT((ref->u - mid->u).norm(), 1e-3*ref->u.norm());

    // XDMF references every step and field
    std::ifstream x("creep.xmf");
    std::stringstream ss;
    ss << x.rdbuf();
    const std::string xs = ss.str();
    EXPECT_NE(xs.find("Quadrilateral"), std::string::npos);
    EXPECT_NE(xs.find("creep.h5:/steps/6/temperatureRise"),
              std::string::npos);
    EXPECT_NE(xs.find("<Time Value=\"0.6\"/>"), std::string::npos);

    EXPECT_THROW(ResultWriter::restart("creep.h5", 42, *mid), SolidError);
    auto other = std::unique_ptr<Model>(new Model(Mesh::rectangle(2, 2, 0, 1,
                                                                  0, 1)));
    other->setMaterial("solid", solidTest::material(1, 1e-3));
    other->initialise();
    EXPECT_THROW(ResultWriter::restart("creep.h5", 3, *other), SolidError);
}
