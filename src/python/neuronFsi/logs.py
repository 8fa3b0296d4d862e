"""The numbers our scripts take from logs: OpenFOAM solver and utility logs
(log.<application>) and /usr/bin/time -v reports.

A number parsed from a log is an interface nobody declared: where a data
file with a header holds it (postProcessing/...), read that instead
(postProcessing.py). Every regular expression on a log lives here, so that
a changed log line breaks one function with a clear message.
"""

import re

from . import options


class LogError(Exception):
    """A log without the line asked for; the message names log and line."""


def text(path):
    """The whole log (a log that is no regular file, or beyond a table's
    size, is a LogError naming it: options.readRefusal)."""
    refusal = options.readRefusal(path, options.TABLE_LIMIT, "log")
    if refusal:
        raise LogError(refusal)
    try:
        with open(path) as f:
            return f.read()
    except OSError as err:
        raise LogError("%s: %s" % (path, err.strerror))


def search(path, pattern, what, last=False):
    """The groups of the first (or last) match of pattern in the log, as
    strings; a LogError naming `what` when there is none."""
    matches = list(re.finditer(pattern, text(path), re.M))
    if not matches:
        raise LogError("%s: no %s (pattern %s)" % (path, what, pattern))
    return matches[-1 if last else 0].groups()


def executionTime(path):
    """(ExecutionTime, ClockTime) [s] of the last such line; (nan, nan)
    when the log has none."""
    cpu = clock = float("nan")
    for line in text(path).split("\n"):
        if line.startswith("ExecutionTime"):
            w = line.split()
            cpu, clock = float(w[2]), float(w[6])
    return cpu, clock


def timeSteps(path):
    """[(time [s], ExecutionTime [s], ClockTime [s])] of each time step of a
    solver log: the ExecutionTime line that ends the step of "Time = t"."""
    out, t = [], None
    for line in text(path).split("\n"):
        if line.startswith("Time = "):
            t = float(line.split()[2])
        elif line.startswith("ExecutionTime") and t is not None:
            w = line.split()
            out.append((t, float(w[2]), float(w[6])))
    return out


def lastTime(path):
    """The last "Time = t" of a solver log [s] (None before the first)."""
    t = None
    for line in text(path).split("\n"):
        if line.startswith("Time = "):
            t = float(line.split()[2])
    return t


def lastLine(path, prefix):
    """The last line that starts with prefix (stripped), or None."""
    found = None
    for line in text(path).split("\n"):
        if line.startswith(prefix):
            found = line.strip()
    return found


def cpuSplit(path):
    """cellBlastFoam's closing "CPU time of the time loop ..." line with its
    seconds to 0.1 s, or None."""
    line = lastLine(path, "CPU time of the time loop")
    if line is None:
        return None
    return re.sub(r"(\d+\.\d+)(?= s)", lambda m: f"{float(m.group(1)):.1f}",
                  line)


def completed(path):
    """Whether a solver log ends with OpenFOAM's "End" and has no FATAL."""
    s = text(path)
    return "\nEnd\n" in s and "FATAL" not in s


def fatalErrors(path, tail=4000):
    """The FOAM FATAL messages in the last `tail` characters of a log."""
    return re.findall(r"(?s)--> FOAM FATAL.*?(?=\n\n|\Z)", text(path)[-tail:])


def checkMeshCells(path):
    """Number of cells reported by checkMesh."""
    return int(search(path, r"^\s*cells:\s+(\d+)", "checkMesh cell count")[0])


def fsiMapCheck(path):
    """cellBlastFoam's interface map check under a unit pressure: (fluid
    force, solid nodal force), each a list of 3 components [N]."""
    g = search(path, r"FSI map check: unit pressure, fluid force (?:\(full "
               r"ring, \(r z 0\)\) )?\((\S+) (\S+) (\S+)\) N, solid nodal "
               r"force \((\S+) (\S+) (\S+)\) N", "FSI map check line")
    v = [float(x) for x in g]
    return v[:3], v[3:]


def pressureLoadCheck(path):
    """cellBlastFoam's check of the pressure load under 1 Pa: (total force
    on the solid, the fluid's force), each 3 components [N]; None when the
    log has no such line (the load is not the pressure load)."""
    m = re.search(r"uniform pressure 1 Pa: total force on the solid \((\S+) "
                  r"(\S+) (\S+)\) N against the fluid's \((\S+) (\S+) "
                  r"(\S+)\) N", text(path))
    if m is None:
        return None
    v = [float(x) for x in m.groups()]
    return v[:3], v[3:]


def couplingSummary(path):
    """cellBlastFoam's closing coupling line: dict of steps, iterations,
    mean, max and notConverged, and the line itself."""
    m = re.search(r"FSI coupling \w+: (\d+) steps, (\d+) iterations \(mean "
                  r"(\S+), max (\d+)\), (\d+) steps not converged", text(path))
    if m is None:
        raise LogError("%s: no coupling summary line" % path)
    return dict(steps=int(m.group(1)), iterations=int(m.group(2)),
                mean=float(m.group(3)), max=int(m.group(4)),
                notConverged=int(m.group(5)), line=m.group(0))


def indentationRun(path):
    """cellIndentationFoam's initial depth delta0 [m] (None when the run
    does not search it), CPU and wall time [s], number of elements and of
    Newton iterations (the first of each line)."""
    m = re.search(r"delta0 = (\S+) m", text(path))
    return dict(
        delta0=float(m.group(1)) if m else None,
        cpu=float(search(path, r"CPU time ([0-9.]+) s", "CPU time line")[0]),
        wall=float(search(path, r"wall time ([0-9.]+) s", "wall time")[0]),
        elements=int(search(path, r"(\d+) elements", "element count")[0]),
        newtonIterations=int(search(path, r"(\d+) Newton iterations",
                                    "Newton iteration count")[0]))


def timeV(path):
    """/usr/bin/time -v report: dict of rss [kB], user, system and wall
    [s], and status (the exit status, None if it was killed by a signal)."""
    s = text(path)

    def value(pattern, what):
        m = re.search(pattern, s)
        if m is None:
            raise LogError("%s: no %s" % (path, what))
        return m.group(1)

    hms = value(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)",
                "wall clock time").split(":")
    status = re.search(r"Exit status: (\d+)", s)
    return dict(
        rss=int(value(r"Maximum resident set size \(kbytes\): (\d+)",
                      "maximum resident set size")),
        user=float(value(r"User time \(seconds\): ([0-9.]+)", "user time")),
        system=float(value(r"System time \(seconds\): ([0-9.]+)",
                           "system time")),
        wall=sum(float(x)*60**k for k, x in enumerate(reversed(hms))),
        status=int(status.group(1)) if status else None)
