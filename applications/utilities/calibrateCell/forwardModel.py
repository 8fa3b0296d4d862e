"""cellIndentationFoam as the forward model of calibrateCell: a meshed
scratch copy of the case, one run per parameter vector in its own folder,
the materials of every region written as sub-dictionaries of the
materials of constant/solidProperties."""

import math
import os
import re
import shutil
import subprocess
import time

from neuronFsi import (caseLock, caseRuns, foamDict, logs, options,
                       postProcessing, scratch, signals)

MESH_SIZES = ("nucleusSize", "cytoplasmSize", "membraneSize", "contactSize")


class ModelError(Exception):
    """A forward run that failed; the message names its log."""


def _run(cmd, cwd, log):
    with open(log, "w") as f:
        # ended on SIGTERM, SIGHUP, SIGINT (calibrateCell's stopOn)
        return signals.call(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)


def protocol_text(rows):
    """Dictionary text of a protocol list [[stage, motion, rate, amount]]."""
    return "\n(\n" + "".join(
        "    (%s %s %s %s)\n" % (r[0], r[1], foamDict.format_value(r[2]),
                                 foamDict.format_value(r[3])) for r in rows
    ) + ")"


def read_materials(path):
    """The materials cellIndentationFoam built, from its materials.dat
    (region, rho0 [kg/m^3], C10 [Pa], d0 [1/Pa], then muN [Pa] and tauN
    [s] per Maxwell branch; 17 digits): region -> {C10, d0, mu1, tau1,
    ...}."""
    if not os.path.isfile(path):
        raise ModelError("no %s (the solver writes it at the start)" % path)
    try:
        return postProcessing.materials(path)
    except postProcessing.ColumnFileError as err:
        raise ModelError(str(err))


