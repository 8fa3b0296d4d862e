"""neuronFsi.indenterProperties: the protocol table of an indentation case
replaced, the rest of the file kept; a file without one is an error."""
import unittest

from neuronFsi import indenterProperties as ip

TEXT = """indenterRadius 22.5e-6;     // [m]
protocol
(
    (A   load    0.3e-6  1.41e-6)
    (B   hold    0       15)
);
// the end
"""


class IndenterProperties(unittest.TestCase):

    def testTableInTheTutorialsColumns(self):
        self.assertEqual(ip.protocolText([("A", "load", "10e-6", "5e-6"),
                                          ("C1", "unload", "0.1e-6", "2e-6"),
                                          ("B", "hold", "0", "15")]),
                         "protocol\n(\n"
                         "    (A   load    10e-6   5e-6)\n"
                         "    (C1  unload  0.1e-6  2e-6)\n"
                         "    (B   hold    0       15)\n"
                         ");")

    def testSetProtocolKeepsTheRest(self):
        s = ip.setProtocol(TEXT, [("A", "load", "10e-6", "5e-6"),
                                  ("C", "unload", "10e-6", "5e-6")])
        self.assertEqual(s, "indenterRadius 22.5e-6;     // [m]\n"
                         "protocol\n(\n    (A   load    10e-6   5e-6)\n"
                         "    (C   unload  10e-6   5e-6)\n);\n"
                         "// the end\n")

    def testNoTableIsAnError(self):
        with self.assertRaisesRegex(ip.ProtocolError,
                                    r"^f: no protocol table"):
            ip.setProtocol("protocol ;\n", [("A", "load", "1", "1")], "f")

    def testProtocolDuration(self):
        rows = [("A", "load", 0.3e-6, 1.41e-6), ("B", "hold", 0, 15),
                ("C1", "unload", 10e-6, 2e-6)]
        self.assertAlmostEqual(ip.protocolDuration(rows),
                               4.7 + 15 + 0.2, places=12)
        # calibrateCell's delta0 replaces the first row's depth
        self.assertAlmostEqual(ip.protocolDuration(rows, 0.6e-6),
                               2 + 15 + 0.2, places=12)
        self.assertIsNone(ip.protocolDuration([("A", "push", 1, 1)]))
        self.assertIsNone(ip.protocolDuration([("A", "load", 0, 1)]))

    def testPeakLabels(self):
        """fix19d (adv46b d70): the labels of peaks.dat from the rows, as
        cellIndentationFoam writes them (the calibration tutorial's
        peaks.dat: endB, C1,i .. C3,iii, endE)"""
        rows = [("A", "load", 0.3e-6, 1.41e-6), ("B", "hold", 0, 15)]
        for c in ("C1", "C2"):
            rows += [(c, "load", 1e-6, 2e-6), (c, "unload", 1e-6, 2e-6)] * 3
        rows += [("D", "load", 10e-6, 2e-6), ("E", "hold", 0, 120)]
        self.assertEqual(ip.protocolPeakLabels(rows),
                         ["endB", "C1,i", "C1,ii", "C1,iii", "C2,i",
                          "C2,ii", "C2,iii", "endE"])
        # a hold inside its stage ends nothing; a load not followed by an
        # unload of its stage is no peak; the 11th peak of a stage
        self.assertEqual(ip.protocolPeakLabels(
            [("A", "hold", 0, 1), ("A", "load", 1, 1), ("B", "unload", 1, 1),
             ("B", "hold", 0, 1)]), ["endB"])
        self.assertEqual(ip.protocolPeakLabels(
            [("C", "load", 1, 1), ("C", "unload", 1, 1)] * 11)[-2:],
            ["C,x", "C,11"])
        self.assertIsNone(ip.protocolPeakLabels([("A",)]))


if __name__ == "__main__":
    unittest.main()
