"""neuronFsi.pulseStudy: the dictionary checked when read (each bad entry
named), the grid's points and their Allrun options, the digests of a
point's inputs and what differs, the records."""
import math
import os
import sys
import unittest

from fixtures import TempDirTestCase
from neuronFsi import pulseStudy as ps

ALLRUN = """#!/bin/bash
allrunOptions .allrunOptions "$@" <<'OPTIONS'
-pulse    pulse     number(1e-10,0.9]       s
-amplitude  amplitude  number(0,1e9]        Pa
-h        h         number(0,inf)           m
-writeInterval  writeInterval  number(0,inf)  s
-endTime  endTime   number(0,inf)           s
-noPlots  plots     flag=no                 -  noRecord
-noVTK    vtk       flag=no                 -  noRecord
%results log.x
OPTIONS
"""

GOOD = {
    "baseCase": '"base"',
    "baseOptions": "(-h 0.25e-6)",
    "overpressure": "(10e6 30e6)",
    "duration": "(2e-9 5e-9 10e-9)",
    "sampleInterval": "0.5e-9",
    "strainRateWindow": "1e-9",
    "nProcs": "2",
    "thresholds": """{
        axon { indicator strain; value 0.21 [-];
               source "Bain and Meaney 2000, J Biomech Eng"; }
    }""",
}


def loadApp():
    """The application applications/utilities/pulseStudy/pulseStudy.py as a
    module (its functions tested directly), sys.excepthook kept as it was
    (the application installs its own)"""
    import importlib.util
    hook = sys.excepthook
    spec = importlib.util.spec_from_file_location(
        "pulseStudyApp", os.path.join(
            os.path.dirname(__file__), "..", "..", "applications",
            "utilities", "pulseStudy", "pulseStudy.py"))
    app = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(app)
    sys.excepthook = hook
    return app


