"""What the suites share: a test case with a temporary folder."""
import os
import tempfile
import unittest


class TempDirTestCase(unittest.TestCase):
    """A test case with a fresh temporary folder, self.tmp (its path),
    removed after each test."""

    def setUp(self):
        tmp = tempfile.TemporaryDirectory()
        self.addCleanup(tmp.cleanup)
        self.tmp = tmp.name

    def write(self, name, text):
        """Write text to the file name below self.tmp (its folders made);
        the file's path."""
        p = os.path.join(self.tmp, name)
        os.makedirs(os.path.dirname(p), exist_ok=True)
        with open(p, "w") as f:
            f.write(text)
        return p
