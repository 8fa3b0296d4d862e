"""The named checks of a test script (tests/*/check*.py, test*.py run by
ctest): each printed when it is made, "ok   <what>" or "FAIL <what>", the
failures kept for the script's summary and exit status."""


class Checks:
    """check(good, what) prints and records one check; check.failed lists
    what failed."""

    def __init__(self):
        self.failed = []

    def __call__(self, good, what):
        """Print and record the check `what` (good: it passed); good as a
        bool."""
        print(("ok   " if good else "FAIL ") + what)
        if not good:
            self.failed.append(what)
        return bool(good)

    def relative(self, name, value, ref, tol):
        """The check that value is within the relative tolerance tol of
        ref, printed with both, their relative difference and tol."""
        err = abs(value - ref)/abs(ref)
        return self(err <= tol, f"{name}: {value:.10g} vs {ref:.10g}"
                    f" (relative {err:.2e}, tolerance {tol:g})")

    def exitStatus(self):
        """0 when every check passed, 1 otherwise."""
        return 1 if self.failed else 0
