"""neuronFsi.bench, what the benchmark scripts share, on small level
folders: options, logged and timed runs, the commit stamps and the
report's first words, coupling statistics, the report file."""
import datetime
import io
import math
import os
import subprocess
import sys
import unittest
from contextlib import redirect_stderr, redirect_stdout

from fixtures import TempDirTestCase
from neuronFsi import bench, logs, resultDigest

COUPLING = ("# FSI coupling (robin)\n"
            "# time [s]  dt [s]  iterations  residual [-]  converged\n"
            "1e-10 1e-10 2 1e-7 1\n"
            "3e-10 2e-10 5 1e-3 0\n"
            "7e-10 4e-10 3 1e-7 1\n")

START = datetime.datetime(2026, 9, 21, 14, 12, 30)


class Bench(TempDirTestCase):

    def testArgumentsAndReportPath(self):
        ap = bench.arguments("One line.\n\nMore.", "/o", "small sizes")
        self.assertEqual(ap.description, "One line.")
        self.assertIn("small sizes", ap.format_help())
        args = ap.parse_args([])
        self.assertEqual((args.quick, args.out, args.doc),
                         (False, "/o", None))
        self.assertEqual(bench.reportPath(args.doc, args.quick, args.out,
                                          "/r", "x.md"),
                         "/r/docs/benchmarks/x.md")
        args = ap.parse_args(["--quick", "--out", "/q"])
        self.assertEqual(bench.reportPath(args.doc, args.quick, args.out,
                                          "/r", "x.md"), "/q/x.md")
        args = ap.parse_args(["--quick", "--doc", "/d/y.md"])
        self.assertEqual(bench.reportPath(args.doc, args.quick, args.out,
                                          "/r", "x.md"), "/d/y.md")

    def parseError(self, ap, argv):
        err = io.StringIO()
        with redirect_stderr(err), self.assertRaises(SystemExit) as cm:
            bench.parse(ap, argv)
        self.assertEqual(cm.exception.code, 2)
        return err.getvalue()

    def testParseChecksTheOptions(self):
        # a bad option of a benchmark was a traceback after minutes of
        # runs, or unnoticed (issue 19, bk06, bk07)
        ap = bench.arguments("B.", os.path.join(self.tmp, "o"))
        ap.add_argument("--factors", default=None)
        ap.add_argument("--sizes", default="40 60")
        ap.add_argument("--endTime", type=float, default=None)
        ap.add_argument("--near", type=float, default=0)
        a = bench.parse(ap, ["--factors", "1.4 1", "--near", "0"])
        self.assertEqual((a.factors, a.near), ("1.4 1", 0))
        file = os.path.join(self.tmp, "f")
        with open(file, "w") as f:
            f.write("x\n")
        for argv, msg in (
                (["--factors", "1 abc"], "--factors '1 abc': 'abc' is not a "
                 "positive number"),
                (["--sizes", "40 2.5"], "'2.5' is not a positive whole"),
                (["--endTime", "nan"], "--endTime nan: not a finite number "
                 "in the valid range (0, inf)"),
                (["--endTime", "-1"], "valid range (0, inf)"),
                (["--near", "-1"], "--near -1.0: not a finite number in the "
                 "valid range [0, inf)"),
                (["--out", os.path.join(file, "o")], "is a file, not a "
                 "folder"),
                (["--doc", self.tmp], "a folder; the option names a report"),
                (["--quick", "--quick"], "option --quick is given 2 times"),
                (["--endTime", "5e-324"], "below the smallest magnitude")):
            self.assertIn(msg, self.parseError(ap, argv), argv)

    def testMainNamesTheProjectsErrors(self):
        r = subprocess.run(
            [sys.executable, "-c", "from neuronFsi import bench, logs\n"
             "def m():\n    raise logs.LogError('/x/log.checkMesh: gone')\n"
             "bench.main(m)"], capture_output=True, text=True,
            env=dict(os.environ))
        self.assertEqual(r.returncode, 1)
        self.assertIn("error: /x/log.checkMesh: gone", r.stderr)
        self.assertNotIn("Traceback", r.stderr)

    def testFoamEnvSourcesTheBashrc(self):
        self.write("etc/bashrc", "export NEURONFSI_TEST='a=b c'\n"
                   "echo noise\n")
        env = bench.foamEnv(self.tmp)
        self.assertEqual(env["NEURONFSI_TEST"], "a=b c")
        self.assertEqual(env["PATH"], os.environ["PATH"])
        self.write("etc/bashrc", "return 1\n")
        with self.assertRaises(subprocess.CalledProcessError):
            bench.foamEnv(self.tmp)

    def testRunLoggedAndFail(self):
        res = bench.runLogged(["sh", "-c", "echo out; echo err >&2; exit 3"],
                              self.tmp, os.environ, "log.x")
        self.assertEqual(res.returncode, 3)
        with open(os.path.join(self.tmp, "log.x")) as f:
            self.assertEqual(sorted(f.read().split()), ["err", "out"])
        shown = io.StringIO()
        with redirect_stdout(shown), \
                self.assertRaisesRegex(RuntimeError, "^x failed$"):
            bench.fail(res, "x failed")
        self.assertEqual(sorted(shown.getvalue().split()), ["err", "out"])

    def testRunTimedLeavesTimeLogAndLoad(self):
        bench.runTimed(self.tmp, ["sh", "-c", "echo solver; exit 2"],
                       os.environ, "log.solver")
        with open(os.path.join(self.tmp, "log.solver")) as f:
            self.assertEqual(f.read(), "solver\n")
        r = logs.timeV(os.path.join(self.tmp, "log.time"))
        self.assertEqual(r["status"], 2)
        self.assertGreater(r["rss"], 0)
        load = bench.loadAverage(self.tmp)
        self.assertEqual(len(load), 3)
        self.assertTrue(all(x >= 0 for x in load))

    def testLoadAverage(self):
        self.assertTrue(all(math.isnan(x) for x in
                            bench.loadAverage(self.tmp)))
        self.assertEqual(bench.loadColumn(bench.loadAverage(self.tmp)), "-")
        self.write("log.load", "1.25 0.50 0.10\n")
        self.assertEqual(bench.loadAverage(self.tmp), [1.25, 0.5, 0.1])
        self.assertEqual(bench.loadColumn([1.254, 0.5, 0.1]), "1.25")

    def testCommitOfACheckout(self):
        git = ["git", "-c", "user.name=t", "-c", "user.email=t@t"]
        for c in (["init", "-q"], ["commit", "-q", "--allow-empty", "-m",
                                   "x"]):
            subprocess.run(git + c, cwd=self.tmp, check=True)
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"],
                              cwd=self.tmp, stdout=subprocess.PIPE,
                              text=True).stdout.strip()
        self.assertEqual(bench.commit(self.tmp), head)
        paths, text = bench.measuredCode("blast")
        self.assertEqual(paths, ["src", "applications", "tutorials/blast",
                                 "bench/blast"])
        self.assertEqual(text, "src/, applications/, tutorials/blast or "
                         "bench/blast")
        self.write("docs/a.md", "x\n")
        self.assertEqual(bench.uncommitted(self.tmp, paths), "")
        self.write("bench/blast/b.py", "x\n")
        self.assertEqual(bench.uncommitted(self.tmp, paths),
                         "?? bench/blast/")

    def testCommitStamps(self):
        a, b = (os.path.join(self.tmp, n) for n in ("a", "b"))
        for d in (a, b):
            os.makedirs(d)
        with self.assertRaisesRegex(RuntimeError, r"unknown or not one "
                                    r"\(set\(\)\); give --commit"):
            bench.stampedCommit([a, b])
        self.assertEqual(bench.stampedCommit([a, b], "fed4321"),
                         ("fed4321", ""))
        bench.stampCommit(a, "abc1234", "")
        self.assertEqual(bench.stampedCommit([a, b]), ("abc1234", ""))
        bench.stampCommit(b, "abc1234", " M src/x.C")
        with self.assertRaisesRegex(RuntimeError, "not one"):
            bench.stampedCommit([a, b])
        bench.stampCommit(a, "abc1234", "yes")
        self.assertEqual(bench.stampedCommit([a, b]), ("abc1234", "yes"))
        self.assertEqual(bench.stampedCommit([a, b], "fed4321"),
                         ("fed4321", ""))

    def testRunPeriod(self):
        stamps = {"a/first": 1_790_000_000, "b/first": 1_790_000_100,
                  "a/last": 1_790_003_000, "b/last": 1_790_002_000}
        for name, t in stamps.items():
            os.utime(self.write(name, ""), (t, t))
        start, end = bench.runPeriod(
            [os.path.join(self.tmp, d, "first") for d in "ab"],
            [os.path.join(self.tmp, d, "last") for d in "ab"])
        self.assertEqual(start, datetime.datetime(2026, 9, 21, 14, 13, 20))
        self.assertEqual((end - start).total_seconds(), 3000)

    def testWrittenBy(self):
        self.assertEqual(bench.writtenBy("bench/x.py", START, "abc1234"),
                         "Written by `bench/x.py` on 2026-09-21 14:12 UTC, "
                         "commit abc1234")
        self.assertEqual(bench.writtenBy("bench/x.py", START, "abc1234",
                                         "quick", "yes"),
                         "Written by `bench/x.py` (quick) on 2026-09-21 "
                         "14:12 UTC, commit abc1234 (with uncommitted "
                         "changes)")
        end = START + datetime.timedelta(seconds=4030.4)
        text = bench.levelsWrittenBy("bench/x.py", "full", START, end,
                                     "abc1234", " M src/a.C", "src/",
                                     False)
        self.assertEqual(text, "Written by `bench/x.py` (full) on "
                         "2026-09-21 14:12 UTC, commit abc1234 (with "
                         "uncommitted changes in src/), 4030 s in all, "
                         "the levels one after the other")
        again = bench.levelsWrittenBy("bench/x.py", "full", START, end,
                                      "abc1234", " M src/a.C", "src/",
                                      True)
        self.assertRegex(again[len(text):], r"^ \(this text regenerated "
                         r"with --reportOnly on \d{4}-\d\d-\d\d \d\d:\d\d "
                         r"UTC from the same level cases\)$")

    def testCouplingStatistics(self):
        # a hand-made log (no run's digests): measured as it is
        resultDigest.measuring("-acceptHandMade", True)
        self.addCleanup(resultDigest.measuring, None, False)
        self.write("postProcessing/fsi/0/coupling.dat", COUPLING)
        s = bench.couplingStatistics(self.tmp)
        self.assertEqual(s, dict(steps=3, itMean=10/3, itMax=5,
                                 notConverged=1, dtMin=1e-10, dtMax=4e-10,
                                 dtMedian=2e-10))

    def testWriteReport(self):
        doc = os.path.join(self.tmp, "new", "report.md")
        shown = io.StringIO()
        with redirect_stdout(shown):
            bench.writeReport(doc, ["# T", "", "| a |"])
        with open(doc) as f:
            self.assertEqual(f.read(), "# T\n\n| a |")
        self.assertEqual(shown.getvalue(), f"# T\n\n| a |\nwrote {doc}\n")


