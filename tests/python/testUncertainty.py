"""neuronFsi.uncertainty: the 'uncertainty' sub-dictionary of the pulse
study checked when read (each bad entry named), the runs it adds (their
material changes, written and checked against the solver's log), and the
propagation on fake runners whose answer is known: an indicator linear in
the fitted variables gives the exact interval (against the parameters'
intervals mapped directly, and against sampling the parameters' normal
law with its correlation), a curved one shows in the second step."""
import json
import math
import os
import unittest

import numpy as np

from fixtures import TempDirTestCase
from neuronFsi import pulseStudy as ps
from neuronFsi import uncertainty as unc
from testPulseStudy import ALLRUN, GOOD

SOLID = """materials
{
    cytoplasm { C10 1.67; mu1 107.78; tau1 0.01; volumetric mieGruneisen;
                C0 1450; }
    nucleus   { C10 6.67; mu1 431.12; tau1 0.5; volumetric mieGruneisen; }
    membrane  { C10 166.67; mu1 13.89; tau1 3000; volumetric quadratic;
                d0 9.5125e-10; }
}
"""

UNCERTAINTY = """{
    pulses      ((10e6 5e-9));
    variants
    {
        table       { materials table; }
        calibrated  { cytoplasm.C10 0.1788 [Pa]; nucleus.C10 2.538 [Pa]; }
    }
    about       calibrated;
    parameters
    {
        cytoplasm.C10 { interval (0.131 0.245) [Pa]; log yes; }
        nucleus.C10   { interval (1.58 4.08) [Pa]; log yes; }
    }
    correlation ((cytoplasm.C10 nucleus.C10 -0.60));
    difference  central;
    step        0.2;
    checkStep   0.1;
}"""


class Study(TempDirTestCase):
    """A study with an 'uncertainty' sub-dictionary (the text of
    UNCERTAINTY with the replacements given)."""

    def setUp(self):
        super().setUp()
        self.case = os.path.join(self.tmp, "study")
        self.write("study/base/Allrun", ALLRUN)
        self.write("study/base/constant/solidProperties", SOLID)
        # a blast case's folders and run length (pulseStudy.read)
        self.write("study/base/system/controlDict", "endTime 1.5e-7;\n")
        self.write("study/base/0.orig/p", "")

    def study(self, *replace, text=None):
        u = UNCERTAINTY if text is None else text
        for a, b in replace:
            self.assertIn(a, u)
            u = u.replace(a, b)
        entries = dict(GOOD, uncertainty=u)
        self.write("study/system/pulseStudyDict", "".join(
            "%s %s;\n" % (k, v) if not v.startswith("{") else
            "%s %s\n" % (k, v) for k, v in entries.items()))
        return ps.read(self.case)

    def refused(self, regex, *replace, text=None):
        with self.assertRaisesRegex(ps.StudyError,
                                    "pulseStudyDict: uncertainty.*" + regex):
            self.study(*replace, text=text)


