"""neuronFsi.foamDict: reading values, nested dictionaries, lists,
comments, includes; setting entries in the text with the rest kept."""
import os
import unittest

from fixtures import TempDirTestCase
from neuronFsi import foamDict

TEXT = """FoamFile
{
    version 2.0;
    object  solidProperties;
}
/* a block
   comment */
model    neoHookean;   // the material
c0       1.6700001;    // [Pa]
n        3;
flag     yes;
name     "a b";
table    ((0 0) (1e-10 5e7));
nucleus
{
    c0   13.33;
    tau  (0.5 1);
}
"""


class FoamDict(TempDirTestCase):

    def testValues(self):
        d = foamDict.parse(TEXT)
        self.assertNotIn("FoamFile", d)
        self.assertEqual(d["model"], "neoHookean")
        self.assertEqual(d["c0"], 1.6700001)
        self.assertIsInstance(d["n"], int)
        self.assertIs(d["flag"], True)
        self.assertEqual(d["name"], "a b")
        self.assertEqual(d["table"], [[0, 0], [1e-10, 5e7]])
        self.assertEqual(d["nucleus"], {"c0": 13.33, "tau": [0.5, 1]})

    def testErrorsNameFileAndLine(self):
        with self.assertRaisesRegex(foamDict.DictError,
                                    r"f, line 2: entry 'b' has no closing"):
            foamDict.parse("a 1;\nb 2\n", "f")
        with self.assertRaisesRegex(foamDict.DictError, r"f, line 1: uncl"):
            foamDict.parse("s { a 1;", "f")

    def testSetEntryKeepsTheRest(self):
        s = foamDict.set_entry(TEXT, ["nucleus", "c0"], "6.67", "f")
        self.assertEqual(foamDict.parse(s)["nucleus"]["c0"], 6.67)
        self.assertEqual(s.replace("c0 6.67", "c0   13.33"), TEXT)
        s = foamDict.set_entry(TEXT, ["nucleus", "d0"], "1e-3", "f")
        self.assertEqual(foamDict.parse(s)["nucleus"]["d0"], 1e-3)
        self.assertIn("// the material", s)
        with self.assertRaisesRegex(foamDict.DictError, "no sub-dictionary"):
            foamDict.set_entry(TEXT, ["cytoplasm", "c0"], "1", "f")

    def testFormatValue(self):
        self.assertEqual(foamDict.format_value(1.6700004), "1.6700004")
        self.assertEqual(foamDict.format_value([1, 2.5, True]), "(1 2.5 yes)")

    def testIncludesMergeAsOpenFoam(self):
        p = self.write("controlDict", "endTime 1.5e-7;\nfluid { a 1; b 2; }\n"
                       '#sinclude "controlDict.run"\n'
                       '#includeIfPresent "absent"\n')
        self.assertEqual(foamDict.read(p), {"endTime": 1.5e-7,
                                            "fluid": {"a": 1, "b": 2}})
        self.write("controlDict.run", "endTime 2e-8;\nfluid { b 3; }\n")
        self.assertEqual(foamDict.read(p), {"endTime": 2e-8,
                                            "fluid": {"a": 1, "b": 3}})
        p = self.write("d", '#include "absent"\n')
        with self.assertRaisesRegex(foamDict.DictError, "no file"):
            foamDict.read(p)
        with self.assertRaisesRegex(foamDict.DictError, "unsupported"):
            foamDict.read(self.write("e", '#remove "a"\n'))

    def testIncludeExpandsEnvironment(self):
        # As the tutorials include the paper's parameter sets
        self.write("sets/table", "nucleus { C10 13.33; mu1 862.22; }\n")
        p = self.write("solidProperties", 'materials\n{\n'
                       '    #include "$FOAMDICT_TEST_DIR/sets/table"\n'
                       '    nucleus { C10 6.67; }\n}\n')
        os.environ["FOAMDICT_TEST_DIR"] = self.tmp
        try:
            self.assertEqual(foamDict.read(p), {"materials": {"nucleus": {
                "C10": 6.67, "mu1": 862.22}}})
        finally:
            del os.environ["FOAMDICT_TEST_DIR"]


if __name__ == "__main__":
    unittest.main()
