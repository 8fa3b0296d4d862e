#!/usr/bin/python3
"""
Application
    planeWave

Description
    The exact-enough answer of a blast case: the 1D nonlinear plane wave of
    its water column (the pulse on the top face, the rigid substrate at
    z = 0), computed by rhoRiemannFoam on a column of cells of -dz with the
    case's own thermo, schemes and top/bottom conditions (neuronFsi.
    planeWave). The cell has water's bulk response and shear moduli about
    1e-7 of it, so the pressure at any height of the coupled scene is this
    wave to that order. Compared with the case's solid probes
    (postProcessing/solidProbes, pressure p<i> at the probe's height) and
    fluid probes (any probes function object sampling p): arrival, 1-ns averaged peak,
    incident plateau and impulse, scene against reference. The fluid
    probes stay at their heights; a solid probe is a material point
    (solid::PointProbe), which the wave moves down by about P T/(rho0 C0)
    (0.17 um for 50 MPa for 5 ns) and back: its reference is the 1D wave
    along that path (the column probed on a band of heights around it,
    neuronFsi.planeWave.materialHistory), not at its reference height
    (for the 5 ns pulse at the Fig. 10 point the 1-ns peaks differ by
    2.4-2.6 %: docs/results/blastPlaneWave.md, "The 5 ns von Mises").

    The solid probes' von Mises stress and longitudinal strain have an
    exact answer too: a material point carried by the plane wave is in
    uniaxial strain, F = diag(1, 1, rho0/rho(t)), with the water's density
    history along its path (nucleus and cytoplasm have the water's
    equation of state), and its region's neo-Hookean + Maxwell law gives
    the von Mises stress in closed form (neuronFsi.planeWave.
    uniaxialResponse; the solid library's own material point gives the
    same to 1e-6, tests/blast/uniaxialPoint.py). Compared: the 1-ns peak of von Mises and of the
    strain, and after the pulse (t >= 140 ns) the largest |strain| and
    von Mises, whose answer is rest.

    Writes <case>/postProcessing/planeWave/0/:
        reference.dat   time [s], p [Pa] and rho [kg/m^3] of the 1D answer
                        at each height, then at each solid probe's
                        material point (and its height [m])
        measures.dat    one row per probe: height, the four measures of
                        the scene and of the reference, their errors
        solidMeasures.dat  one row per solid probe: region, height, von
                        Mises and strain peaks of the scene and of the
                        answer, their errors, the rest measures
    and prints them. With -check, exits 1 when a measure is
    outside issue 17's bounds (arrival 0.3 ns, peaks and plateau 5 %,
    impulse 3 %; solid von Mises and strain peaks 5 %; after the pulse
    |strain| 1e-3 and von Mises 10 % of its peak), naming it; -except
    leaves the named measures out of the check (they are still printed).

    With -layered, the reference is the 1D answer of the posed model on the
    axis instead of the water-only column: the water column with the
    cell's layers where the axis (or the line r = -radius) crosses the
    solid mesh (membrane: its quadratic law; cytoplasm, nucleus: their
    Mie-Grueneisen law and rho0; the neo-Hookean deviatoric stress of
    uniaxial strain), computed by neuronFsi.layeredColumn (a Lagrangian
    finite-volume solver, independent of the scene's code and of
    rhoRiemannFoam); the water's probes at fixed heights, the solid's at
    their material points. Written to postProcessing/planeWaveLayered/0/
    (postProcessing/planeWaveLayeredR<r>/0/ with -radius; the same files),
    so that the comparisons stay side by side.

    With -inflow HEIGHT, for a scene whose water ends at HEIGHT below the
    physical column (its top patch of type planeWaveInflow): computes the
    column to -endTime (default: the case's controlDict endTime) and
    writes <case>/constant/inflowWave, the 1D wave's p and u at HEIGHT
    that the boundary condition reads (neuronFsi.planeWave.writeInflow);
    no probes, no measures.

Usage
    planeWave [-case dir] [-Z 100e-6] [-dz 25e-9] [-endTime t]
              [-probes solid,fluid] [-check] [-except m1,m2]
              [-reference file] [-partial] [-acceptHandMade] [-layered [-radius r]]
    planeWave -inflow HEIGHT [-case dir] [-Z Z] [-dz 25e-9] [-endTime t]
              [-overwrite] [-maxSteps 1e6]

    -Z          the physical water column's height [m]: the pulse is
                applied at its top face (default: for a case whose top is
                planeWaveInflow, its columnHeight in 0/p; else the top of
                the case's mesh, 100e-6 without a mesh; a different -Z is
                refused)
    -dz         the 1D cell size [m] (default 25e-9: ten times finer
                than the preview's finest water cell; with -layered
                10e-9, the largest cell of the layered column)
    -layered    the reference is the layered column of the posed model
                (above) instead of the water-only column
    -radius     with -layered: the vertical line r [m] whose layers make
                the column (default 0, the axis)
    -endTime    [s]; default: the last time of the case's probes (with
                -inflow: the case's controlDict endTime; the wave is
                computed one step of the scene beyond it, maxDeltaT or
                deltaT of the controlDict: a run's last step may end past
                its endTime)
    -maxSteps   the most time steps the column may take [1, inf) (default
                1e6): estimated before anything runs as endTime /
                (0.5 dz / c), c the water's sound speed at rest; more is
                refused (issue 19: -endTime 1 ran without end)
    -inflow     the height [m] of the scene's top above the substrate,
                0 < HEIGHT < Z, the top of its mesh, for a top patch of
                type planeWaveInflow (refused for another): write
                constant/inflowWave for it. An
                earlier file whose entries differ from the new ones is
                kept and the run refused (results may have been computed
                with it), unless -overwrite; one differing in its comments
                only is replaced
    -except     measures not checked, [solid:|fluid:]<measure> (all
                probes, or the solid's or the water's only); measures:
                arrival, peak1ns, peakIncident, plateau, impulse,
                vonMises1ns, strain1ns, restStrain, restVonMises
    -reference  reuse a reference.dat of an earlier run (same pulse,
                column and heights) instead of computing it (for solid
                probes, one with their material points: written since
                2026-12-05, g5ns)
    -acceptHandMade
                measure probe logs and a -reference that do not carry
                the digests of the run that wrote them, or whose bytes
                differ from them (a file made or edited by hand): by
                default such a file is refused naming it and its first
                line not as written (adv52 p06b)
    -partial    compare the probes of a run still going on in the case
                (its solver holds the case's run lock): by default such a
                case is refused, naming the run (adv34 n21: a report of
                the run so far, exit 0, without a word)

    planeWave takes the case's run lock (.runLock, the solvers'; neuronFsi.
    caseLock) while it writes there; -partial takes none.

\\*---------------------------------------------------------------------------*/
"""

