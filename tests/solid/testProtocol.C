// Indentation protocol (paper Table 1): load history, peak times, input
#include "IndentationProtocol.H"
#include "SolidError.H"

#include <gtest/gtest.h>

using namespace solid;

TEST(SolidProtocol, PaperTable1LoadHistory)
{
    const double um = 1e-6;
    const IndentationProtocol p(IndentationProtocol::paperRows(1.41*um));
    // A: 1.41/0.3 = 4.7 s; B to 19.7 s; C1 cycles of 0.4 s; C2 of 4 s; C3
    // of 40 s; D 0.2 s; E 120 s
    const double tA = 4.7, tB = 19.7;
    const std::vector<std::pair<std::string, double>> expected =
    {
        {"C1,i", tB + 0.2}, {"C1,ii", tB + 0.6}, {"C1,iii", tB + 1.0},
        {"C2,i", tB + 1.2 + 2}, {"C2,ii", tB + 1.2 + 6},
        {"C2,iii", tB + 1.2 + 10},
        {"C3,i", tB + 13.2 + 20}, {"C3,ii", tB + 13.2 + 60},
        {"C3,iii", tB + 13.2 + 100}
    };
    const auto peaks = p.peaks();
    ASSERT_EQ(peaks.size(), expected.size());
    for (std::size_t i = 0; i < peaks.size(); ++i)
    {
        EXPECT_EQ(peaks[i].label, expected[i].first);
        EXPECT_NEAR(peaks[i].time, expected[i].second, 1e-9);
        EXPECT_NEAR(peaks[i].depth, 3.41*um, 1e-15);
        EXPECT_NEAR(p.depth(peaks[i].time), 3.41*um, 1e-15);
    }
    // The paper's field snapshot at 26.88 s is a peak of this schedule
    // (C2,ii at 26.9 s with delta0 = 1.41 um; 26.88 s with 1.404 um)
    EXPECT_NEAR(peaks[4].time, 26.88, 0.03);
    EXPECT_NEAR(p.stageEnd("A"), tA, 1e-12);
    EXPECT_NEAR(p.stageEnd("B"), tB, 1e-12);
    EXPECT_NEAR(p.stageEnd("C3"), tB + 133.2, 1e-9);
    EXPECT_NEAR(p.stageEnd("D"), tB + 133.4, 1e-9);
    EXPECT_NEAR(p.endTime(), 273.1, 1e-9);
    EXPECT_THROW(p.stageEnd("F"), SolidError);

    // Depth and rate along the way
    EXPECT_NEAR(p.depth(2.35), 0.705*um, 1e-15);
    EXPECT_NEAR(p.rate(2.35), 0.3*um, 1e-15);
    EXPECT_NEAR(p.depth(10), 1.41*um, 1e-15);
    EXPECT_EQ(p.rate(10), 0);
    EXPECT_NEAR(p.depth(tB + 0.3), 3.41*um - 1*um, 1e-15);
    EXPECT_NEAR(p.rate(tB + 0.3), -10*um, 1e-12);
    EXPECT_NEAR(p.depth(tB + 1.2), 1.41*um, 1e-15);
    EXPECT_NEAR(p.depth(200), 3.41*um, 1e-15);
    EXPECT_NEAR(p.depth(1e4), 3.41*um, 1e-15);
    EXPECT_EQ(p.rows()[p.rowAt(200)].stage, "E");

    // Force criterion: A ends at the depth found, the rest shifts
    const IndentationProtocol q = p.withFirstRowAmount(0.84*um);
    EXPECT_NEAR(q.stageEnd("A"), 2.8, 1e-12);
    EXPECT_NEAR(q.peaks()[0].time, 2.8 + 15 + 0.2, 1e-9);
    EXPECT_NEAR(q.peaks()[0].depth, 2.84*um, 1e-15);
    EXPECT_NEAR(q.endTime(), 273.1 - 1.9, 1e-9);
}


TEST(SolidProtocol, BadRowsNameTheRow)
{
    auto rows = IndentationProtocol::paperRows(1e-6);
    auto expectMessage = [](const std::vector<ProtocolRow>& r,
                            const std::string& part)
    {
        try
        {
            IndentationProtocol p(r);
            ADD_FAILURE() << "no error for " << part;
        }
        catch (const SolidError& e)
        {
            std::printf("%s\n", e.what());
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
                << e.what();
        }
    };
    auto r = rows;
    r[3].rate = -1e-5;                              // C1 unload
    expectMessage(r, "row 4 (stage 'C1', unload)");
    r = rows;
    r[1].amount = 0;                                // B: zero duration
    expectMessage(r, "row 2 (stage 'B', hold)");
    r = rows;
    r[1].amount = -15;                              // B: time backwards
    expectMessage(r, "row 2 (stage 'B', hold)");
    r = rows;
    r[2].motion = "press";
    expectMessage(r, "unknown motion 'press'");
    r = rows;
    r[3].amount = 4e-6;                             // unload above surface
    expectMessage(r, "row 4 (stage 'C1', unload): unloads to depth");
    r = rows;
    r[2].rate = 6e-301;                             // duration overflows
    r[2].amount = 4e25;                             // (found by fuzzProtocol)
    expectMessage(r, "row 3 (stage 'C1', load): entry 'amount' = 4e+25 m is"
                  " outside the valid range (0, 1)");
    // Finite values beyond the physical bounds (physicalBounds.H; issue
    // 19, adv30 hg07: a hold of 1e300 s was a floating-point exception;
    // n26: a rate of 1e300 m/s a row shorter than the time resolution)
    r = rows;
    r[1].amount = 1e300;
    expectMessage(r, "row 2 (stage 'B', hold): entry 'amount' = 1e+300 s is"
                  " outside the valid range (0, 1e+06)");
    r = rows;
    r[2].rate = 1e300;
    expectMessage(r, "row 3 (stage 'C1', load): entry 'rate' = 1e+300 m/s");
    r = rows;
    r[2].rate = 6e-301;                             // 1.7e294 s
    expectMessage(r, "row 3 (stage 'C1', load): the protocol ends at");
    r = rows;
    r[1].amount = 999999;                           // the sum beyond 1e6 s
    expectMessage(r, "the table must end before 1e+06 s");
    r = rows;
    r[2].rate = 1e4;
    r[2].amount = 1e-14;                            // 1e-18 s at t ~ 20 s
    expectMessage(r, "row 3 (stage 'C1', load): the row lasts amount/rate ="
                  " 1e-18 s, below the time resolution at its start");
    expectMessage({}, "no rows");
}
