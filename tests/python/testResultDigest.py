"""neuronFsi.resultDigest: our text results verified against the digests
their writers recorded before they are measured (issue 19 class 5; adv52
p06b, p31), and options.readRefusal: a reader's look at a user's file
before it opens it (adv52 p10)."""
import os
import subprocess
import sys

from fixtures import TempDirTestCase
from neuronFsi import options, planeWave, postProcessing, resultDigest


def fnv(data):
    return resultDigest.hexText(resultDigest.add(resultDigest.BASIS, data))


class Digest(TempDirTestCase):

    def tearDown(self):
        resultDigest.measuring("-acceptHandMade", False)

    def testDigestIsThatOfFileDigest(self):
        """FNV-1a 64 of the C++ side (fileDigest.H): the known values."""
        self.assertEqual(fnv(b""), "cbf29ce484222325")
        self.assertEqual(fnv(b"a"), "af63dc4c8601ec8c")

    def testSidecarNamesTheFirstEditedLine(self):
        """A file written with its sidecar is taken; one digit changed on
        line 3 is refused naming the file and line 3; a cut file names the
        cut; the explicit option measures it as it is."""
        p = self.write("peaks.dat", "# label time\nC1 1\nC2 2\nC3 3\n")
        resultDigest.writeSidecar(p)
        self.assertIsNone(resultDigest.check(p))
        self.write("peaks.dat", "# label time\nC1 1\nC2 3\nC3 3\n")
        with self.assertRaisesRegex(resultDigest.DigestError,
                                    r"peaks\.dat, line 3: the file is not as "
                                    r"the run wrote it .*-acceptHandMade"):
            resultDigest.check(p)
        self.write("peaks.dat", "# label time\nC1 1\n")
        with self.assertRaisesRegex(resultDigest.DigestError,
                                    r"was cut after it was written"):
            resultDigest.check(p)
        resultDigest.measuring("--accept-hand-made", True)
        self.assertIsNone(resultDigest.check(p))

    def testDigestWithALeadingZero(self):
        """fileDigest::hex writes no leading zeros (one digest in 16 has
        15 digits or fewer: adv53's regressions (1), (2) on fix19j's merge,
        every finished indentation refused): such a line, and the same
        digest written with its zeros, are taken."""
        rows, h, i = ["# t F\n"], resultDigest.add(resultDigest.BASIS,
                                                   b"# t F\n"), 0
        while len(resultDigest.hexText(h)) == 16:
            i += 1
            rows.append("%d %d\n" % (i, 2*i))
            h = resultDigest.add(h, rows[-1].encode())
        self.assertLess(len(resultDigest.hexText(h)), 16)
        p = self.write("force.dat", "".join(rows))
        resultDigest.writeSidecar(p)
        self.assertIsNone(resultDigest.check(p))
        with open(p + resultDigest.SUFFIX) as f:
            lines = f.read().splitlines()
        with open(p + resultDigest.SUFFIX, "w") as f:
            f.write("".join("%s %016x\n" % (n, int(d, 16)) for n, d in
                            (x.split() for x in lines)))
        self.assertIsNone(resultDigest.check(p))

    def testKilledRunsSidecarCutInALine(self):
        """A run killed while its sidecar's last line was written (adv53
        l32's killed indentation): that line is not a damage; the rows it
        would cover are the uncovered tail."""
        p = self.write("force.dat", "# t F\n1 2\n3 4\n")
        resultDigest.writeSidecar(p)
        with open(p + resultDigest.SUFFIX) as f:
            text = f.read()
        with open(p + resultDigest.SUFFIX, "w") as f:
            f.write(text[:-7])
        self.assertEqual(resultDigest.check(p), 3)

    def testHandMadeFileRefusedUnlessAccepted(self):
        p = self.write("reference.dat", "# t p\n0 1\n")
        with self.assertRaisesRegex(resultDigest.DigestError,
                                    r"reference\.dat has no digest of the run "
                                    r"that wrote it .* give -acceptHandMade"):
            planeWave.readReference(p)
        resultDigest.measuring("-acceptHandMade", True)
        self.assertIsNone(resultDigest.check(p))

    def testRowAppendedAfterTheDigests(self):
        """adv54 n01: a row appended to a file whose sidecar covers every
        row the run wrote (peaks.dat, a reference written whole) is not
        the run's: refused naming its line; a '#' note after the rows and
        a row a later segment replaces (rows) are not measured rows"""
        p = self.write("postProcessing/indentation/peaks.dat",
                       "# label time depth force\nC1,i 1 2 3\n")
        resultDigest.writeSidecar(p)
        with open(p, "a") as f:
            f.write("# a note\n")
        resultDigest.uncoveredRows(p, resultDigest.check(p))
        with open(p, "a") as f:
            f.write("C1,i 2.06 8e-07 1.5e-09\n")
        line = resultDigest.check(p)
        self.assertEqual(line, 3)
        with self.assertRaisesRegex(resultDigest.DigestError,
                                    r"peaks.dat, line 4: the rows from this "
                                    r"line on are not covered .* give "
                                    r"-acceptHandMade"):
            resultDigest.uncoveredRows(p, line)
        resultDigest.uncoveredRows(p, line, rows=[2])
        resultDigest.measuring("-acceptHandMade", True)
        resultDigest.uncoveredRows(p, line)

    def testLargeFileReadRecordByRecord(self):
        """adv53 l31 (e): a 1 GiB reference.dat of zeros (below the table
        limit) was read whole (1.08 GB) before its line 1 was refused; now
        record by record: the refusal after the first record's bytes, a
        small memory (a child process's maximum resident size)"""
        p = self.write("ref.dat", "# t p\n0 1\n")
        resultDigest.writeSidecar(p)
        os.truncate(p, 256 << 20)
        with open(p, "r+b") as f:
            f.write(b"\0"*16)          # zeros from its first byte on
        code = ("import resource, sys\n"
                "from neuronFsi import resultDigest\n"
                "try:\n    resultDigest.check(sys.argv[1])\n"
                "except resultDigest.DigestError as e:\n    print(e)\n"
                "print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)\n")
        r = subprocess.run([sys.executable, "-c", code, p],
                           capture_output=True, text=True)
        out = r.stdout.split("\n")
        self.assertRegex(out[0], r"ref.dat, line 1: the file is not as the "
                                 r"run wrote it")
        self.assertLess(int(out[1]), 150000, "maximum resident size [KiB]")

    def testIndentationResultsOfAnotherRun(self):
        """adv54 n03 (a): force.dat and peaks.dat of another run copied
        with their digests into a case whose solid.h5 is its own: refused
        naming the runs; the same run's files are read"""
        import h5py
        from neuronFsi import indentationPlots
        d = os.path.join(self.tmp, "postProcessing", "indentation")
        for name, text in (("force.dat", "# time [s]  depth [m]  force [N]"
                            "  stage\n0 0 0 A\n1 1e-7 1e-9 A\n"),
                           ("peaks.dat", "# label  time [s]  depth [m]  "
                            "force [N]\nC1,i 1 1e-7 1e-9\n")):
            p = self.write("postProcessing/indentation/" + name,
                           "# run aaaa\n" + text)
            resultDigest.writeSidecar(p)
        with h5py.File(os.path.join(d, "solid.h5"), "w") as f:
            f.attrs["runId"] = b"aaaa"
        rows, peaks = indentationPlots.read(self.tmp)
        self.assertEqual(len(rows), 2)
        with h5py.File(os.path.join(d, "solid.h5"), "w") as f:
            f.attrs["runId"] = b"bbbb"
        with self.assertRaisesRegex(indentationPlots.IndentationPlotError,
                                    r"of different runs: force.dat names run "
                                    r"aaaa; peaks.dat names run aaaa; "
                                    r"solid.h5 names run bbbb"):
            indentationPlots.read(self.tmp)

    def testLogAgainstCommitMarkers(self):
        """A probe log of postProcessing/ checked against the commit
        markers' "log" lines (restartLogs.H): an edit between two commits
        names the first line of that interval; rows after the last
        commit are returned as not covered."""
        rows = b"# Probe 0 (0 0 0)\n# Time p\n1 10\n2 20\n3 30\n4 40\n"
        log = os.path.join(self.tmp, "postProcessing", "probes", "0", "p")
        os.makedirs(os.path.dirname(log))
        with open(log, "wb") as f:
            f.write(rows + b"5 50\n")
        first = rows.index(b"3 30")
        for t, n in (("2", first), ("4", len(rows))):
            self.write("%s/.writeCommitted" % t,
                       "digest fnv1a64 ended\nlog %s %d postProcessing/"
                       "probes/0/p\nend\n" % (fnv(rows[:n]), n))
        self.assertEqual(resultDigest.check(log), 7)
        # the row after the last commit: refused (appended, or a run
        # stopped or going on: adv54 n02), measured with the script's
        # option for a run so far (planeWave -partial)
        with self.assertRaisesRegex(resultDigest.DigestError,
                                    r"probes/0/p, line 7: the rows from "
                                    r"this line on are not covered"):
            postProcessing.series(self.tmp, "probes/p", verify=True)
        resultDigest.measuringPartial(True)
        self.addCleanup(resultDigest.measuringPartial, False)
        data = postProcessing.series(self.tmp, "probes/p", verify=True)
        self.assertEqual(len(data), 5)
        resultDigest.measuringPartial(False)
        with open(log, "wb") as f:
            f.write(rows.replace(b"4 40", b"4 60"))
        with self.assertRaisesRegex(resultDigest.DigestError,
                                    r"probes/0/p, line 5: .*lines 5 to 6"):
            postProcessing.series(self.tmp, "probes/p", verify=True)


