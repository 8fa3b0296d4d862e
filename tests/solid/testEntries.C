// The material entries as the solid library reads them (solid::Entries):
// the map-of-strings implementation is strict (one finite decimal number,
// one word) and keeps every digit, so that two parameters differing in
// the 8th digit build different materials (issue 16: a text round trip
// through 6 digits made C10 = 1.6700001 and 1.6700004 the same material).
#include "Material.H"
#include "SolidError.H"
#include "StringEntries.H"

#include <gtest/gtest.h>

using namespace solid;

namespace
{

//- The message of the SolidError that reading key as a number throws
std::string numberError(const std::string& value)
{
    const StringEntries e("material 'cell'", {{"C10", value}});
    try
    {
        e.real("C10");
    }
    catch (const SolidError& err)
    {
        EXPECT_EQ(err.kind(), SolidError::Kind::parameter);
        return err.what();
    }
    return "";
}

//- Second Piola-Kirchhoff stress of the isochoric model at a sheared,
//  stretched state (first step of 1 ms from the reference state)
Mat3 stressOf(const std::string& C10)
{
    const auto m = Material::create
    (
        MaterialParameters::fromEntries
        (
            "cytoplasm",
            StringEntries
            (
                "material 'cytoplasm'",
                {{"C10", C10}, {"mu1", "107.78"}, {"tau1", "0.01"}}
            )
        )
    );
    Mat3 F;
    F << 1.2, 0.1, 0, 0, 0.9, 0, 0, 0, 1/(1.2*0.9);
    const Mat3 C = F.transpose()*F;
    const IsochoricModel& iso = m->isochoric();
    std::vector<double> hOld(iso.nHistory()), hNew(iso.nHistory());
    iso.initHistory(hOld.data());
    IsoResponse r;
    iso.evaluate(C, 1e-3, hOld.data(), hNew.data(), r);
    return r.S;
}

} // namespace


TEST(SolidEntries, NumbersKeepEveryDigit)
{
    const StringEntries e
    (
        "material 'cell'",
        {{"a", "1.6700001"}, {"b", "1.6700004"}, {"c", "-3e-6"},
         {"d", "0.1000000000000000055511151231257827"}}
    );
    EXPECT_EQ(e.real("a"), 1.6700001);
    EXPECT_EQ(e.real("b"), 1.6700004);
    EXPECT_NE(e.real("a"), e.real("b"));
    EXPECT_EQ(e.real("c"), -3e-6);
    EXPECT_EQ(e.real("d"), 0.1);
    EXPECT_EQ(e.keys(), (std::vector<std::string>{"a", "b", "c", "d"}));
    EXPECT_TRUE(e.has("a"));
    EXPECT_FALSE(e.has("e"));
}


TEST(SolidEntries, StrictNumbersAndWords)
{
    for
    (
        const char* bad :
        {"", "abc", "1 Pa", " 2", "2 ", "1,5", "inf", "-inf", "nan",
         "0x10", "1e999", "1.5.2", "--1"}
    )
    {
        EXPECT_NE(numberError(bad).find("material 'cell': entry 'C10' = '"
                                        + std::string(bad)
                                        + "' is not a number"),
                  std::string::npos) << "'" << bad << "'";
    }
    const StringEntries e
    (
        "material 'cell'", {{"volumetric", "neo Hookean"}, {"law", "x"}}
    );
    EXPECT_EQ(e.word("law"), "x");
    EXPECT_THROW(e.word("volumetric"), SolidError);
    try
    {
        e.real("C10");
        ADD_FAILURE() << "a missing entry was read";
    }
    catch (const SolidError& err)
    {
        EXPECT_STREQ(err.what(), "material 'cell': missing entry 'C10'");
    }
}


TEST(SolidEntries, EighthDigitChangesTheMaterial)
{
    const Mat3 a = stressOf("1.6700001");
    const Mat3 b = stressOf("1.6700004");
    const Mat3 c = stressOf("1.6700001");
    EXPECT_NE(a, b);
    EXPECT_EQ(a, c);
    // The difference is the neo-Hookean part's: 2 dC10 times its shape
    const Mat3 d = stressOf("2.6700001") - a;
    EXPECT_NEAR((b - a).norm(), 3e-7*d.norm(), 1e-3*3e-7*d.norm());
}