import argparse
import math
import os
import re
import sys

try:
    from neuronFsi import script
except ImportError:
    sys.exit("planeWave.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import caseLock, foamDict, layeredColumn, options, \
    planeWave, postProcessing, resultDigest

# the layered column's default cell size [m] (docs/results/
# blastPlaneWave.md, "The layered reference": its own error)
LAYERED_DZ = 10e-9
BOUNDS = {"arrival": 0.3e-9, "peak1ns": 0.05, "peakIncident": 0.05,
          "plateau": 0.05, "impulse": 0.03}
# the solid probes' deviatoric response against the uniaxial-strain answer
# (relative, 1-ns means), and at rest after the pulse (issue 17 item 6:
# |strain_z| below 1e-3, von Mises below 10 % of the pulse's peak)
SOLID_BOUNDS = {"vonMises1ns": 0.05, "strain1ns": 0.05, "restStrain": 1e-3,
                "restVonMises": 0.1}


def main():
    p = argparse.ArgumentParser(prog="planeWave", add_help=True)
    p.add_argument("-case", default=".")
    p.add_argument("-Z", type=float, default=None)
    p.add_argument("-inflow", type=float, default=None)
    p.add_argument("-dz", type=float, default=None)
    p.add_argument("-layered", action="store_true")
    p.add_argument("-radius", type=float, default=None)
    p.add_argument("-endTime", type=float, default=None)
    p.add_argument("-maxCells", type=int, default=100000)
    p.add_argument("-maxSteps", type=float, default=1e6)
    p.add_argument("-overwrite", action="store_true")
    p.add_argument("-probes", default="solid,fluid")
    p.add_argument("-check", action="store_true")
    p.add_argument("-except", dest="skip", default="")
    p.add_argument("-reference", default=None)
    p.add_argument("-partial", action="store_true")
    p.add_argument("-acceptHandMade", action="store_true")
    a = options.parse(p)
    # the logs and a -reference measured only as their runs wrote them
    # (their digests), unless the user says they are hand-made (adv52 p06b)
    resultDigest.measuring("-acceptHandMade", a.acceptHandMade)
    # -partial: the rows a run going on wrote after its last write time
    resultDigest.measuringPartial(a.partial)
    case = os.path.abspath(a.case)
    if a.radius is not None and not a.layered:
        p.error("-radius is an option of -layered (the line whose layers "
                "make the column)")
    if a.radius is not None and not (a.radius >= 0
                                     and math.isfinite(a.radius)):
        p.error("-radius %g m: must be 0 or positive and finite" % a.radius)
    if a.layered and a.inflow is not None:
        p.error("-layered is not an option of -inflow (the inflow wave is "
                "the water column's)")
    if a.dz is None:
        a.dz = LAYERED_DZ if a.layered else 25e-9
    # [(kind or None, measure)]: "peak1ns" or "fluid:peak1ns"
    skip = [tuple(k.split(":")) if ":" in k else (None, k)
            for k in a.skip.split(",") if k]
    for kind, k in skip:
        if (k not in BOUNDS and k not in SOLID_BOUNDS) \
                or kind not in (None, "solid", "fluid"):
            p.error("-except %s: not [solid:|fluid:]<measure> (measures: "
                    "%s)" % (k if kind is None else kind + ":" + k,
                             ", ".join(list(BOUNDS) + list(SOLID_BOUNDS))))
    # -probes: which probes to compare, a comma-separated list of solid and
    # fluid (was: any text, then "no solid or fluid probes" naming no
    # option; issue 19)
    kinds = a.probes.split(",")
    if not all(k in ("solid", "fluid") for k in kinds):
        p.error("-probes %r: not a comma-separated list of solid and fluid "
                "(e.g. -probes solid,fluid or -probes fluid)" % a.probes)
    for name, v in (("-Z", a.Z), ("-dz", a.dz)):
        if v is not None and not (v > 0 and math.isfinite(v)):
            p.error("%s %g m: must be positive and finite" % (name, v))
    if not 1 <= a.maxSteps < float("inf"):
        p.error("-maxSteps %g is outside the valid range [1, inf)"
                % a.maxSteps)
    # adv48b g49: -maxCells -1 was taken as a limit ("800 cells, above
    # -maxCells -1")
    if not a.maxCells >= 1:
        p.error("-maxCells %d is outside the valid range [1, inf)"
                % a.maxCells)
    if a.endTime is not None and not (a.endTime > 0
                                      and math.isfinite(a.endTime)):
        p.error("-endTime %g s: must be positive and finite" % a.endTime)
    if a.overwrite and a.inflow is None:
        p.error("-overwrite is an option of -inflow (it replaces a "
                "differing constant/inflowWave)")
    if a.inflow is not None and (a.check or a.skip or a.reference):
        p.error("-inflow writes constant/inflowWave only: no -check, "
                "-except or -reference with it")
    if a.partial and a.inflow is not None:
        p.error("-partial is not an option of -inflow (it writes "
                "constant/inflowWave into the case: the case's run lock)")
    if a.partial:
        running = caseLock.inUse(case)
        if running:
            print("planeWave: the case %s is not finished: %s. -partial: "
                  "the report is of the run so far (its probes' last "
                  "time)" % (case, running))
        return compare(case, a, p, skip, kinds)
    if a.inflow is None:
        caseLock.checkFree(case, "planeWave", "-partial")
    with caseLock.held(case, "planeWave"):
        return compare(case, a, p, skip, kinds)


def compare(case, a, p, skip, kinds):
    """The body of main, the options checked (the case's lock held
    unless -partial)"""
    # the physical column: a planeWaveInflow top states it
    columnHeight = planeWave.inflowColumnHeight(case)
    if a.Z is None:
        a.Z = planeWave.caseColumnHeight(case)
    else:
        planeWave.checkColumnHeight(case, a.Z, "-Z")
    if a.inflow is not None and not 0 < a.inflow < a.Z:
        p.error("-inflow %g m is outside the valid range (0, %g) m: the "
                "scene's top lies inside the column, whose top is at %g m "
                "(%s)" % (a.inflow, a.Z, a.Z, "-Z" if columnHeight is None
                          else "columnHeight of the top in 0/p"))
    # -inflow writes a file only a planeWaveInflow top reads, for the
    # height where the case's water ends (issue 19, adv35 t48: written on a
    # classic top, exit 0)
    if a.inflow is not None:
        if columnHeight is None:
            path, top = planeWave._topP(case, "top")
            sys.exit("planeWave: -inflow writes %s for a top patch of type "
                     "%s; %s: boundaryField/top is of type %s, which reads "
                     "no such file. Nothing written: set the top to %s "
                     "(the blast Allruns' -inflow option does) or leave -inflow "
                     "out" % (planeWave.INFLOW_FILE, planeWave.INFLOW, path,
                              top.get("type"), planeWave.INFLOW))
        top = planeWave.meshTop(case)
        if top is not None and abs(a.inflow - top) > 1e-6*top:
            sys.exit("planeWave: -inflow %g m differs from the height where "
                     "the case's water ends, %g m (the top of its mesh, %s): "
                     "the boundary condition applies the wave there; give "
                     "-inflow %g" % (a.inflow, top, os.path.join(
                         case, planeWave.POINTS), top))
    if a.Z/a.dz > a.maxCells:
        p.error("-Z %g m / -dz %g m = %.3g cells, above -maxCells %d (the "
                "column's cost grows as the square of its cells)"
                % (a.Z, a.dz, a.Z/a.dz, a.maxCells))

    table = planeWave.appliedPressure(case)
    if a.inflow is not None:
        inflow(case, a, table)
        return
    amp, T = planeWave.pulseShape(table)
    probes = planeWave.caseProbes(case, "solid" in kinds, "fluid" in kinds)
    if not probes:
        sys.exit("planeWave: no solid or fluid probes in %s/postProcessing"
                 % case)
    # the water of the scene: its mesh (a shortened scene ends below the
    # physical column)
    water = min(a.Z, planeWave.meshTop(case) or a.Z)
    outside = [n for n, z, _, _ in probes if not 0 <= z <= water*(1 + 1e-9)]
    if outside:
        print("planeWave: %s outside the case's water [0, %g] m: not "
              "compared" % (", ".join(outside), water))
        probes = [q for q in probes if q[0] not in outside]
    heights = sorted({z for _, z, _, _ in probes})
    end = a.endTime or max(t[-1] for _, _, t, _ in probes)
    # a run whose logs end before its endTime (killed, or still going on)
    # is named as such; -check compares a finished run only, or the run
    # so far with -partial (adv49b i43: a run killed at 3.38 ns of 6 ns
    # failed -check on windows its logs do not cover, not said)
    cut = runCut(case, max(t[-1] for _, _, t, _ in probes))
    if cut:
        if a.check and not a.partial:
            sys.exit("planeWave: -check: %s. Nothing compared: finish the "
                     "run (restart it: startFrom latestTime) or give "
                     "-partial to compare the run so far" % cut)
        print("planeWave: %s: the measures are of the run so far (each "
              "over the span both histories cover)" % cut)

    # each reference its own folder: the water column, the layered one on
    # the axis, on another line (-radius)
    name = "planeWave"
    if a.layered:
        name = "planeWaveLayered" + ("" if not a.radius
                                     else "R%g" % a.radius)
    out = os.path.join(case, "postProcessing", name, "0")
    os.makedirs(out, exist_ok=True)
    if a.reference:
        kind = options.notARegularFile(a.reference)
        if kind:
            raise planeWave.PlaneWaveError(
                "-reference %s is %s, not a file (a reference.dat of an "
                "earlier run)" % (a.reference, kind))
        wave = planeWave.readReference(a.reference)
        # the reference of this case's pulse (adv54 n03 (b): a 50 MPa
        # run's reference in a 100 MPa case gave "not compared" for every
        # probe, for a wrong reason): the pulse its header states
        with open(a.reference, errors="replace") as f:
            head = f.readline(4096)
        m = re.search(r"pulse (\S+) Pa for (\S+) s", head)
        if m:
            try:
                was = (float(m.group(1)), float(m.group(2)))
            except ValueError:
                was = None
            if was and any(abs(x - y) > 1e-6*max(abs(x), abs(y))
                           for x, y in zip(was, (amp, T))):
                raise planeWave.PlaneWaveError(
                    "-reference %s is the answer of a pulse of %g Pa for %g "
                    "s (its header), not the case's pulse of %g Pa for %g s "
                    "(its 0/p): the reference of another case or run; write "
                    "this case's with planeWave -case %s" % (
                        a.reference, was[0], was[1], amp, T, a.case))
    elif a.layered:
        layeredColumn.checkRunMesh(case)
        wave = layeredColumn.solve(
            case, heights, a.Z, end, dz=a.dz, r=a.radius or 0.0,
            material={z for n, z, _, _ in probes if n.startswith("solid")},
            maxSteps=a.maxSteps)
        planeWave.writeReference(
            os.path.join(out, "reference.dat"), wave,
            "1D layered column of %s on r = %g m (%s; water above): column "
            "%g m, cells up to %g m (%d), pulse %g Pa for %g s" % (
                case, a.radius or 0.0, ", ".join(
                    "%s %.6g-%.6g um" % (n, z0*1e6, z1*1e6)
                    for z0, z1, n in wave.layers), a.Z, a.dz, wave.cells,
                amp, T))
    else:
        wave = planeWave.column(case, heights, a.Z, end, dz=a.dz,
                                maxCells=a.maxCells, maxSteps=a.maxSteps,
                                material={z for n, z, _, _ in probes
                                          if n.startswith("solid")})
        # the column's inputs are those the run was computed with (adv37
        # w50), before anything is written
        planeWave.checkRunInputs(case, wave)
        planeWave.writeReference(
            os.path.join(out, "reference.dat"), wave,
            "1D plane wave of %s: column %g m, cells %g m, pulse %g Pa for "
            "%g s" % (case, a.Z, a.dz, amp, T))

    rows, bad = [], []
    for name, z, t, pz in probes:
        # a solid probe follows its material point (solid::PointProbe),
        # the water's probes stay at their heights
        ref = (wave.solidAt(z) if name.startswith("solid")
               else wave.at(z))
        if planeWave.arrival(wave.t, ref, amp) is None:
            print("planeWave: %s at z = %g m: the pulse has not reached it "
                  "by %g s: not compared" % (name, z, wave.t[-1]))
            continue
        s, r = planeWave.measures(t, pz, wave.t, ref, amp, T, z)
        e = planeWave.errors(s, r)
        rows.append((name, z, s, r, e))
        if s["arrival"] is None:
            bad.append("%s at z = %.4g um: never reaches half the applied "
                       "pressure (the 1D answer does at %.4g ns)"
                       % (name, z*1e6, r["arrival"]*1e9))
        for k, bound in BOUNDS.items():
            kind = "solid" if name.startswith("solid") else "fluid"
            skipped = (None, k) in skip or (kind, k) in skip
            if not skipped and e[k] is not None and abs(e[k]) > bound:
                bad.append("%s at z = %.4g um: %s error %s (bound %s)"
                           % (name, z*1e6, k, _fmt(k, e[k]),
                              _fmt(k, bound)))

    keys = ("arrival", "peak1ns", "peakIncident", "plateau", "impulse")
    unit = {"arrival": ("[ns]", 1e9), "impulse": ("[Pa s]", 1.0)}
    lines = ["# planeWave: probes of %s against the %s (cells "
             "%g m); errors: arrival [ns], the others [%%]"
             % (case, "layered 1D column (-layered)" if a.layered
                else "1D plane wave", a.dz),
             "# probe  z[m]  " + "  ".join(
                 "%s%s %sRef" % (k, unit.get(k, ("[MPa]",))[0], k)
                 for k in keys) + "  " + "  ".join(
                 "err%s%s" % (k[0].upper() + k[1:],
                              "[ns]" if k == "arrival" else "[%]")
                 for k in keys)]

    def v(d, k, scale):
        return "-" if d[k] is None else "%.5g" % (d[k]*scale)

    for name, z, s, r, e in rows:
        lines.append("%s %.5g  %s  %s" % (
            name.replace(" ", "_"), z,
            "  ".join("%s %s" % (v(s, k, unit.get(k, ("", 1e-6))[1]),
                                 v(r, k, unit.get(k, ("", 1e-6))[1]))
                      for k in keys),
            " ".join(v(e, k, 1e9 if k == "arrival" else 100)
                     for k in keys)))
    text = "\n".join(lines) + "\n"
    with script.writing(os.path.join(out, "measures.dat")) as f:
        f.write(text)
    # its digests beside it, as reference.dat's (readMeasures verifies them)
    resultDigest.writeSidecar(os.path.join(out, "measures.dat"))
    sys.stdout.write(text)
    if "solid" in kinds and wave.rho is not None:
        text, solidBad = solidRows(case, wave, skip)
        bad += solidBad
        with script.writing(os.path.join(out, "solidMeasures.dat")) as f:
            f.write(text)
        resultDigest.writeSidecar(os.path.join(out, "solidMeasures.dat"))
        sys.stdout.write(text)
    if a.check:
        if not rows:
            sys.exit("planeWave: -check, but no probe saw the pulse")
        if bad:
            sys.stdout.write("".join("FAIL %s\n" % b for b in bad))
            sys.exit(1)
        print("planeWave: every measure%s within issue 17's bounds "
              "(arrival 0.3 ns, peaks and plateau 5 %%, impulse 3 %%)"
              % (" but " + ", ".join(k if c is None else c + ":" + k
                                     for c, k in skip) if skip else ""))


def runCut(case, last):
    """"" when the case's run reached its endTime (system/controlDict):
    the probes' last time last [s] within a step of it (OpenFOAM ends a
    run within half a step of endTime; a step at most maxDeltaT with
    adjustTimeStep, else deltaT); else the words naming the cut."""
    path = os.path.join(case, "system", "controlDict")
    try:
        d = foamDict.read(path)
    except (OSError, foamDict.DictError):
        return ""
    endTime = d.get("endTime")
    step = d.get("maxDeltaT") if d.get("adjustTimeStep") is True \
        else d.get("deltaT")
    if not all(isinstance(v, (int, float)) and not isinstance(v, bool)
               and math.isfinite(v) for v in (endTime, step)):
        return ""
    if last >= endTime - step:
        return ""
    return ("the run's logs end at %.10g s, before its endTime %.10g s "
            "(%s): the run was cut (killed) or is still going on"
            % (last, endTime, path))


def _time(path, d, key, hint=""):
    """The entry key of the dictionary d of file path: a time [s],
    positive and finite."""
    v = d.get(key)
    if isinstance(v, bool) or not isinstance(v, (int, float)) \
            or not (math.isfinite(v) and v > 0):
        raise planeWave.PlaneWaveError(
            "%s: entry '%s' = %s: must be a time [s], positive and finite%s"
            % (path, key, v, hint))
    return float(v)


def inflow(case, a, table):
    """planeWave -inflow: the column's p and u at the height a.inflow
    written to <case>/constant/inflowWave, to the scene's end time and one
    of its steps beyond: OpenFOAM ends a run with the first step that ends
    at or after endTime - deltaT/2, and the boundary condition needs the
    wave at that step's time (in the preview's smoke run, endTime 2.2e-8 s,
    the last step ended at 2.2003e-8 s). A step is at most maxDeltaT with
    adjustTimeStep, else deltaT (system/controlDict)."""
    path = os.path.join(case, "system", "controlDict")
    try:
        d = foamDict.read(path)
    except (OSError, foamDict.DictError) as err:
        raise planeWave.PlaneWaveError("%s: %s" % (path, err))
    end = a.endTime
    if end is None:
        end = _time(path, d, "endTime", " (or give -endTime)")
    step = (_time(path, d, "maxDeltaT", " (with adjustTimeStep, the "
                  "longest step of the scene: the wave is computed that "
                  "long beyond the end time)")
            if d.get("adjustTimeStep") is True else _time(path, d, "deltaT"))
    wave = planeWave.column(case, [a.inflow], a.Z, end + step, dz=a.dz,
                            maxCells=a.maxCells, maxSteps=a.maxSteps)
    out = os.path.join(case, planeWave.INFLOW_FILE)
    planeWave.writeInflow(
        out, wave, a.inflow, table, overwrite=a.overwrite, what=
        "Written by: planeWave %s (case %s)\nto %.17g s: the end time %g s "
        "and the longest step of the scene, %g s (%s), past which its last "
        "step cannot end" % (" ".join(sys.argv[1:]), case, end + step, end,
                             step, "maxDeltaT" if d.get("adjustTimeStep")
                             is True else "deltaT"))
    u = wave.velocityAt(a.inflow)
    print("planeWave: %s: p and u at z = %g m of the 1D column (%g m, cells "
          "%g m) to %g s (end time %g s + one step of the scene at most), "
          "%d steps; peak p %.4g MPa, u %.4g to %.4g m/s"
          % (out, a.inflow, a.Z, a.dz, end + step, end, len(wave.t),
             wave.at(a.inflow).max()*1e-6, u.min(), u.max()))


def solidRows(case, wave, skip):
    """The solid probes' von Mises and longitudinal strain against the
    uniaxial-strain answer of the plane wave along their material points'
    paths (text of solidMeasures.dat, failed bounds)"""
    log = "solidProbes/solidProbes.dat"
    if not planeWave._has(case, log):
        return "", []
    data = postProcessing.series(case, log, verify=True)
    cols = postProcessing.names(case, log)
    axis = 1 if planeWave.isWedge(case) else 2
    lines = ["# planeWave: solid probes of %s against the uniaxial-strain "
             "answer of the 1D wave at their material points (F = "
             "diag(1, 1, rho0/rho), the "
             "region's neo-Hookean + Maxwell law); von Mises [Pa], strain "
             "ln(stretch_z) [-]: the 1-ns peak of the scene and of the "
             "answer and the error [%%]; after %g ns: largest |strain| [-] "
             "and von Mises [Pa] of the scene (answer: 0); the 1-ns peak "
             "of the temperature rise [K] of the scene (the solid's "
             "adiabatic energy) and of the water at the probe's height in "
             "the 1D answer (same law), and the error [%%] ('-' where the "
             "region or the reference has no temperature)"
             % (case, planeWave.REST*1e9),
             "# probe  region  z[m]  vonMises1ns vonMises1nsRef errVonMises"
             "[%]  strain1ns strain1nsRef errStrain[%]  restStrain "
             "restVonMises  dT1ns[K] dT1nsRef[K] errDT[%]"]
    bad = []
    for i, q in enumerate(postProcessing.probes(case, log)):
        z = q["point"][axis]
        rho0, mu0, branches = planeWave.solidMaterial(case, q["region"])
        ezRef, vmRef = planeWave.uniaxialResponse(
            wave.t, wave.solidDensityAt(z), rho0, mu0, branches)
        s, r = planeWave.solidMeasures(
            data[:, 0], data[:, cols.index("vonMises%d" % i)],
            data[:, cols.index("strainZ%d" % i)], wave.t, vmRef, ezRef)
        if not r["vonMises1ns"] or not r["strain1ns"]:
            # the answer is at rest there: no relative error (adv33 pw01:
            # inf % and numpy's divide-by-zero warnings)
            print("planeWave: solid probe %d (%s) at z = %g m: the 1D "
                  "answer is at rest there up to %g s (the wave has not "
                  "reached it): not compared"
                  % (i, q["region"], z, wave.t[-1]))
            continue
        e = {k: s[k]/r[k] - 1 for k in ("vonMises1ns", "strain1ns")}
        # the temperature rise: the water's in the 1D answer at this height
        # (the region has the water's law) against the solid's
        dT = dTRef = errDT = None
        TRef = wave.solidTemperatureAt(z)
        if TRef is not None and "dT%d" % i in cols:
            scene = data[:, cols.index("dT%d" % i)]
            if scene.max() > 0:
                dT = planeWave.runningMean(data[:, 0], scene, 1e-9)[1].max()
                dTRef = planeWave.runningMean(
                    wave.t, TRef - TRef[0], 1e-9)[1].max()
                errDT = dT/dTRef - 1

        def f(v, fmt="%.5g"):
            return "-" if v is None else fmt % v

        lines.append("solid_%d %s %.5g  %s %s %s  %s %s %s  %s %s  %s %s %s"
                     % (i, q["region"], z, f(s["vonMises1ns"]),
                        f(r["vonMises1ns"]), f(100*e["vonMises1ns"], "%.3g"),
                        f(s["strain1ns"]), f(r["strain1ns"]),
                        f(100*e["strain1ns"], "%.3g"), f(s["restStrain"]),
                        f(s["restVonMises"]), f(dT), f(dTRef),
                        f(None if errDT is None else 100*errDT, "%.3g")))
        checks = [("vonMises1ns", abs(e["vonMises1ns"]), "%.3g %%", 100),
                  ("strain1ns", abs(e["strain1ns"]), "%.3g %%", 100)]
        if s["restStrain"] is not None:
            checks += [("restStrain", s["restStrain"], "%.3g", 1),
                       ("restVonMises", s["restVonMises"]/s["vonMises1ns"],
                        "%.3g of the peak", 1)]
        for k, v, fmt, scale in checks:
            if (None, k) in skip or ("solid", k) in skip:
                continue
            if v > SOLID_BOUNDS[k]:
                bad.append("solid %d (%s) at z = %.4g um: %s %s (bound %s)"
                           % (i, q["region"], z*1e6, k, fmt % (v*scale),
                              fmt % (SOLID_BOUNDS[k]*scale)))
    return "\n".join(lines) + "\n", bad


def _fmt(kind, v):
    return "%.3g ns" % (v*1e9) if kind == "arrival" else "%.3g %%" % (v*100)


if __name__ == "__main__":
    try:
        main()
    except (planeWave.PlaneWaveError, caseLock.CaseLockError,
            postProcessing.ColumnFileError) as err:
        sys.exit("planeWave: error: %s" % err)