class ReadRefusal(TempDirTestCase):

    def testNotARegularFileOrTooLarge(self):
        fifo = os.path.join(self.tmp, "fifo")
        os.mkfifo(fifo)
        self.assertRegex(options.readRefusal(fifo, 0, "case file"),
                         r"fifo' is a FIFO \(named pipe\), not a file: "
                         r"reading it would wait without end")
        self.assertRegex(options.readRefusal("/dev/zero", 0, "case file"),
                         r"'/dev/zero' is a device, not a file: reading it "
                         r"would not end")
        big = self.write("big", "x" * 2000)
        self.assertRegex(options.readRefusal(big, 1024, "dictionary"),
                         r"big' is 1\.95 KiB \(2000 bytes\), more than the "
                         r"1 KiB \(1024 bytes\) a dictionary may be")
        self.assertEqual(options.readRefusal(big, 0, "dictionary"), "")
        self.assertEqual(options.readRefusal(self.tmp + "/none", 0, "x"), "")

    def testReadersRefuseAFifo(self):
        """The package's readers look first (a FIFO blocked the open)."""
        from neuronFsi import logs, msh
        fifo = os.path.join(self.tmp, "fifo")
        os.mkfifo(fifo)
        for read, error in ((postProcessing.readTable,
                             postProcessing.ColumnFileError),
                            (logs.text, logs.LogError),
                            (msh.read, msh.MshError)):
            with self.assertRaisesRegex(error, r"is a FIFO"):
                read(fifo)

    def testExactRiemannRefusesDevZero(self):
        """adv52 p10: exactRiemann /dev/zero read without end."""
        exe = os.path.join(os.path.dirname(__file__), "..", "..", "build",
                           "bin", "exactRiemann")
        self.assertTrue(os.path.exists(exe), exe + " not built")
        r = subprocess.run([exe, "/dev/zero", "n=11"], capture_output=True,
                           text=True, timeout=20)
        self.assertEqual(r.returncode, 1)
        self.assertIn("error: case file '/dev/zero' is a device, not a file",
                      r.stderr)