class FluidBenchRunsTwice(TempDirTestCase):
    """bench/fluid/run.py runs a Sod case more than once (the repeats of
    the timings, then the perf profile): each run starts from the initial
    time (adv33/adv34 bn10: the profile continued the finished case from
    its end time, rhoRiemannFoam refused, the report said only '(perf
    record failed: no profile)')."""

    def testRepeatAndProfileOfAFinishedCase(self):
        import importlib.util
        import shutil
        if not shutil.which("rhoRiemannFoam"):
            self.skipTest("rhoRiemannFoam not built / not on PATH")
        spec = importlib.util.spec_from_file_location(
            "fluidBench", os.path.join(os.path.dirname(__file__), "..", "..",
                                       "bench", "fluid", "run.py"))
        run = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(run)
        case = os.path.join(self.tmp, "sod")
        with redirect_stdout(io.StringIO()):
            run.sod_case(case, 200, 1, 5)
            for _ in range(2):
                r = run.run_solver(case, "rhoRiemannFoam")
                self.assertEqual(len(r["cpu"]), 5)
            if shutil.which("perf"):
                md = []
                run.profile(case, md)
                self.assertNotIn("failed", "\n".join(md))
                self.assertRegex(md[0], r"\| share of CPU samples \| "
                                 r"library \|")


if __name__ == "__main__":
    unittest.main()