class Dictionary(Study):

    def testGood(self):
        s = self.study()
        u = s["uncertainty"]
        self.assertEqual(u["pulses"], [(1e7, 5e-9)])
        # the set's deviatoric parameters, the base's volumetric law kept
        self.assertEqual(u["variants"]["table"]["nucleus"],
                         {"C10": 13.33, "mu1": 862.22, "tau1": 0.5})
        self.assertEqual(u["variants"]["calibrated"],
                         {"cytoplasm": {"C10": 0.1788},
                          "nucleus": {"C10": 2.538}})
        p = u["parameters"]
        self.assertEqual([q["value"] for q in p], [0.1788, 2.538])
        self.assertAlmostEqual(p[0]["halfWidth"], math.log(0.245/0.131)/2)
        self.assertEqual(u["correlation"][0, 1], -0.6)
        self.assertFalse(u["independent"])
        pts = ps.uncertaintyPoints(s)
        # 2 variants and 2 parameters x 2 steps x 2 signs
        self.assertEqual(len(pts), 10)
        self.assertEqual(pts[0]["label"], "p1e+07_T5e-09_table")
        self.assertEqual(pts[0]["options"], ps.points(s)[1]["options"])
        q = next(x for x in pts
                 if x["run"] == "calibrated_nucleus.C10-0.1")
        self.assertEqual(q["change"], {"cytoplasm": {"C10": 0.1788},
                                       "nucleus": {"C10":
                                                   2.538*math.exp(-0.1)}})
        # a finished point's record with another change is named
        d = ps.inputs({}, q)
        self.assertEqual(ps.differences(d, d), [])
        other = dict(q, change={"nucleus": {"C10": 1.0}})
        self.assertEqual(ps.differences(d, ps.inputs({}, other))[0][0],
                         "uncertainty")
        # JSON keeps the change exactly (a restart compares it)
        self.assertEqual(ps.differences(json.loads(json.dumps(d)), d), [])

    def testIndependentForwardNoVariants(self):
        s = self.study(("    correlation ((cytoplasm.C10 nucleus.C10 "
                        "-0.60));\n", ""),
                       ("central", "forward"),
                       ("about       calibrated;", "about base;"))
        u = s["uncertainty"]
        self.assertTrue(u["independent"])
        self.assertEqual(u["parameters"][0]["value"], 1.67)
        self.assertEqual(len(unc.runs(u)), 2 + 2*2)

    def testCorrelationNone(self):
        """fix19d (adv47b f64): 'correlation none;', the user guide's
        words for independent parameters, was refused as not a row"""
        u = self.study(("((cytoplasm.C10 nucleus.C10 -0.60))", "none"))[
            "uncertainty"]
        self.assertTrue(u["independent"])
        self.assertEqual(u["correlation"].tolist(), [[1, 0], [0, 1]])
        self.refused(r"'none' or no entry: independent",
                     ("((cytoplasm.C10 nucleus.C10 -0.60))", "nothing"))

    def testVariantsOnly(self):
        text = """{ pulses ((30e6 2e-9) (10e6 5e-9));
                    variants { text { materials text; } } }"""
        u = self.study(text=text)["uncertainty"]
        self.assertEqual(u["parameters"], [])
        self.assertEqual([n for n, _ in unc.runs(u)], ["text"])
        self.assertEqual(len(ps.uncertaintyPoints(self.study(text=text))),
                         2)
        self.refused(r"entry 'step' without 'parameters'",
                     text=text.replace("} } }", "} } step 0.1; }"))
        self.refused(r"neither 'variants' nor 'parameters'",
                     text="{ pulses ((30e6 2e-9)); }")

    def testStepNames(self):
        # two steps that %g would print alike get every digit
        u = self.study(("checkStep   0.1", "checkStep 0.2000001"))[
            "uncertainty"]
        names = [n for n, _ in unc.runs(u)]
        self.assertEqual(len(set(names)), len(names))
        self.assertIn("calibrated_nucleus.C10-0.2000001", names)

    def testUnknownParameter(self):
        self.refused(r"parameters/cytoplasm.C11: 'cytoplasm.C11': region "
                     r"cytoplasm has no parameter 'C11'; did you mean 'C10'"
                     r"\? \(valid: C10 mu1 tau1 C0\)",
                     ("cytoplasm.C10 { interval", "cytoplasm.C11 { interval"))

    def testUnknownRegion(self):
        self.refused(r"parameters/nucleos.C10: 'nucleos.C10': no region "
                     r"'nucleos'.*did you mean 'nucleus'",
                     ("nucleus.C10   { interval", "nucleos.C10   { interval"),
                     ("(cytoplasm.C10 nucleus.C10 -0.60)",
                      "(cytoplasm.C10 nucleos.C10 -0.60)"))

    def testVariantUnknownParameter(self):
        self.refused(r"variants/calibrated: 'cytoplasm.mu2': region "
                     r"cytoplasm has no parameter 'mu2'",
                     ("cytoplasm.C10 0.1788 [Pa]", "cytoplasm.mu2 1 [Pa]"))

    def testStepZero(self):
        self.refused(r"entry 'step' = 0 is outside the valid range "
                     r"\(0, 1\)", ("step        0.2", "step 0"))

    def testStepTooLarge(self):
        """adv48a h10: step 1e3 (or 710) overflowed e^step in stepProblem,
        an OverflowError traceback: refused naming the range"""
        for step in ("1e3", "710", "1"):
            self.refused(r"entry 'step' = %s is outside the valid range "
                         r"\(0, 1\) \[-\] \(the finite difference's step "
                         r"in ln p" % ("1000.0" if step == "1e3" else step),
                         ("step        0.2", "step %s" % step))
        self.refused(r"entry 'checkStep' = 710 is outside the valid range "
                     r"\(0, 1\)", ("checkStep   0.1", "checkStep 710"))

    def testStepThatMovesNoParameter(self):
        """fix19d (adv47b f25): a step that leaves a parameter's value
        unchanged in double precision (p e^1e-17 == p) was accepted, its
        runs the 'about' run and the half-width 0: refused naming the
        entry, the parameter and a step that moves it"""
        self.refused(r"entry 'step' = 1e-17 does not move parameter "
                     r"cytoplasm.C10 = 0.1788 Pa: 0.1788 e\^\(\+-1e-17\) is "
                     r"0.1788 in double precision(.|\n)*Give a step of at "
                     r"least [0-9.e-]+",
                     ("step        0.2", "step 1e-17"),
                     ("checkStep   0.1", "checkStep 2e-17"))
        self.refused(r"entry 'checkStep' = 1e-17 does not move parameter",
                     ("checkStep   0.1", "checkStep 1e-17"))
        # the smallest step named moves it
        s = self.study()
        u = dict(s["uncertainty"], step=1e-17)
        import re
        least = float(re.search(r"at least (\S+)",
                                unc.stepProblem(u)).group(1))
        self.assertIsNone(unc.stepProblem(dict(u, step=least)))

    def testSameSteps(self):
        self.refused(r"entry 'checkStep' = step = 0.2",
                     ("checkStep   0.1", "checkStep 0.2"))

    def testIntervalWithoutUnit(self):
        self.refused(r"parameters/cytoplasm.C10: interval: \(0.131 0.245\) "
                     r"has no unit: give it as 'interval \(lo hi\) \[Pa\]'",
                     ("(0.131 0.245) [Pa]", "(0.131 0.245)"))

    def testIntervalWrongUnit(self):
        self.refused(r"parameters/nucleus.C10: interval: \(1.58 4.08\) "
                     r"\[kPa\]: the unit of this entry is \[Pa\]",
                     ("(1.58 4.08) [Pa]", "(1.58 4.08) [kPa]"))

    def testIntervalReversed(self):
        self.refused(r"parameters/nucleus.C10: interval .*lo < hi",
                     ("(1.58 4.08) [Pa]", "(4.08 1.58) [Pa]"))

    def testVariantValueWithoutUnit(self):
        self.refused(r"variants/calibrated: nucleus.C10: 2.538 has no unit",
                     ("nucleus.C10 2.538 [Pa]", "nucleus.C10 2.538"))

    def testUnknownSet(self):
        self.refused(r"variants/table: materials 'tabel': no such set.*"
                     r"did you mean 'table'",
                     ("materials table", "materials tabel"))

    def testPulseNotOnGrid(self):
        self.refused(r"entry 'pulses': \(5e\+07 Pa, 5e-09 s\) is not a "
                     r"point of the grid", ("((10e6 5e-9))", "((50e6 5e-9))"))
        # one ulp above a grid value: printed with the digits that show it
        # (adv48b g46: "(3e+07 Pa, ...) is not a point of the grid
        # (overpressure 3e+07 ...)")
        self.refused(r"entry 'pulses': \(10000000.000000002 Pa, 5e-09 s\) "
                     r"is not a point of the grid \(overpressure 1e\+07 ",
                     ("((10e6 5e-9))", "((10000000.000000002 5e-9))"))

    def testAboutUnknown(self):
        self.refused(r"entry 'about' = calibrate: neither base nor a "
                     r"variant; did you mean 'calibrated'",
                     ("about       calibrated", "about calibrate"))

    def testCorrelationOutOfRange(self):
        self.refused(r"entry 'correlation': \(cytoplasm.C10 nucleus.C10 "
                     r"-1.5\) is not",
                     ("nucleus.C10 -0.60", "nucleus.C10 -1.5"))

    def testUnknownKeyword(self):
        self.refused(r"unknown entry 'steps'; did you mean 'step'",
                     ("    checkStep", "    steps 1;\n    checkStep"))


