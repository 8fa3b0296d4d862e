"""neuronFsi.foamDict: reading values, nested dictionaries, lists,
comments, includes; setting entries in the text with the rest kept; a
keyword twice in one scope and a number beyond a double's range refused;
the closest valid keyword of a misspelt one (check_keywords)."""
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

    def testNotATextFileOrNotAFile(self):
        # adv45 b16: a binary file given as a dictionary was a traceback
        # (UnicodeDecodeError); b16, b26: a directory, a FIFO, /dev/null,
        # /dev/zero were each "no such file"
        path = os.path.join(self.tmp, "bin")
        with open(path, "wb") as f:
            f.write(b"a 1;\n\xd0\xff\x00 b 2;\n")
        with self.assertRaisesRegex(foamDict.DictError,
                                    r"bin is not a text dictionary: byte 7 "
                                    r"\(0x00\) is a control character"):
            foamDict.read(path)
        # adv45 b48: a Latin-1 byte in a comment (an ISO-8859-1 editor's
        # "um" with a micro sign) was a traceback; OpenFOAM reads it
        latin = os.path.join(self.tmp, "latin")
        with open(latin, "wb") as f:
            f.write(b"// a size in \xb5m\nradius 2e-5; // \xb5m\n")
        self.assertEqual(foamDict.read(latin), {"radius": 2e-5})
        self.assertEqual(foamDict.fileText(latin),
                         "// a size in \u00b5m\nradius 2e-5; // \u00b5m\n")
        inc = self.write("inc", '#include "bin"\n')
        with self.assertRaisesRegex(foamDict.DictError,
                                    r"bin is not a text dictionary"):
            foamDict.read(inc)

        class E(Exception):
            pass
        fifo = os.path.join(self.tmp, "fifo")
        os.mkfifo(fifo)
        empty = self.write("empty", "")
        os.symlink(os.path.join(self.tmp, "gone"),
                   os.path.join(self.tmp, "link"))
        for p, why in ((path, r"is not a text dictionary"),
                       (self.tmp, r": a directory, not a file"),
                       (fifo, r": a FIFO \(named pipe\), not a file"),
                       ("/dev/null", r": a device, not a file"),
                       ("/dev/zero", r": a device, not a file"),
                       (os.path.join(self.tmp, "link"),
                        r": a symbolic link to .*gone, which is not there"),
                       (os.path.join(self.tmp, "none"), r": no such file"),
                       (empty, r": no entry 'a' \(the file is empty\)")):
            with self.assertRaisesRegex(E, why):
                foamDict.read_checked(p, ["a"], ["a"], E)

    def testByteOrderMarkRefused(self):
        # adv45 c02: a UTF-8 byte-order mark at the start of pulseStudyDict
        # was "line 9: unexpected '{' in entry '\ufeff/*---'"; OpenFOAM
        # reads the mark as part of the first keyword (a banner comment
        # after it: the header and the first entry became its value), so
        # every reader of ours refuses it naming the file and the mark,
        # in the file itself and in a file it includes
        for text in (b"/*--- banner ---*/\nradius 2e-5;\n",
                     b"FoamFile\n{\n    version 2.0;\n}\nradius 2e-5;\n",
                     b"radius 2e-5;\n"):
            path = os.path.join(self.tmp, "bom")
            with open(path, "wb") as f:
                f.write(b"\xef\xbb\xbf" + text)
            with self.assertRaisesRegex(foamDict.DictError,
                                        r"bom, line 1: the file begins with "
                                        r"a UTF-8 byte-order mark"):
                foamDict.read(path)
            # without the mark the same text is read
            with open(path, "wb") as f:
                f.write(text)
            self.assertEqual(foamDict.read(path)["radius"], 2e-5)
        with open(path, "wb") as f:
            f.write(b"\xef\xbb\xbfradius 2e-5;\n")
        inc = self.write("incBom", '#include "bom"\n')
        with self.assertRaisesRegex(foamDict.DictError, r"byte-order mark"):
            foamDict.read(inc)
        # a mark later in the file is a character of a word, as in OpenFOAM
        later = self.write("later", "// \ufeff\nradius 2e-5;\n")
        self.assertEqual(foamDict.read(later), {"radius": 2e-5})

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

    def testDuplicatesInOneScopeOfOneText(self):
        with self.assertRaisesRegex(
                foamDict.DictError,
                r"x, line 3: entry 'C10' is given twice in "
                r"'materials/nucleus' \(first on line 2"):
            foamDict.parse("materials { nucleus {\nC10 1;\nC10 2; } }", "x")
        with self.assertRaisesRegex(foamDict.DictError,
                                    "'fluid' is given twice in the top"):
            foamDict.parse("fluid { a 1; }\nfluid { b 2; }")
        # the same keyword in two scopes, and an included entry the text
        # replaces, are not duplicates
        self.assertEqual(foamDict.parse("a 1; b { a 2; }"),
                         {"a": 1, "b": {"a": 2}})
        self.write("set", "nucleus { C10 13.33; }\n")
        p = self.write("solidProperties", 'materials { #include "set"\n'
                       'nucleus { C10 6.67; } }\n')
        self.assertEqual(foamDict.read(p),
                         {"materials": {"nucleus": {"C10": 6.67}}})

    def testNumberBeyondDoubleRange(self):
        with self.assertRaisesRegex(foamDict.DictError,
                                    "x, line 2: entry 'C10' = 1e999 is "
                                    "beyond the range"):
            foamDict.parse("a 1;\nC10 1e999;", "x")
        with self.assertRaisesRegex(foamDict.DictError, "= -1e400"):
            foamDict.parse("t (1 -1e400);", "x")

    def testNumbersOutsideOpenFoamsReader(self):
        # OpenFOAM's reader: |x| > 1e300 an error, a non-zero |x| <= 1e-300
        # read as 0 without a word (issue 19, ps04, pu04, k33, k34: 5e-324
        # gave ZeroDivisionError, 1e308 an overflow, in the scripts)
        for text, what in (("b { c 1e308; }", "entry 'b/c' = 1e308 is "
                            "beyond the range of a number \\(OpenFOAM reads"),
                           ("a 5e-324;", "entry 'a' = 5e-324 is below the "
                            "smallest magnitude OpenFOAM reads \\(1e-300\\):"
                            " it would be read as 0"),
                           ("a (1 -1e-400);", "entry 'a' = -1e-400 is below"),
                           ("a 1e-300;", "entry 'a' = 1e-300 is below")):
            with self.assertRaisesRegex(foamDict.DictError, what):
                foamDict.parse(text, "x")
        self.assertEqual(foamDict.parse("a 1e300; b 2e-300; c 0e-400;"),
                         {"a": 1e300, "b": 2e-300, "c": 0.0})
        # nan and inf are words, as OpenFOAM reads them
        self.assertEqual(foamDict.parse("a nan; b inf;"),
                         {"a": "nan", "b": "inf"})

    def testOutsideTheReaderNamedByItsReader(self):
        # belowReader: a number read as 0 or not read at all is left to the
        # entry's reader, which names its range (adv47b f22; adv48a h15,
        # fix19f: 1e308 was refused at once with the reader's limits)
        d = foamDict.parse("a 1e-310; b 1e308; c (1 -1e309);", "x",
                           belowReader=True)
        self.assertFalse(d["a"].beyond())
        self.assertTrue(d["b"].beyond())
        self.assertTrue(d["c"][1].beyond())
        self.assertEqual(
            d["b"].problem("[1e-6, 10]"),
            "x, line 1: entry 'b' = 1e308 is beyond the range of a number "
            "(OpenFOAM reads |x| <= 1e+300; a double holds |x| <= "
            "1.79769e+308); the entry's valid range is [1e-6, 10]: give a "
            "value in it")
        self.assertIn("give 0, or a value of magnitude above 1e-300 in it",
                      d["a"].problem("[0, 1]"))
        with self.assertRaisesRegex(
                foamDict.DictError,
                r"entry 'b' = 1e308 is beyond the range of a number .*: "
                r"give a value with \|x\| <= 1e\+300 in the entry's valid "
                r"range$"):
            foamDict.refuseBelowReader(d, foamDict.DictError, keep=("a",))

    def testClosestKeyword(self):
        valid = ["scheme", "maxIter", "tolerance", "velocityScale"]
        self.assertEqual(foamDict.edit_distance("kitten", "sitting"), 3)
        self.assertEqual(foamDict.edit_distance("tua1", "tau1"), 1)
        self.assertEqual(foamDict.closest("maxIterr", valid), "maxIter")
        self.assertEqual(foamDict.closest("sceme", valid), "scheme")
        self.assertIsNone(foamDict.closest("xyz", valid))
        # max(2, len/3): 12 characters, 4 edits close, 5 not
        self.assertEqual(foamDict.closest("abcdefghWXYZ", ["abcdefghijkl"]),
                         "abcdefghijkl")
        self.assertIsNone(foamDict.closest("abcdefgVWXYZ", ["abcdefghijkl"]))
        self.assertEqual(foamDict.did_you_mean("tolerence", valid),
                         "; did you mean 'tolerance'?")
        self.assertEqual(foamDict.did_you_mean("xyz", valid), "")
        foamDict.check_keywords({"scheme": "robin"}, valid, "f")
        with self.assertRaisesRegex(
                foamDict.DictError,
                r"^f: unknown entry 'maxIterr'; did you mean 'maxIter'\?; "
                r"valid entries: \(scheme maxIter tolerance velocityScale\)"):
            foamDict.check_keywords({"maxIterr": 3}, valid, "f")


if __name__ == "__main__":
    unittest.main()