class Dictionary(TempDirTestCase):

    def setUp(self):
        super().setUp()
        self.case = os.path.join(self.tmp, "study")
        self.write("study/base/Allrun", ALLRUN)
        self.write("study/base/system/controlDict", "endTime 1.5e-7;\n")
        self.write("study/base/constant/thermophysicalProperties", "")
        self.write("study/base/0.orig/p", "")

    def study(self, **changes):
        entries = dict(GOOD)
        entries.update(changes)
        self.write("study/system/pulseStudyDict", "".join(
            "%s %s;\n" % (k, v) if not v.startswith("{") else
            "%s %s\n" % (k, v) for k, v in entries.items()
            if v is not None))
        return ps.read(self.case)

    def refused(self, regex, extra="", **changes):
        with self.assertRaisesRegex(ps.StudyError,
                                    "pulseStudyDict.*" + regex):
            if extra:
                self.write("study/system/pulseStudyDict", extra)
                ps.read(self.case)
            else:
                self.study(**changes)

    def testGood(self):
        s = self.study()
        self.assertEqual(s["overpressure"], [1e7, 3e7])
        self.assertEqual(s["duration"], [2e-9, 5e-9, 1e-8])
        self.assertEqual(s["thresholds"][0]["value"], 0.21)
        self.assertEqual(s["thresholds"][0]["unit"], "-")
        pts = ps.points(s)
        self.assertEqual(len(pts), 6)
        self.assertEqual(pts[0]["label"], "p1e+07_T2e-09")
        self.assertEqual(pts[0]["options"][:2], ["-h", "2.5e-07"])
        self.assertIn("-amplitude", pts[0]["options"])
        self.assertEqual(pts[0]["options"][pts[0]["options"].index(
            "-amplitude") + 1], "10000000")

    def testLabelsOfCloseValues(self):
        # issue 19, adv44 a03 (fix19za): 30e6 and 30.0000001e6 both got
        # p3e+07_T2e-09 (one folder, the first point's record replaced)
        s = self.study(overpressure="(30e6 30.0000001e6)",
                       duration="(2e-9 2.0000004e-9 5e-9)")
        labels = [p["label"] for p in ps.points(s)]
        self.assertEqual(len(set(labels)), 6, labels)
        self.assertIn("p30000000_T2e-09", labels)
        self.assertIn("p30000000.1_T2.0000004e-09", labels)
        # a value far from the others keeps its six digits
        self.assertIn("p30000000.1_T5e-09", labels)

    def testLabelsOfEarlierStudiesKept(self):
        # values that differ in six digits: the labels (folders) of the
        # studies made before, found again
        s = self.study()
        self.assertEqual([p["label"] for p in ps.points(s)],
                         ["p%.6g_T%.6g" % (A, T) for A in s["overpressure"]
                          for T in s["duration"]])
        self.assertEqual(ps.labelTexts([3e7, 3.5e7, 1e-9, 1.234567e7]),
                         {3e7: "3e+07", 3.5e7: "3.5e+07", 1e-9: "1e-09",
                          1.234567e7: "1.23457e+07"})

    def testEmptyGrid(self):
        self.refused("entry 'overpressure' is empty", overpressure="()")

    def testValueTwice(self):
        self.refused("entry 'duration': the value 5e-09 s is given twice",
                     duration="(5e-9 2e-9 5e-9)")

    def testPulseTheLawCannotCarry(self):
        self.refused(r"entry 'overpressure': -1e\+07: option -amplitude = "
                     r".* is outside the valid range \(0, 1e9\] Pa",
                     overpressure="(-10e6 30e6)")
        self.refused(r"entry 'overpressure': 2e\+09: option -amplitude",
                     overpressure="(2e9)")

    def testThresholdWithoutUnit(self):
        self.refused(r"thresholds/axon: value 0.21 has no unit: give it as "
                     r"'value <number> \[-\]'",
                     thresholds='{ axon { indicator strain; value 0.21; '
                                'source "Bain and Meaney 2000, J"; } }')

    def testThresholdWrongUnit(self):
        self.refused(r"thresholds/p: value 1e\+06 \[MPa\]: the unit of "
                     r"indicator pressure is \[Pa\]",
                     thresholds='{ p { indicator pressure; value 1e6 [MPa];'
                                ' source "someone 2000, a journal"; } }')

    def testThresholdOutsideItsIndicator(self):
        # a value reached from the start or never (adv pass st36, st42)
        self.refused(r"thresholds/axon: value -0.21 \[-\] is outside the "
                     r"valid range \(0, 10\] \[-\] of indicator strain",
                     thresholds='{ axon { indicator strain; value -0.21 [-];'
                                ' source "Bain and Meaney 2000, J"; } }')
        self.refused(r"thresholds/p: value 0 \[Pa\] is outside the valid "
                     r"range \[-1e13, 1e13\] \[Pa\] of indicator pressure "
                     r"\(not 0\)",
                     thresholds='{ p { indicator pressure; value 0 [Pa];'
                                ' source "someone 2000, a journal"; } }')
        self.refused(r"value 1e\+06 \[K\] is outside the valid range",
                     thresholds='{ t { indicator temperatureRise; value 1e6 '
                                '[K]; source "someone 2000, a journal"; } }')

    def testThresholdWithoutSource(self):
        self.refused(r"thresholds/axon: no entry 'source' \(no threshold "
                     "without its citation",
                     thresholds='{ axon { indicator strain; value 0.2 [-];'
                                ' } }')

    def testUnknownIndicator(self):
        self.refused(r"thresholds/x: indicator 'stran' unknown; did you "
                     r"mean 'strain'\?",
                     thresholds='{ x { indicator stran; value 0.2 [-];'
                                ' source "a b c"; } }')

    def testUnknownKeyword(self):
        self.refused(r"unknown entry 'durations'; did you mean 'duration'",
                     durations="(1e-9)")

    def testDuplicatedKeyword(self):
        self.refused("entry 'nProcs' is given twice",
                     extra="".join("%s %s;\n" % (k, v) if not
                                   v.startswith("{") else "%s %s\n" % (k, v)
                                   for k, v in GOOD.items())
                     + "nProcs 1;\n")

    def testMissingEntry(self):
        self.refused("no entry 'nProcs'", nProcs=None)

    def testStudyOptionInBase(self):
        self.refused(r"entry 'baseOptions': -pulse is set by the study",
                     baseOptions="(-pulse 1e-9)")

    def testBadBaseOption(self):
        self.refused(r"entry 'baseOptions': unknown option '-hh'",
                     baseOptions="(-hh 1)")

    def testBelowTheReaderNamesTheRange(self):
        # adv47b f22: 4.9e-324 and 1e-300 were refused with "give 0 or a
        # value ... in the entry's valid range": the range unnamed, and 0
        # advised where the entry refuses it
        for tiny in ("4.9e-324", "1e-300", "1e-400"):
            self.refused(r"line 3: entry 'overpressure' = %s Pa is below "
                         r"the smallest magnitude OpenFOAM reads "
                         r"\(1e-300\): it would be read as 0; the entry's "
                         r"valid range is \(0, 1e9\] Pa: give a value in "
                         r"it above 1e-300 \(option -amplitude of "
                         % tiny.replace("+", r"\+"),
                         overpressure="(10e6 %s)" % tiny)
        self.refused(r"entry 'duration' = 1e-300 s is below the smallest "
                     r"magnitude OpenFOAM reads \(1e-300\): it would be "
                     r"read as 0; the entry's valid range is "
                     r"\(1e-10, 0.9\] s: give a value in it \(option "
                     r"-pulse", duration="1e-300")
        self.refused(r"entry 'strainRateWindow' = 1e-300 s is below the "
                     r"smallest magnitude OpenFOAM reads \(1e-300\): it "
                     r"would be read as 0; the entry's valid range is "
                     r"\[5e-10, 1.5e-07\] s: give a value in it$",
                     strainRateWindow="1e-300")
        # an entry whose range the study does not hold: no 0 advised as
        # such, the range not invented
        self.refused(r"entry 'thresholds/axon/value' = 1e-300 is below the "
                     r"smallest magnitude OpenFOAM reads \(1e-300\): it "
                     r"would be read as 0: give a value with 1e-300 < \|x\|"
                     r" <= 1e\+300 in the entry's valid range \(or 0, if "
                     r"the range holds 0\)",
                     thresholds=GOOD["thresholds"].replace(
                         "value 0.21 [-]", "value 1e-300 [-]"))

    def testSampleIntervalNotFinite(self):
        # adv48a h09: "inf is not a positive number": the range and unit
        for v in ("inf", "-inf", "nan", "0"):
            self.refused(r"entry 'sampleInterval' = %s is not a number in "
                         r"the valid range \(0, inf\) s" % v.replace(
                             "+", r"\+"), sampleInterval=v)

    def testSamplesBoundedByTheRun(self):
        # a point's writes at most the solvers' maxWrites (adv pass ps09:
        # sampleInterval 1e-15 s wrote without end); tiny or huge numbers
        # named, not a ZeroDivisionError or OverflowError (ps04, pu04)
        self.refused(r"entry 'sampleInterval' = 1e-15 s is outside the "
                     r"valid range \[1.5e-11, 1.5e-07\] s: a point's run to "
                     r"endTime 1.5e-07 s would write 1.5e\+08 times",
                     sampleInterval="1e-15")
        self.refused(r"entry 'sampleInterval' = 5e-324 s is below the "
                     r"smallest magnitude OpenFOAM reads \(1e-300\): it "
                     r"would be read as 0; the entry's valid range is "
                     r"\(0, inf\) s: give a value in it above 1e-300 "
                     r"\(option -writeInterval",
                     sampleInterval="5e-324")
        self.refused(r"entry 'strainRateWindow' = 1e\+300 s is outside the "
                     r"valid range \[5e-10, 1.5e-07\] s",
                     strainRateWindow="1e300")
        self.refused(r"entry 'sampleInterval' = 1e-06 s is outside",
                     sampleInterval="1e-6")
        self.refused(r"entry 'sampleInterval' = 2e-08 s is outside the valid"
                     r" range \[1e-12, 1e-08\] s",
                     baseOptions="(-endTime 1e-8)", sampleInterval="2e-8",
                     strainRateWindow="2e-8")

    def testBaseWithoutInitialFields(self):
        # adv pass ps30: every point's Allrun failed
        os.remove(os.path.join(self.case, "base", "0.orig", "p"))
        os.rmdir(os.path.join(self.case, "base", "0.orig"))
        self.refused(r"entry 'baseCase': .*base has no folder 0.orig \(the "
                     r"initial fields its Allrun copies to 0\): not a blast "
                     r"case")

    def testWindow(self):
        self.refused(r"entry 'strainRateWindow' = 7.5e-10 s is not a whole"
                     " number of sampleInterval",
                     strainRateWindow="0.75e-9")

    def testNProcs(self):
        """a whole number in [1, the grid's points] (adv29 s15, s16: 1.5
        and 1e12 were said to be outside [1, inf), which holds both)"""
        for n in ("0", "1.5", "1e12", "7", "-1", "two"):
            self.refused(r"entry 'nProcs' = \S+ is not valid: a whole number"
                         r" in \[1, 6\] \(the points run at a time; the "
                         r"grid has 6 points\)", nProcs=n)
        self.assertEqual(self.study(nProcs="6")["nProcs"], 6)
        self.assertEqual(self.study(nProcs="2.0")["nProcs"], 2)

    def testMaxPoints(self):
        """adv46b d52: a grid of 1000 x 1000 values was accepted and
        started (about 140 days of runs, its memory growing): more runs
        than maxPoints (default 1000) are refused before anything runs"""
        over = "(%s)" % " ".join("%de5" % (i + 1) for i in range(1001))
        self.refused(r"the study has 3003 runs \(entry 'overpressure': 1001 "
                     r"values x entry 'duration': 3 values\), more than entry"
                     r" 'maxPoints' = 1000 \(its default\).*Nothing was run",
                     overpressure=over, nProcs="1")
        self.refused(r"the study has 6 runs .*more than entry 'maxPoints' = "
                     r"5: ", maxPoints="5")
        for v in ("0", "1.5", "inf", "many"):
            self.refused(r"entry 'maxPoints' = \S+ is not valid: a whole "
                         r"number in \[1, inf\)", maxPoints=v)
        self.assertEqual(self.study(maxPoints="6")["nProcs"], 2)

    def testNoBase(self):
        self.refused(r"entry 'baseCase': .*absent has no Allrun",
                     baseCase='"absent"')