class Propagation(Study):
    """Fake runners: the indicator of a run is a known function of the
    parameters its material change gives (the base case's values
    otherwise), evaluated for every run the study would make."""

    def values(self, s, f):
        """{run name: f(cytoplasm.C10, nucleus.C10)} of every run the
        study adds at its pulse, and 'base'."""
        u = s["uncertainty"]
        base = u["base"]
        out = {"base": f(base["cytoplasm"]["C10"], base["nucleus"]["C10"])}
        for p in ps.uncertaintyPoints(s):
            m = unc.materialsOf(base, p["change"])
            out[p["run"]] = f(m["cytoplasm"]["C10"], m["nucleus"]["C10"])
        return out

    def centred(self, *replace):
        """The study with the calibrated variant at the intervals'
        geometric centres (the log interval symmetric about it)."""
        a, b = math.sqrt(0.131*0.245), math.sqrt(1.58*4.08)
        return self.study(("0.1788 [Pa]", "%r [Pa]" % a),
                          ("2.538 [Pa]", "%r [Pa]" % b), *replace), a, b

    def testLinearOneParameterExact(self):
        # linear in ln p: the interval of I is [I(lo), I(hi)] exactly
        s, a, b = self.centred(("    correlation ((cytoplasm.C10 "
                                "nucleus.C10 -0.60));\n", ""))

        def f(c, n):
            return 3.0 + 2.5*math.log(c)
        v = self.values(s, f)
        r = unc.propagate(s["uncertainty"], v.__getitem__)
        exact = (f(0.245, b) - f(0.131, b))/2
        self.assertAlmostEqual(float(r["about"]), f(a, b), places=12)
        self.assertAlmostEqual(float(r["halfWidth"]), exact, places=12)
        self.assertAlmostEqual(float(r["halfWidthCheck"]), exact, places=12)
        # the other parameter does not move it
        self.assertAlmostEqual(float(r["contributions"][1]), 0, places=12)

    def testLinearTwoParametersAgainstSampling(self):
        # I linear in (ln c, ln n), the parameters log-normal with the
        # intervals' 95 % and correlation -0.6: the 2.5 and 97.5 %
        # percentiles of I sampled (400 000 draws) against I0 +- H
        s, a, b = self.centred()
        bc, bn = 2.0, -7.0

        def f(c, n):
            return 1.0 + bc*math.log(c) + bn*math.log(n)
        v = self.values(s, f)
        u = s["uncertainty"]
        r = unc.propagate(u, v.__getitem__)
        q = 1.959963984540054
        se = np.array([p["halfWidth"] for p in u["parameters"]])/q
        C = np.outer(se, se)*u["correlation"]
        rng = np.random.default_rng(20)
        x = rng.multivariate_normal([math.log(a), math.log(b)], C, 400000)
        I = 1.0 + bc*x[:, 0] + bn*x[:, 1]
        lo, hi = np.percentile(I, [2.5, 97.5])
        self.assertAlmostEqual(float(r["about"]), f(a, b), places=12)
        H = float(r["halfWidth"])
        self.assertLess(abs((hi - lo)/2 - H)/H, 0.01)
        self.assertLess(abs((hi + lo)/2 - f(a, b))/H, 0.01)
        # the closed form of a linear indicator: q sqrt(g^T C g)
        g = np.array([bc, bn])
        self.assertAlmostEqual(H, q*math.sqrt(g @ C @ g), places=10)
        # correlation -0.6 with derivatives of opposite sign widens it
        Hind = math.sqrt(sum(c**2 for c in r["contributions"]))
        self.assertGreater(H, Hind)

    def testLinearInPNotLog(self):
        s = self.study(("cytoplasm.C10 { interval (0.131 0.245) [Pa]; log "
                        "yes; }", "cytoplasm.C10 { interval (0.1288 0.2288)"
                        " [Pa]; log no; }"),
                       ("    correlation ((cytoplasm.C10 nucleus.C10 "
                        "-0.60));\n", ""))

        def f(c, n):
            return 4.0 - 30.0*c
        v = self.values(s, f)
        r = unc.propagate(s["uncertainty"], v.__getitem__)
        self.assertAlmostEqual(float(r["halfWidth"]), 30.0*0.05, places=10)

    def testCurvatureShowsInTheSecondStep(self):
        # forward differences of I = (ln c)^2 about ln c0: g(h) = 2 ln c0 +
        # h, so the two steps give different half-widths, as predicted
        s, a, b = self.centred(("central", "forward"),
                               ("    correlation ((cytoplasm.C10 "
                                "nucleus.C10 -0.60));\n", ""))

        def f(c, n):
            return math.log(c)**2
        v = self.values(s, f)
        r = unc.propagate(s["uncertainty"], v.__getitem__)
        w = math.log(0.245/0.131)/2
        self.assertAlmostEqual(float(r["halfWidth"]),
                               abs(2*math.log(a) + 0.2)*w, places=10)
        self.assertAlmostEqual(float(r["halfWidthCheck"]),
                               abs(2*math.log(a) + 0.1)*w, places=10)

    def testTimeSeries(self):
        # arrays: the band of a series, element by element
        s, a, b = self.centred(("    correlation ((cytoplasm.C10 "
                                "nucleus.C10 -0.60));\n", ""))
        t = np.linspace(0, 1, 5)
        v = self.values(s, lambda c, n: t*math.log(c))
        r = unc.propagate(s["uncertainty"], v.__getitem__)
        np.testing.assert_allclose(r["halfWidth"],
                                   t*math.log(0.245/0.131)/2, atol=1e-12)


