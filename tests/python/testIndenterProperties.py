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


if __name__ == "__main__":
    unittest.main()
