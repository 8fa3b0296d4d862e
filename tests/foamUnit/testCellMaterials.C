/*---------------------------------------------------------------------------*\
Description
    Unit tests of the paper's parameter sets as data
    (etc/caseDicts/cellMaterials, included in 'materials' of
    constant/solidProperties) read through solidInput: every number of
    Table 2 and of the text reaches the material exactly, the
    "instantaneous" set holds the Abaqus products of Table 2 to the last
    bit, and the former names (parameterSet, c0, volumetric neoHookean) are
    errors naming the replacement.

\*---------------------------------------------------------------------------*/

#include "solidInput.H"
#include "foamTestCase.H"
#include "IOdictionary.H"

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace Foam;

namespace
{

//- The materials of solidProperties whose 'materials' holds text, for the
//  three regions of the cell mesh
std::map<std::string, solid::MaterialParameters> readMaterials
(
    const std::string& materials
)
{
    foamUnit::testCase tc("cellMaterials");
    tc.writeFile
    (
        "constant/solidProperties",
        "FoamFile { version 2.0; format ascii; class dictionary; "
        "object solidProperties; }\nmaterials\n{\n" + materials + "\n}\n"
    );
    const IOdictionary dict
    (
        IOobject
        (
            "solidProperties", tc.time().constant(), tc.time(),
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    solid::Mesh mesh;
    mesh.regionNames = {"nucleus", "cytoplasm", "membrane"};
    std::map<std::string, solid::MaterialParameters> result;
    for (const auto& p : solidInput(dict, tc.dir()).materials(mesh))
    {
        result[p.name] = p;
    }
    return result;
}

std::string include(const std::string& set)
{
    return "#include \"$PROJECT_DIR/etc/caseDicts/cellMaterials/" + set
      + "\"";
}

//- The message of the FatalIOError of reading materials
std::string errorOf(const std::string& materials)
{
    try
    {
        readMaterials(materials);
    }
    catch (const Foam::IOerror& err)
    {
        return err.message();
    }
    ADD_FAILURE() << "accepted: " << materials;
    return "";
}

//- Region (C10 [Pa], mu1 [Pa], tau1 [s]) as written in the paper
struct paperMaterial
{
    double C10, mu1, tau1;
};

void expectSet
(
    const std::map<std::string, solid::MaterialParameters>& set,
    const std::map<std::string, paperMaterial>& expected
)
{
    ASSERT_EQ(set.size(), expected.size());
    for (const auto& e : expected)
    {
        const solid::MaterialParameters& p = set.at(e.first);
        EXPECT_EQ(p.rho0, 1000) << e.first;
        EXPECT_EQ(p.C10, e.second.C10) << e.first;
        EXPECT_EQ(p.volumetric, "quadratic") << e.first;
        EXPECT_EQ(p.d0, 0) << e.first;
        ASSERT_EQ(p.branches.size(), 1u) << e.first;
        EXPECT_EQ(p.branches[0].mu, e.second.mu1) << e.first;
        EXPECT_EQ(p.branches[0].tau, e.second.tau1) << e.first;
    }
}

//- Table 2 (tau1_cyto from eta1_cyto = 1.08 Pa s, sec. 3.2)
const std::map<std::string, paperMaterial> table2 =
{
    {"membrane", {166.67, 13.89, 3000}},
    {"cytoplasm", {1.67, 107.78, 0.01}},
    {"nucleus", {13.33, 862.22, 0.5}}
};

} // End anonymous namespace


TEST(cellMaterials, paperReadings)
{
    expectSet(readMaterials(include("table")), table2);

    // Sec. 3.1, eq. 10: c_0^nuc = 6.67 Pa
    std::map<std::string, paperMaterial> text = table2;
    text["nucleus"].C10 = 6.67;
    expectSet(readMaterials(include("text")), text);

    // Sec. 3.2: mu1_nuc = 4 mu1_cyto as well
    std::map<std::string, paperMaterial> factor4 = text;
    factor4["nucleus"].mu1 = 4*107.78;
    expectSet(readMaterials(include("textFactor4")), factor4);

    // The text's set with Abaqus' instantaneous moduli and a relative Prony
    // weight: G0 = 2 c_0, g1 = mu1/(G0 + mu1), long-term C10 = c_0 (1 - g1),
    // branch G0 g1; the file's digits must give these doubles exactly
    std::map<std::string, paperMaterial> instantaneous = text;
    for (auto& r : instantaneous)
    {
        const double G0 = 2*r.second.C10;
        const double g1 = r.second.mu1/(G0 + r.second.mu1);
        r.second.C10 *= 1 - g1;
        r.second.mu1 = G0*g1;
    }
    expectSet(readMaterials(include("instantaneous")), instantaneous);
}


TEST(cellMaterials, regionAfterTheSetReplacesItsEntries)
{
    const auto set = readMaterials
    (
        include("table")
      + "\nnucleus { volumetric mieGruneisen; C0 1450; s 1.99;"
        " Gamma0 0.1; Cv 4184; T0 293.15; }"
    );
    EXPECT_EQ(set.at("nucleus").volumetric, "mieGruneisen");
    EXPECT_EQ(set.at("nucleus").eos.C0, 1450);
    EXPECT_EQ(set.at("nucleus").C10, 13.33);
    EXPECT_EQ(set.at("nucleus").branches[0].mu, 862.22);
    EXPECT_EQ(set.at("cytoplasm").volumetric, "quadratic");
}


TEST(cellMaterials, usageExampleOfSolidInput)
{
    // The materials of the Usage example of solidInput.H
    const std::string usage =
        foamUnit::testCase::usageExample("src/solidInput/solidInput.H");
    const auto begin = usage.find("materials");
    ASSERT_NE(begin, std::string::npos);
    const auto open = usage.find('{', begin);
    const auto close = usage.rfind('}');
    ASSERT_LT(open, close);
    expectSet(readMaterials(usage.substr(open + 1, close - open - 1)), table2);
}


TEST(cellMaterials, formerNamesNameTheirReplacement)
{
    const std::string set = errorOf("parameterSet textFactor4;");
    for
    (
        const std::string m
      : {"'parameterSet' is no longer read", "cellMaterials/<set>",
         "table, text, textFactor4, instantaneous"}
    )
    {
        EXPECT_NE(set.find(m), std::string::npos) << set;
    }
    const std::string c0 = errorOf
    (
        include("table") + "\nnucleus { c0 13.33; }"
    );
    EXPECT_NE(c0.find("entry 'c0' is now 'C10'"), std::string::npos) << c0;
    const std::string vol = errorOf
    (
        include("table") + "\nmembrane { volumetric neoHookean; }"
    );
    EXPECT_NE(vol.find("'neoHookean' is now 'quadratic'"), std::string::npos)
        << vol;
    const std::string none = errorOf("nucleus { C10 1; }");
    EXPECT_NE(none.find("no material for region 'cytoplasm'"),
              std::string::npos) << none;
}


// ************************************************************************* //