class ForwardModel:
    """Scratch copies of `case` under `work`: base/ holds the mesh (cellMesh,
    sizes scaled by mesh_factor) and the edited dictionaries; each run
    copies base/ without the mesh (a link to it)."""

    def __init__(self, case, work, mesh_factor=1.0, protocol=None,
                 keep=False, factor_where=None):
        self.case = os.path.abspath(case)
        self.work = os.path.abspath(work)
        self.keep = keep
        self.base = os.path.join(self.work, "base")
        # Only a folder this class made (its marker) is cleaned: a -work
        # folder holding a user's files is refused, nothing removed
        marker = os.path.join(self.work, ".calibrateCellWork")
        # a -work that is not a folder (a file, a FIFO, a dangling link):
        # named with the option (adv46b d24: "File exists"; adv45 b27)
        kind = options.notARegularFile(self.work) \
            if os.path.exists(self.work) else (
                "a symbolic link to %s, which is not there"
                % os.readlink(self.work) if os.path.islink(self.work)
                else "")
        if os.path.lexists(self.work) and not os.path.isdir(self.work):
            raise ModelError(
                "-work %s is %s, not a folder: give -work a new or empty "
                "folder (nothing was written)"
                % (self.work, kind or "a file"))
        if os.path.isdir(self.work) and os.listdir(self.work) \
                and not os.path.isfile(marker):
            raise ModelError(
                "the work folder %s holds files calibrateCell did not write "
                "(no %s): refused, nothing removed; give -work a new or "
                "empty folder" % (self.work, os.path.basename(marker)))
        # A forward run of an earlier calibrateCell that was stopped
        # (SIGKILL leaves its child running) still writes in its run
        # folder: removing the folder under it made this run fail on a
        # file vanishing (adv37 w109). Refused up front, nothing removed
        if os.path.isdir(self.work):
            for n in sorted(os.listdir(self.work)):
                d = os.path.join(self.work, n)
                why = caseLock.inUse(d) if os.path.isdir(d) else ""
                if why:
                    raise ModelError(
                        "the work folder %s is in use: its run folder %s: "
                        "%s (a forward run of an earlier calibrateCell that "
                        "was stopped, e.g. killed, goes on). Refused, "
                        "nothing removed: wait for that run to end, or stop "
                        "it, then run again; or give -work another folder"
                        % (self.work, d, why))
        os.makedirs(self.work, exist_ok=True)
        open(marker, "a").close()
        if os.path.exists(self.base):
            shutil.rmtree(self.base)
        for d in ("system", "constant"):
            if not os.path.isdir(os.path.join(self.case, d)):
                raise ModelError("%s: no %s/ folder" % (self.case, d))
        # a file the case reads from outside its folder by a path relative
        # to it: the copies in the work folder read another one (adv45 b15)
        problem = caseRuns.relativeOutsideProblem(
            self.case, "The forward runs use copies of its system/ and "
            "constant/ in %s" % self.work, ("system", "constant"))
        if problem:
            raise ModelError(problem)
        scratch.copyInputs(self.case, self.base, ("system", "constant"),
                           ("cell.msh", "*.calibrated"))
        self._edit_mesh_dict(mesh_factor)
        log = os.path.join(self.base, "log.cellMesh")
        if _run(["cellMesh", "-case", self.base], self.base, log) \
                or not os.path.isfile(self.mesh()):
            raise ModelError(self._too_many(log, mesh_factor, factor_where)
                             or "cellMesh failed for %s (see %s)"
                             % (self.case, log))
        self.ip_path = os.path.join(self.base, "constant/indenterProperties")
        self.ip_text = foamDict.fileText(self.ip_path)
        if protocol is not None:
            self.ip_text = foamDict.set_entry(
                self.ip_text, ["protocol"], protocol_text(protocol),
                self.ip_path)
        self.ip = foamDict.parse(self.ip_text, self.ip_path)
        self.sp_path = os.path.join(self.base, "constant/solidProperties")
        self.sp_text = foamDict.fileText(self.sp_path)
        self.materials, self.elements = self._probe()
        self.count = 0

    def mesh(self):
        return os.path.join(self.base, "constant/cell.msh")

    def _too_many(self, log, factor, where):
        """cellMesh's refusal of the scaled sizes (more elements than its
        maxElements) named as the calibration entry that scaled them, with
        the smallest factor that fits (adv40 z24: "cellMesh failed"
        without the entry); None for any other failure. The count goes
        with 1/factor^2 in the axisymmetric mesh (1/factor^3 in 3D: the
        same bound then fits too)."""
        try:
            text = open(log, errors="replace").read()
        except OSError:
            return None
        m = re.search(r"at least ([0-9.eE+-]+) elements, more than "
                      r"maxElements (\d+)", text)
        if not m or factor == 1.0:
            return None
        count, most = float(m.group(1)), int(m.group(2))
        # 1 % over the 1/factor^2 estimate, rounded up to 3 digits (the
        # membrane's layers go with 1/factor: at the plain estimate the
        # count was still above maxElements, at this one below)
        least = 1.01*factor*math.sqrt(count/most)
        unit = 10.0**(math.floor(math.log10(least)) - 2)
        least = math.ceil(least/unit)*unit
        return ("%s: entry 'meshSizeFactor' = %s scales the sizes of %s "
                "to a mesh of at least %.3g elements, more than its "
                "maxElements %d (cellMesh's estimate, %s): valid range "
                "[%s, inf) (at least about that: the count goes with "
                "1/meshSizeFactor^2), or a larger maxElements in "
                "system/cellMeshDict if that many is meant"
                % (where or "calibrationDict", foamDict.format_value(factor),
                   os.path.join(self.case, "system/cellMeshDict"), count,
                   most, log, "%.3g" % least))

    def _edit_mesh_dict(self, factor):
        if factor == 1.0:
            return
        p = os.path.join(self.base, "system/cellMeshDict")
        text = foamDict.fileText(p)
        d = foamDict.parse(text, p)
        for k in MESH_SIZES:
            if k in d:
                text = foamDict.set_entry(
                    text, [k], foamDict.format_value(float(d[k])*factor), p)
        open(p, "w").write(text)

    def _probe(self):
        """Region materials as the solver built them (the included paper
        set merged with the case's sub-dictionaries), every digit: the
        materials.dat of a run of one load step of the case's
        maxDepthIncrement (a row shorter than it is refused since fix19i:
        each row would be one step)."""
        d = os.path.join(self.work, "probe")
        step = self.ip.get("maxDepthIncrement", 1e-8)
        self._make_run_dir(d, self.sp_text, foamDict.set_entry(
            self.ip_text, ["protocol"], "((A load 0.3e-6 %s))"
            % foamDict.format_value(step), self.ip_path))
        log = os.path.join(d, "log.cellIndentationFoam")
        if _run(["cellIndentationFoam", "-case", d], d, log):
            raise ModelError("the case's own parameters do not run (see %s)"
                             % log)
        mats = read_materials(
            os.path.join(d, "postProcessing/indentation/materials.dat"))
        ne = re.search(r"(\d+) elements", open(log).read())
        if not ne:
            raise ModelError("cannot read the number of elements from %s"
                             % log)
        if not self.keep:
            shutil.rmtree(d)
        return mats, int(ne.group(1))

    def _make_run_dir(self, d, sp_text, ip_text):
        if os.path.exists(d):
            shutil.rmtree(d)
        shutil.copytree(os.path.join(self.base, "system"),
                        os.path.join(d, "system"))
        os.makedirs(os.path.join(d, "constant"))
        # the case's other files of constant/ as well: a dictionary may
        # include one ("$FOAM_CASE/constant/set", the OpenFOAM idiom; adv45
        # c05 (c): "Cannot open include file .../probe/constant/set", and
        # the case's own parameters were said not to run)
        written = ("cell.msh", "solidProperties", "indenterProperties")
        src = os.path.join(self.base, "constant")
        for n in sorted(os.listdir(src)):
            if n in written:
                continue
            f = os.path.join(src, n)
            if os.path.isdir(f) and not os.path.islink(f):
                shutil.copytree(f, os.path.join(d, "constant", n),
                                symlinks=True)
            else:
                shutil.copy2(f, os.path.join(d, "constant", n),
                             follow_symlinks=False)
        os.symlink(self.mesh(), os.path.join(d, "constant/cell.msh"))
        open(os.path.join(d, "constant/solidProperties"), "w").write(sp_text)
        open(os.path.join(d, "constant/indenterProperties"), "w").write(
            ip_text)

    def solid_properties(self, materials, header=""):
        """constant/solidProperties text with one sub-dictionary of
        'materials' per region (every entry of MaterialParameters the
        solver reported)."""
        text = self.sp_text
        for region, e in materials.items():
            text = foamDict.set_subdict(
                text, ["materials", region], e, self.sp_path,
                {k: ("Pa" if k[0] in "Cm" else "1/Pa" if k == "d0" else "s")
                 for k in e})
        return header + text if header else text

    def indenter_properties(self, delta0=None):
        """constant/indenterProperties text, the first row's amount set to
        delta0 [m] when given."""
        if delta0 is None:
            return self.ip_text
        rows = [list(r) for r in self.ip["protocol"]]
        rows[0][3] = delta0
        return foamDict.set_entry(self.ip_text, ["protocol"],
                                  protocol_text(rows), self.ip_path)

    def run(self, materials, delta0=None, tag=None):
        """Forward run: dict with peaks (label -> force [N]), time [s] and
        force [N] arrays, delta0 [m], cpu and wall time [s], elements."""
        self.count += 1
        d = os.path.join(self.work, tag or "run%04d" % self.count)
        self._make_run_dir(d, self.solid_properties(materials),
                           self.indenter_properties(delta0))
        log = os.path.join(d, "log.cellIndentationFoam")
        t0 = time.time()
        rc = _run(["cellIndentationFoam", "-case", d], d, log)
        wall = time.time() - t0
        text = open(log).read()
        if rc or "FOAM FATAL" in text:
            # the error's message, not only the last lines (they held
            # "file: ... From function ... FOAM exiting" without the error
            # line; adv30 k23, k36)
            fatal = logs.fatalErrors(log)
            raise ModelError("cellIndentationFoam failed (exit %d) in %s; "
                             "%s:\n%s" % (rc, log,
                                          "its error" if fatal else
                                          "last lines", "\n".join(
                                              fatal[-1:] if fatal else
                                              text.splitlines()[-8:])))
        pp = os.path.join(d, "postProcessing/indentation")
        try:
            p = postProcessing.readTable(os.path.join(pp, "peaks.dat"))
            peaks = dict(zip(p.column("label"),
                             p.column("force", finite=True).tolist()))
            f = postProcessing.readTable(os.path.join(pp, "force.dat"))
            t = f.column("time", increasing=True).tolist()
            F = f.column("force", finite=True).tolist()
        except postProcessing.ColumnFileError as err:
            raise ModelError("the forward run in %s: %s" % (d, err))
        m = re.search(r"delta0 = (\S+) m", text)
        cpu = re.search(r"CPU time ([0-9.eE+-]+) s", text)
        out = dict(peaks=peaks, time=t, force=F, wall=wall,
                   cpu=float(cpu.group(1)) if cpu else float("nan"),
                   delta0=float(m.group(1)) if m else
                   (delta0 if delta0 is not None
                    else float(self.ip["protocol"][0][3])))
        if not self.keep:
            shutil.rmtree(d)
        return out