class Records(TempDirTestCase):

    def read(self, name):
        with open(os.path.join(self.tmp, name)) as f:
            return f.read()

    def testDigestsAndDifferences(self):
        self.write("base/a", "1")
        self.write("base/sub/b", "2")
        d = ps.fileDigests(os.path.join(self.tmp, "base"))
        self.assertEqual(sorted(d), ["a", "sub/b"])
        p = {"options": ["-h", "1", "-writeInterval", "5e-10"]}
        now = ps.inputs(d, p)
        self.assertEqual(ps.differences(now, now), [])
        self.write("base/sub/b", "3")
        d2 = ps.fileDigests(os.path.join(self.tmp, "base"))
        diff = ps.differences(now, ps.inputs(d2, p))
        self.assertEqual(diff[0][0], "baseCase")
        self.assertIn("sub/b", diff[0][1])
        q = {"options": ["-h", "2", "-writeInterval", "5e-10"]}
        self.assertEqual(ps.differences(now, ps.inputs(d, q))[0][0],
                         "baseOptions")
        q = {"options": ["-h", "1", "-writeInterval", "1e-9"]}
        self.assertEqual(ps.differences(now, ps.inputs(d, q))[0][0],
                         "sampleInterval")

    def testOutsideInputs(self):
        """what the base case reads from outside it, as OpenFOAM reads it,
        is a point's input (adv43 k23: a material set #included from
        outside the base case changed between two runs of a study; the
        finished point kept, the new one run with the other set, one
        table of two models): an #include'd file (to its 17th digit), a
        file it #includes in turn, an #includeEtc'd one, a boundary
        condition's table; a record without them (an earlier build's)
        refused"""
        header = ("FoamFile { version 2.0; format ascii; class dictionary;"
                  " object %s; }\n")
        out = os.path.join(self.tmp, "outside")
        self.write("outside/set", "C10 166.67;\n#include \"%s/deeper\"\n"
                   % out)
        self.write("outside/deeper", "d0 9.5e-10;\n")
        self.write("outside/pulse.dat", "(\n(0 1e5)\n(1e-9 3e7)\n)\n")
        self.write("base/Allrun", "#include \"%s/set\"\n" % out)
        self.write("base/constant/solidProperties", header % "solidProperties"
                   + "materials { membrane { #include \"%s/set\" } }\n"
                   "#sinclude \"solidProperties.allrun\"\n" % out)
        self.write("base/system/controlDict", header % "controlDict"
                   + "#includeEtc \"caseDicts/meshQualityDict\"\n")
        self.write("base/0.orig/p", header % "volScalarField" + """
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 1e5;
boundaryField
{
    top { type uniformFixedValue; uniformValue tableFile;
          uniformValueCoeffs { file "%s/pulse.dat"; } }
    inner { type uniformFixedValue; uniformValue tableFile;
          uniformValueCoeffs { file "$FOAM_CASE/constant/inner.dat"; } }
}
""" % out)
        self.write("base/constant/inner.dat", "(\n(0 1e5)\n)\n")
        base = os.path.join(self.tmp, "base")
        first = ps.outsideInputs(base)
        self.assertEqual(sorted(first), sorted([
            "%s/set (included by constant/solidProperties)" % out,
            "%s/deeper (included by constant/solidProperties)" % out,
            "constant/solidProperties as OpenFOAM reads it (foamDictionary "
            "-expand)",
            "system/controlDict as OpenFOAM reads it (foamDictionary "
            "-expand)",
            "%s/pulse.dat (entry 'file' of 0.orig/p)" % out]))
        p = {"options": ["-h", "1"]}
        before = ps.inputs({}, p, first)
        self.assertEqual(ps.outsideInputs(base), first)
        self.assertEqual(ps.differences(before, ps.inputs({}, p, first)), [])
        for name, old, new, changed in (
                ("set", "166.67", "166.6700001", ["/set (included", "as "
                                                  "OpenFOAM reads it"]),
                ("deeper", "9.5e-10", "9.6e-10", ["/deeper (included"]),
                ("pulse.dat", "3e7", "4e7", ["/pulse.dat (entry 'file' of "
                                             "0.orig/p)"])):
            text = self.read("outside/" + name)
            self.write("outside/" + name, text.replace(old, new))
            diff = ps.differences(before, ps.inputs({}, p, ps.outsideInputs(
                base)))
            self.assertEqual(diff[0][0], "baseCase")
            self.assertIn("what it reads from outside its folder differs "
                          "from what the point ran with: %s" % out,
                          diff[0][1])
            for c in changed:
                self.assertIn(c, diff[0][1])
            self.write("outside/" + name, text)
            self.assertEqual(ps.outsideInputs(base), first)
        # a comment, the layout or a number's spelling is no change, as
        # in the solvers' record (adv44 a40 (b), (c))
        text = self.read("outside/set")
        self.write("outside/set", "// a comment\n" + text.replace(
            "166.67", "1.6667e2").replace(";", " ;"))
        self.assertEqual(ps.outsideInputs(base), first)
        self.write("outside/set", text)
        # the etc file: as OpenFOAM reads the controlDict (to 17 digits)
        etc = ps.outsideInputs(base)
        self.write("base/system/controlDict", header % "controlDict"
                   + "#includeEtc \"caseDicts/meshQualityDict\"\n"
                   "maxNonOrtho 64.9999999;\n")
        self.assertNotEqual(ps.outsideInputs(base), etc)
        # a record of an earlier build (no 'outside'): refused
        old = ps.inputs({}, p)
        diff = ps.differences(old, before)
        self.assertIn("(not in the point's record: a record of an earlier "
                      "build)", diff[0][1])
        # nothing read from outside: nothing to compare
        self.assertEqual(ps.differences(old, ps.inputs({}, p, {})), [])

    def testRecord(self):
        path = os.path.join(self.tmp, "result.json")
        self.assertIsNone(ps.readRecord(path))
        ps.writeRecord(path, {"inputs": {}, "series": {"x": [1.0,
                                                             math.nan]}})
        self.assertEqual(ps.readRecord(path)["series"]["x"], [1.0, None])
        # written atomically: a cut record is damaged, refused, kept
        self.write("result.json", '{"inputs": {}, "seri')
        with self.assertRaisesRegex(ps.StudyError, "result.json: the "
                                    "point's record is damaged \\(not JSON"):
            ps.readRecord(path)
        self.assertEqual(self.read("result.json"), '{"inputs": {}, "seri')

    def point(self, A=3e7, T=2e-9):
        return {"label": "p%.6g_T%.6g" % (A, T), "overpressure": A,
                "duration": T}

    def record(self, point):
        return dict(point, inputs={"options": ["-amplitude", repr(
            point["overpressure"])]}, wall=4.15, cpu=3.0,
            series={"t": [0.0, 5e-10], "targets": {"nucleus": {
                "pressure": [0.0, 9.34e-07]}}})

    def testRecordValuesVerified(self):
        """the record carries the digest of its values, verified on every
        read (adv29 sr05: the wall time 4.15 -> 9.15 s; sr05c: a series
        x1000, valid JSON both, were used as they were)"""
        path = os.path.join(self.tmp, "result.json")
        p = self.point()
        ps.writeRecord(path, self.record(p))
        self.assertEqual(ps.readRecord(path, p)["wall"], 4.15)
        good = self.read("result.json")
        for old, new in (("4.15", "9.15"), ("9.34e-07", "0.000934"),
                         ('"cpu": 3.0', '"cpu": 3.0, "extra": 1')):
            self.assertIn(old, good)
            self.write("result.json", good.replace(old, new, 1))
            with self.assertRaisesRegex(
                    ps.StudyError, "result.json: the point's record is "
                    "damaged \\(the digest of its values is [0-9a-f]{64}, "
                    "the one it carries [0-9a-f]{64}: a value was changed"
                    ".*Nothing was run: move the file away"):
                ps.readRecord(path, p)
        # a record written before the digest: not verifiable, refused
        import json
        r = json.loads(good)
        del r["digest"]
        self.write("result.json", json.dumps(r))
        with self.assertRaisesRegex(ps.StudyError, "damaged \\(no entry "
                                    "digest; a record written before"):
            ps.readRecord(path, p)

    def testAnotherPointsRecord(self):
        """a record copied over another point's is said to be that
        point's (adv29 sr07: said to be a changed 'baseOptions')"""
        path = os.path.join(self.tmp, "result.json")
        ps.writeRecord(path, self.record(self.point(1e7)))
        with self.assertRaisesRegex(
                ps.StudyError, "result.json is the record of another point "
                "\\(p1e\\+07_T2e-09: overpressure 10000000.0 Pa, duration "
                "2e-09 s\\), not of p3e\\+07_T2e-09 \\(overpressure 3e\\+07 "
                "Pa, duration 2e-09 s\\)"):
            ps.readRecord(path, self.point())

    def testTemporaryTablesOfAKilledStudyRemoved(self):
        """a study killed while writing its tables left table.h5.tmp (and
        table.csv.tmp, uncertainty.csv.tmp) for good: the next study
        removes them, and only them"""
        app = loadApp()
        out = os.path.join(self.tmp, "out")
        for name in ("table.h5.tmp", "table.csv.tmp", "uncertainty.csv.tmp",
                     "table.h5", "notes.tmp", "table.h5.tmp1"):
            self.write("out/" + name, "x\n")
        removed = app.removeTemporaryFiles(out)
        self.assertEqual(sorted(os.path.basename(p) for p in removed),
                         ["table.csv.tmp", "table.h5.tmp",
                          "uncertainty.csv.tmp"])
        self.assertEqual(sorted(os.listdir(out)),
                         ["notes.tmp", "table.h5", "table.h5.tmp1"])
        self.assertEqual(app.removeTemporaryFiles(out), [])

    def testBaseCopyWithTheUsersFileRefused(self):
        """the study's copy of the base case (made again at every run)
        holding a file the base case does not is refused, nothing removed
        (adv43 k20: the user's notes.md in it was removed by every run)"""
        app = loadApp()
        self.write("base/constant/x", "base\n")
        self.write("out/base/constant/x", "base\n")
        base = os.path.join(self.tmp, "base")
        out = os.path.join(self.tmp, "out")
        # the copy as the study left it: made again, nothing said
        staging, _ = app.prepareBase({"base": base}, out)
        self.assertEqual(sorted(os.listdir(staging)), ["constant"])
        self.write("out/base/notes.md", "# my notes\n")
        self.write("out/base/constant/mine/a.txt", "mine\n")
        with self.assertRaisesRegex(
                ps.StudyError, "holds files the base case does not: "
                "constant/mine/a.txt, notes.md\\. Nothing was removed"):
            app.prepareBase({"base": base}, out)
        with open(os.path.join(out, "base", "notes.md")) as f:
            self.assertEqual(f.read(), "# my notes\n")

    def testInterruptedPointKeepsTheUsersFiles(self):
        """a point interrupted earlier is run again from the start: a
        record's temporary file is removed, its case copy moved aside
        (case.interrupted, case.interrupted1, ...: adv43 k21, a file of the
        user's in it was removed with it), a file of the user's in the
        point's folder is kept (adv42 g13: the whole folder was removed
        with the user's notes.md in it)"""
        import io
        from contextlib import redirect_stdout
        from neuronFsi import caseRuns
        app = loadApp()
        staging = self.write("staging/Allrun", "#!/bin/sh\nexit 3\n")
        os.chmod(staging, 0o755)
        staging = os.path.dirname(staging)
        self.write("staging/constant/x", "base\n")
        folder = os.path.join(self.tmp, "points", "p1")
        self.write("points/p1/case/constant/x", "the killed run's\n")
        self.write("points/p1/case/1e-09/p", "the killed run's\n")
        self.write("points/p1/case/notes.txt", "my case notes\n")
        self.write("points/p1/case/postProcessing/fsi/0/notes.txt",
                   "my fsi notes\n")
        self.write("points/p1/result.json.tmp123", "{")
        self.write("points/p1/notes.md", "# my notes\n")
        os.makedirs(os.path.join(folder, "myPlots"))
        self.write("points/p1/myPlots/a.png", "png")
        out = io.StringIO()
        with redirect_stdout(out), self.assertRaisesRegex(
                caseRuns.RunError, "exit 3"):
            app.runPoint({}, staging, {"label": "p1", "options": []}, {},
                         folder, False)
        self.assertEqual(sorted(os.listdir(folder)),
                         ["case", "case.interrupted", "myPlots", "notes.md"])
        with open(os.path.join(folder, "notes.md")) as f:
            self.assertEqual(f.read(), "# my notes\n")
        self.assertTrue(os.path.isfile(
            os.path.join(folder, "myPlots", "a.png")))
        self.assertFalse(os.path.exists(os.path.join(folder, "case",
                                                     "1e-09")))
        with open(os.path.join(folder, "case", "constant", "x")) as f:
            self.assertEqual(f.read(), "base\n")
        self.assertIn("p1: run again from the start; kept in %s (not the "
                      "study's): myPlots, notes.md" % folder, out.getvalue())
        self.assertEqual(app.pointFiles(folder),
                         ([], ["myPlots", "notes.md"]))
        # the interrupted run's case copy moved aside whole with the user's
        # files in it (adv43 k07, k20 (c), k21: removed with it)
        aside = os.path.join(folder, "case.interrupted")
        with open(os.path.join(aside, "postProcessing", "fsi", "0",
                               "notes.txt")) as f:
            self.assertEqual(f.read(), "my fsi notes\n")
        with open(os.path.join(aside, "notes.txt")) as f:
            self.assertEqual(f.read(), "my case notes\n")
        self.assertTrue(os.path.isfile(os.path.join(aside, "1e-09", "p")))
        self.assertIn("p1: run again from the start; the case copy of its "
                      "interrupted run (and any file you put in it) moved "
                      "to %s: the study does not read it again" % aside,
                      out.getvalue())
        # again: the next free name, the first copy kept
        with redirect_stdout(out), self.assertRaisesRegex(
                caseRuns.RunError, "exit 3"):
            app.runPoint({}, staging, {"label": "p1", "options": []}, {},
                         folder, False)
        self.assertEqual(sorted(os.listdir(folder)),
                         ["case", "case.interrupted", "case.interrupted1",
                          "myPlots", "notes.md"])
        self.assertTrue(os.path.isfile(os.path.join(aside, "notes.txt")))


if __name__ == "__main__":
    unittest.main()