class Changes(TempDirTestCase):

    LOG = ("Solid\n    nucleus: C10 2.5379999999999998 Pa, d0 0 1/Pa, mu "
           "862.22000000000003 Pa tau 0.5 s\n    cytoplasm: C10 "
           "0.17879999999999999 Pa, d0 0 1/Pa, mu 107.78 Pa tau 0.01 s\n")

    def testIncludeAndCheck(self):
        self.write("case/constant/solidProperties", SOLID)
        case = os.path.join(self.tmp, "case")
        change = {"nucleus": {"C10": 2.538, "mu1": 862.22},
                  "cytoplasm": {"C10": 0.1788}}
        unc.includeChange(case, change, "p_calibrated")
        from neuronFsi import foamDict
        m = foamDict.read(os.path.join(case, "constant",
                                       "solidProperties"))["materials"]
        self.assertEqual(m["nucleus"]["C10"], 2.538)
        self.assertEqual(m["nucleus"]["tau1"], 0.5)       # kept
        self.assertEqual(m["cytoplasm"]["volumetric"], "mieGruneisen")
        log = self.write("case/log.cellBlastFoam", self.LOG)
        self.assertEqual(unc.solverMaterials(log)["nucleus"]["mu1"], 862.22)
        unc.checkReached(log, change, "p_calibrated")
        with self.assertRaisesRegex(unc.UncertaintyError,
                                    r"p_x: nucleus.C10 = 3.0 was asked for, "
                                    r"the solver reports 2.538"):
            unc.checkReached(log, {"nucleus": {"C10": 3.0}}, "p_x")


if __name__ == "__main__":
    unittest.main()
