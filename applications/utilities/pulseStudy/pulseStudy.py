#!/usr/bin/python3
"""
Application
    pulseStudy

Description
    A pulse study of the blast scene in one command: the base case (e.g.
    tutorials/blast/axisymmetricPreview) run once per point of a grid over
    the pulse's overpressure [Pa] and positive-phase duration [s] (its
    Allrun -amplitude and -pulse), several points at a time, and the
    damage indicators of the cell per region (nucleus, cytoplasm,
    membrane) and per region interface tabulated and mapped, with the time
    each spends above the thresholds of the dictionary (their sources:
    docs/userGuide/pulseStudy.md). Settings: <case>/system/pulseStudyDict
    (src/python/neuronFsi/pulseStudy.py); the indicators:
    src/python/neuronFsi/damageIndicators.py.

    Restartable: a finished point keeps its result in
    postProcessing/pulseStudy/points/<label>/result.json with the digest of
    its inputs (the base case's files after its Allclean, its Allrun
    options, the strain-rate window) and is not run again; a point
    interrupted (a folder without a result) is run again from the start
    (its case copy moved aside to points/<label>/case.interrupted[N], kept
    for the user; a file of the user's in its folder is kept).
    The record carries the digest of its own values and its point,
    verified on every read: a damaged record, or another point's, is
    refused naming the file (nothing runs; it is left for the user).
    A dictionary whose inputs differ from those of the finished points
    (another base case or options, or a file the base case reads from
    outside it by an #include or a 'file' entry) is refused with the
    entry and the file named:
    nothing is run (move postProcessing/pulseStudy/points away to start
    over). Thresholds may change between runs (no point runs again).

    Writes postProcessing/pulseStudy/table.csv and table.h5 (one row per
    point) and the maps postProcessing/pulseStudy/map_<indicator>.png and
    timeAbove_<threshold>.png (overpressure x duration, one panel per
    region and interface, the thresholds drawn as contours).

    With a sub-dictionary 'uncertainty' (src/python/neuronFsi/
    uncertainty.py): at its pulses, material variants and the finite-
    difference runs of the calibrated parameters' intervals, run as points
    of their own; uncertainty.csv, uncertainty_<label>.png and
    fig10_<label>.png (the linearised 95 % interval of every indicator and
    the band of probe 0's series), the half-widths on the maps.

Usage
    pulseStudy [-case dir] [-dict file] [-keep]

    -dict    the dictionary (default system/pulseStudyDict); the outputs of
             pulseStudyDict.<suffix> go to postProcessing/pulseStudy.<suffix>
    -keep    keep each point's case (postProcessing/pulseStudy/points/
             <label>/case; default: removed once its result is recorded)

\\*---------------------------------------------------------------------------*/
"""

import argparse
import math
import os
import re
import shlex
import shutil
import sys
import textwrap
import time

import numpy as np

try:
    from neuronFsi import script
except ImportError:
    sys.exit("pulseStudy.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import (caseLock, caseRuns, damageIndicators as di, logs,
                       options,
                       postProcessing, pulseStudy as ps, signals,
                       uncertainty as unc)

OUT = "postProcessing/pulseStudy"     # for system/pulseStudyDict
LABELS = {"pressure": "peak pressure", "vonMises": "peak von Mises stress",
          "strain": "peak largest principal Green-Lagrange strain",
          "strainRate": "peak strain rate",
          "temperatureRise": "peak temperature rise"}
SCALE = {"Pa": (1e-6, "MPa"), "-": (1, "-"), "1/s": (1, "1/s"),
         "K": (1, "K")}


def _shown(ind):
    """(factor, unit) an indicator is shown in by the uncertainty's
    outputs: pressure in MPa, the others in their SI unit (von Mises
    stresses are tens of Pa)."""
    return (1e-6, "MPa") if ind == "pressure" else (1, di.UNITS[ind])


def prepareBase(s, out):
    """A copy of the base case after its Allclean (out/base), from which
    every point's case is copied; {file: digest} of its files (what they
    read from outside it: pulseStudy.outsideInputs of the copy)."""
    staging = os.path.join(out, "base")
    if os.path.lexists(staging):
        caseRuns.checkNoEarlierRun(staging)
        # re-made at every run: refused, nothing removed, if it holds a
        # file the base case does not (the user's: adv43 k20, a notes.md
        # in it was removed by every ./Allrun)
        foreign = filesNotIn(staging, s["base"])
        if foreign:
            raise ps.StudyError(
                "%s is the study's copy of the base case %s, made again at "
                "every run; it holds files the base case does not: %s. "
                "Nothing was removed: move them out of %s (or remove it "
                "if they are not yours), then run the study again"
                % (staging, s["base"], ", ".join(foreign), staging))
        shutil.rmtree(staging)
    shutil.copytree(s["base"], staging, symlinks=True)
    if os.path.isfile(os.path.join(staging, "Allclean")):
        # the log outside the copy: an Allclean removes log.*
        log = os.path.join(out, "log.Allclean")
        caseRuns.runIn(staging, "./Allclean", log)
        os.remove(log)
    return staging, ps.fileDigests(staging)


def filesNotIn(copy, original):
    """The files and links under folder copy (paths relative to it,
    sorted) with no entry of the same path under original; a caseRuns
    marker is not counted."""
    found = []
    for root, dirs, files in os.walk(copy):
        rel = os.path.relpath(root, copy)
        for name in sorted(dirs + files):
            path = os.path.normpath(os.path.join(rel, name))
            full = os.path.join(root, name)
            if name == caseRuns.MARKER or (
                    name in dirs and not os.path.islink(full)):
                continue
            if not os.path.lexists(os.path.join(original, path)):
                found.append(path)
    return sorted(found)


def pointFiles(folder):
    """The entries of a point's folder besides its case copy and the
    copies of interrupted runs moved aside (case.interrupted[N], named
    when moved): (those the study writes there: result.json and its
    temporary files result.json.tmp<pid>; every other one, the user's),
    by name."""
    ours, others = [], []
    if os.path.isdir(folder) and not os.path.islink(folder):
        for f in sorted(os.listdir(folder)):
            if f == "case" or re.fullmatch(r"case\.interrupted\d*", f):
                continue
            if f == "result.json" or (f.startswith("result.json.tmp")
                                      and f[15:].isdigit()):
                ours.append(f)
            else:
                others.append(f)
    return ours, others


def caseAside(folder):
    """The free name folder/case.interrupted, case.interrupted1, ...
    that the case copy of a point's interrupted run is moved to."""
    return caseRuns.asideName(os.path.join(folder, "case"))


def runPoint(s, staging, point, inputs, folder, keep):
    """Run one point in folder/case; its record."""
    case = os.path.join(folder, "case")
    # interrupted earlier: from scratch (a run left going: refused in
    # main). Only what the study wrote is removed: the point's record (and
    # a record's temporary file); the case copy is moved aside; a file of
    # the user's beside them is kept and named (adv42 g13: the point's
    # folder was removed with the user's notes.md in it)
    kept = pointFiles(folder)[1]
    aside = None
    if os.path.lexists(case):
        if os.path.isdir(case) and not os.path.islink(case):
            # the interrupted run's case copy may hold a file of the user's
            # among the run's (adv43 k07, k20 (c), k21: a notes.txt in it
            # and in its postProcessing/fsi/0/ were removed with it): moved
            # aside whole, never removed
            aside = caseAside(folder)
            os.rename(case, aside)
        else:
            os.remove(case)
    for f in pointFiles(folder)[0]:
        os.remove(os.path.join(folder, f))
    if kept:
        print("    %s: run again from the start; kept in %s (not the "
              "study's): %s" % (point["label"], folder, ", ".join(kept)),
              flush=True)
    if aside:
        print("    %s: run again from the start; the case copy of its "
              "interrupted run (and any file you put in it) moved to %s: "
              "the study does not read it again, remove it when you no "
              "longer need it" % (point["label"], aside), flush=True)
    os.makedirs(folder, exist_ok=True)
    shutil.copytree(staging, case, symlinks=True)
    # a variant or a finite-difference run of the uncertainty: its material
    # change included at the end of constant/solidProperties
    change = point.get("change")
    unc.includeChange(case, change, point["label"])
    command = "./Allrun " + " ".join(shlex.quote(o) for o in point["options"])
    wall = caseRuns.runIn(case, command, "log.pulseStudy")
    log = os.path.join(case, "log.cellBlastFoam")
    if change:
        unc.checkReached(log, change, point["label"])
    t, series = di.series(case, s["window"])
    interfaces = di.interfaceMaxima(case)
    cpu = logs.executionTime(log)[0]
    record = {
        "inputs": inputs, "label": point["label"],
        "overpressure": point["overpressure"],
        "duration": point["duration"], "wall": wall, "cpu": cpu,
        "series": {"t": t.tolist(),
                   "targets": {k: {i: v.tolist() for i, v in d.items()}
                               for k, d in series.items()},
                   "interfaces": {k: [x.tolist() for x in v]
                                  for k, v in interfaces.items()},
                   "probe": probeSeries(case)}}
    ps.writeRecord(os.path.join(folder, "result.json"), record)
    if not keep:
        shutil.rmtree(case)
    return record


def probeSeries(case):
    """Probe 0 of the solid (the paper's Fig. 10 point): {name: list}
    of time [s], pressure [Pa], vonMises [Pa], strainZ [-], strainRateZ
    [1/s] (postProcessing/solidProbes); None for a case without solid
    probes."""
    if not os.path.isdir(os.path.join(case, "postProcessing",
                                      "solidProbes")):
        return None
    d = postProcessing.series(case, "solidProbes/solidProbes.dat")
    nProbe = (d.shape[1] - 1)//7
    zBase = 1 + 5*nProbe
    return {"t": d[:, 0].tolist(), "pressure": d[:, 1].tolist(),
            "vonMises": d[:, 2].tolist(), "strainZ": d[:, zBase].tolist(),
            "strainRateZ": d[:, zBase + 1].tolist()}


def rowOf(s, record):
    """{column: value} of one point: the peak of each indicator per target
    (interface pressure and von Mises over every time step, from the
    solver's interface maxima; the rest over the writes of solid.h5) and
    the time above each threshold."""
    ser = record["series"]
    t = np.array(ser["t"])
    row = {"overpressure [Pa]": record["overpressure"],
           "duration [s]": record["duration"]}
    above = {}
    atEnd = {}
    for target, d in ser["targets"].items():
        step = ser["interfaces"].get(target)
        for ind in di.INDICATORS:
            y = np.array(d[ind], float)
            tt = t
            if step is not None and ind in ("pressure", "vonMises"):
                tt = np.array(step[0])
                y = np.array(step[1 if ind == "pressure" else 2])
            col = "%s:%s [%s]" % (target, ind, di.UNITS[ind])
            row[col] = di.peak(y)
            # a peak that is the last value: still rising when the run ends
            atEnd[col] = bool(np.isfinite(y[-1]) and y[-1] >= row[col]
                              and np.nanmax(y[:-1], initial=-np.inf)
                              < row[col])
            for th in s["thresholds"]:
                if th["indicator"] == ind:
                    above["%s:timeAbove:%s [s]" % (target, th["name"])] = \
                        di.timeAbove(tt, y, th["value"]) \
                        if np.any(np.isfinite(y)) else math.nan
    row.update(above)
    row["wall [s]"] = record["wall"]
    row["solver CPU [s]"] = record["cpu"]
    return row, atEnd


# The temporary files of the study's own outputs in its folder, each
# replacing its output when whole (writeTable, the uncertainty's table)
TEMPORARY = ("table.csv.tmp", "table.h5.tmp", "uncertainty.csv.tmp")


def removeTemporaryFiles(out):
    """Remove the temporary files (TEMPORARY) a study killed while writing
    its tables left in its folder out, a file or a symbolic link of that
    name (a folder is left, and named by the write); the paths removed.
    Called with the study's lock held: no other study writes them (was: a
    killed study left postProcessing/pulseStudy/table.h5.tmp for good)."""
    removed = []
    for name in TEMPORARY:
        path = os.path.join(out, name)
        if os.path.islink(path) or os.path.isfile(path):
            os.remove(path)
            removed.append(path)
    return removed


def writeTable(s, out, rows):
    cols = list(rows[0])
    tmp = os.path.join(out, "table.csv.tmp")
    with open(tmp, "w") as f:
        f.write(",".join('"%s"' % c for c in cols) + "\n")
        for r in rows:
            # every digit (repr): the table holds the doubles computed
            f.write(",".join(repr(float(r[c])) for c in cols) + "\n")
    os.replace(tmp, os.path.join(out, "table.csv"))
    import h5py
    tmp = os.path.join(out, "table.h5.tmp")
    with h5py.File(tmp, "w") as h:
        h.attrs["description"] = (
            "pulseStudy: one row per point of the grid; column names as in "
            "table.csv (<target>:<indicator> [unit]); the thresholds in "
            "/thresholds")
        h.attrs["strainRateWindow [s]"] = s["window"]
        h.attrs["sampleInterval [s]"] = s["sampleInterval"]
        for c in cols:
            name, unit = c.rsplit(" [", 1)
            ds = h.create_dataset("table/" + name.replace("/", "|"),
                                  data=np.array([r[c] for r in rows]))
            ds.attrs["unit"] = unit[:-1]
        for th in s["thresholds"]:
            g = h.create_group("thresholds/" + th["name"])
            g.attrs["indicator"] = th["indicator"]
            g.attrs["value"] = th["value"]
            g.attrs["unit"] = th["unit"]
            g.attrs["source"] = th["source"]
    os.replace(tmp, os.path.join(out, "table.h5"))


def _panel(ax, A, T, Z, title, unit, levels=(), atEnd=None, errors=None):
    """One map: Z [len(A), len(T)] over overpressure A [Pa] x duration T
    [s]; threshold contours (value, name, style) where the map crosses
    them; atEnd [len(A), len(T)]: the points whose peak is the run's last
    write, marked '*'; errors [len(A), len(T)]: a 95 % half-width, shown
    '+-' where it is not NaN."""
    import matplotlib.colors as mcolors
    x, y = np.array(A)/1e6, np.array(T)*1e9
    finite = Z[np.isfinite(Z)]
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("overpressure [MPa]")
    ax.set_ylabel("positive-phase duration [ns]")
    if finite.size == 0:
        ax.text(0.5, 0.5, "none (no such field)", ha="center",
                va="center", transform=ax.transAxes)
        return
    lo, hi = finite.min(), finite.max()
    norm = mcolors.Normalize(lo, hi if hi > lo else lo + 1)
    if len(x) > 1 and len(y) > 1:
        ax.contourf(x, y, Z.T, 20, cmap="viridis", norm=norm)
        for value, name, style in levels:
            if lo < value < hi:
                c = ax.contour(x, y, Z.T, [value], colors="w",
                               linestyles=style, linewidths=1.5)
                ax.clabel(c, fmt={value: name}, fontsize=6)
    pts = ax.scatter(np.repeat(x, len(y)), np.tile(y, len(x)),
                     c=Z.ravel(), cmap="viridis", norm=norm,
                     edgecolors="k", s=30, clip_on=False, zorder=3)
    ax.figure.colorbar(pts, ax=ax, label=unit)
    for i, a in enumerate(x):
        for j, b in enumerate(y):
            mark = "*" if atEnd is not None and atEnd[i, j] else ""
            if errors is not None and np.isfinite(errors[i, j]):
                mark += "\n+-%.2g" % errors[i, j]
            right = i == len(x) - 1 and len(x) > 1
            ax.annotate("%.3g%s" % (Z[i, j], mark), (a, b), fontsize=7,
                        xytext=(-4 if right else 4, 4),
                        ha="right" if right else "left",
                        textcoords="offset points",
                        color="k", zorder=4,
                        bbox=dict(boxstyle="round,pad=0.1", fc="w",
                                  alpha=0.7, lw=0))
    # room around the grid for the points and their values
    for lim, v in ((ax.set_xlim, x), (ax.set_ylim, y)):
        pad = 0.08*(v.max() - v.min()) or 0.1*abs(v.max())
        lim(v.min() - pad, v.max() + 0.5*pad if lim == ax.set_xlim
            else v.max() + 1.5*pad)


def _percent(x):
    """x as a percentage with 2 decimals, 0.00 for a rounding error"""
    return ("%.2f" % (100*x)).replace("-0.00", "0.00")


def _figure(n):
    import matplotlib.pyplot as plt
    cols = min(n, 3)
    rows = (n + cols - 1)//cols
    fig, axs = plt.subplots(rows, cols, figsize=(4.6*cols, 3.9*rows),
                            squeeze=False)
    for ax in axs.flat[n:]:
        ax.set_visible(False)
    return fig, axs.flat


def writeMaps(s, out, rows, targets, atEnd, errors=None):
    """map_<indicator>.png and timeAbove_<threshold>.png; atEnd: {column:
    {label: whether its peak is the last write}}; errors: {column: {label:
    the 95 % half-width of the value}} (the uncertainty's points)"""
    errors = errors or {}
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    A, T = s["overpressure"], s["duration"]
    styles = ["-", "--", ":", "-."]

    def grid(col, values=None, default=0):
        Z = np.full((len(A), len(T)), math.nan)
        for r in rows:
            i, j = A.index(r["overpressure [Pa]"]), T.index(r["duration [s]"])
            Z[i, j] = r[col] if values is None else values.get(r["label"],
                                                               default)
        return Z

    written = []
    n = len(targets)
    for ind in di.INDICATORS:
        unit = di.UNITS[ind]
        k, shown = SCALE[unit]
        fig, axs = _figure(n)
        ths = [t for t in s["thresholds"] if t["indicator"] == ind]
        levels = [(th["value"]*k, th["name"], styles[i % 4])
                  for i, th in enumerate(ths)]
        marked = False
        for ax, target in zip(axs, targets):
            col = "%s:%s [%s]" % (target, ind, unit)
            ends = grid(col, atEnd.get(col, {}))
            marked |= bool(np.nansum(ends))
            _panel(ax, A, T, grid(col)*k, target, "[%s]" % shown, levels,
                   ends, grid(col, errors.get(col, {}), math.nan)*k)
        lines = ["%s%s [%s]" % (LABELS[ind], "" if ind != "strainRate"
                                else " over a %g ns window"
                                % (s["window"]*1e9), shown)]
        if ths:
            top = max(r["%s:%s [%s]" % (t, ind, unit)] for r in rows
                      for t in targets
                      if np.isfinite(r["%s:%s [%s]" % (t, ind, unit)]))
            lines += textwrap.wrap("thresholds (white contours where the map "
                                   "crosses them): " + ", ".join(
                "%s %g [%s]%s" % (th["name"], th["value"], th["unit"],
                                  " (not reached: the largest value here "
                                  "is %.3g of it)" % (top/th["value"])
                                  if th["value"] > top else "")
                for th in ths), 110)
        if marked:
            lines.append("*: the peak is the run's last write (still "
                         "rising at the end)")
        if any(errors.get("%s:%s [%s]" % (t, ind, unit)) for t in targets):
            lines.append("+-: the 95 %% half-width from the material "
                         "parameters' intervals, linearised about '%s' "
                         "(uncertainty.csv)" % s["uncertainty"]["about"])
        fig.suptitle("\n".join(lines), fontsize=10)
        fig.tight_layout()
        p = os.path.join(out, "map_%s.png" % ind)
        script.saveFigure(fig, p, dpi=110)
        plt.close(fig)
        written.append(p)
    for th in s["thresholds"]:
        fig, axs = _figure(n)
        for ax, target in zip(axs, targets):
            _panel(ax, A, T, grid("%s:timeAbove:%s [s]"
                                  % (target, th["name"]))*1e9,
                   target, "[ns]")
        fig.suptitle("time above %s: %s %g %s [ns]" % (
            th["name"], th["indicator"], th["value"], th["unit"]),
            fontsize=10)
        fig.tight_layout()
        p = os.path.join(out, "timeAbove_%s.png" % th["name"])
        script.saveFigure(fig, p, dpi=110)
        plt.close(fig)
        written.append(p)
    return written


PROBE = (("pressure", 1e-6, "pressure [MPa]"),
         ("vonMises", 1, "von Mises [Pa]"),
         ("strainZ", 1, "longitudinal strain ln(stretch_z) [-]"),
         ("strainRateZ", 1, "longitudinal strain rate [1/s]"))


def writeUncertainty(s, out, pts, records, targets):
    """The uncertainty of the indicators at the pulses of the
    'uncertainty' sub-dictionary: uncertainty.csv (one row per pulse,
    target and indicator: the grid's run, each variant, the linearised
    95 % interval about 'about' at both steps with each parameter's
    share), uncertainty_<pulse>.png (the indicators per target, the
    variants and the interval) and fig10_<pulse>.png (probe 0 against time
    with the band); printed as a table. Returns ({column: {grid label:
    half-width}}, the files written)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    u = s["uncertainty"]
    params = u["parameters"]
    variants = list(u["variants"])
    errors, written, lines = {}, [], []
    header = ["overpressure [Pa]", "duration [s]", "target", "indicator",
              "unit", "base"] + variants
    if params:
        header += ["about", "halfWidth95", "halfWidth95 checkStep"] + [
            "share:%s" % p["name"] for p in params] + [
            "derivative:%s" % p["name"] for p in params] + [
            "derivative checkStep:%s" % p["name"] for p in params]
    csv = [",".join('"%s"' % h for h in header)]
    for A, T in u["pulses"]:
        g = next(p for p in pts if p["overpressure"] == A
                 and p["duration"] == T)
        rows = {"base": rowOf(s, records[g["label"]])[0]}
        for name, _ in unc.runs(u):
            rows[name] = rowOf(s, records["%s_%s" % (g["label"], name)])[0]
        result = {}
        for target in targets:
            for ind in di.INDICATORS:
                col = "%s:%s [%s]" % (target, ind, di.UNITS[ind])
                r = [A, T, target, ind, di.UNITS[ind], rows["base"][col]] + [
                    rows[v][col] for v in variants]
                if params:
                    lin = unc.propagate(u, lambda n: rows[n][col])
                    result[col] = lin
                    H = float(lin["halfWidth"])
                    errors.setdefault(col, {})[g["label"]] = H
                    # each parameter's share of H^2 (with the correlation:
                    # c_i (R c)_i / H^2, summing to 1)
                    c = lin["contributions"]
                    share = c*(u["correlation"] @ c)/H**2 if H > 0 \
                        else np.full(len(params), math.nan)
                    r += [u["about"], H, float(lin["halfWidthCheck"])] + \
                        list(share) + list(lin["derivatives"]) + \
                        list(lin["derivativesCheck"])
                csv.append(",".join(
                    '"%s"' % x if isinstance(x, str) else repr(float(x))
                    for x in r))
        written.append(_uncertaintyFigure(
            plt, s, out, g, rows, result, targets, variants))
        if params:
            band = _fig10Band(plt, s, out, g, records)
            if band:
                written.append(band)
        # the terminal's table
        k = {}
        lines.append("Uncertainty at %g Pa, %g s (%s): the base case's "
                     "value%s, then each variant's" % (
                         A, T, g["label"], "; the linearised 95 %% interval"
                         " about '%s' (its value +- the half-width at step "
                         "%g, and at checkStep %g)" % (
                             u["about"], u["step"], u["checkStep"])
                         if params else ""))
        for col in [c for c in rows["base"] if ":" in c and "timeAbove"
                    not in c]:
            unit = col.rsplit("[", 1)[1][:-1]
            k, shown = _shown(col.split(":")[1].split(" ")[0])
            text = "    %-34s base %.4g" % (col.replace(
                "[%s]" % unit, "[%s]" % shown), rows["base"][col]*k)
            if col in result:
                lin = result[col]
                text += "; %s %.4g +- %.2g (%.2g)" % (
                    u["about"], lin["about"]*k, lin["halfWidth"]*k,
                    lin["halfWidthCheck"]*k)
            text += "; " + ", ".join("%s %.4g" % (v, rows[v][col]*k)
                                     for v in variants)
            lines.append(text)
    tmp = os.path.join(out, "uncertainty.csv.tmp")
    with open(tmp, "w") as f:
        f.write("\n".join(csv) + "\n")
    os.replace(tmp, os.path.join(out, "uncertainty.csv"))
    written.insert(0, os.path.join(out, "uncertainty.csv"))
    print("\n".join(lines))
    return errors, written


def _uncertaintyFigure(plt, s, out, g, rows, result, targets, variants):
    """uncertainty_<label>.png: one panel per indicator, its value per
    target for the base case, each variant, and the linearised interval
    about 'about' as an error bar."""
    u = s["uncertainty"]
    fig, axs = _figure(len(di.INDICATORS))
    x = np.arange(len(targets))
    names = ["base"] + variants
    markers = "os^vDPX*<>"
    width = 0.8/len(names)
    for ax, ind in zip(axs, di.INDICATORS):
        unit = di.UNITS[ind]
        k, shown = _shown(ind)
        for n, name in enumerate(names):
            y = np.array([rows[name]["%s:%s [%s]" % (t, ind, unit)]
                          for t in targets])*k
            xx = x - 0.4 + width*(n + 0.5)
            err = None
            if name == u.get("about") or (name == "base" and
                                          u.get("about") == "base"):
                err = np.array([result["%s:%s [%s]" % (t, ind, unit)]
                                ["halfWidth"] for t in targets])*k \
                    if result else None
            ax.errorbar(xx, y, yerr=err, fmt=markers[n % len(markers)],
                        capsize=4, label=name + (
                            " +- its 95 % half-width (linearised)"
                            if err is not None else ""))
            if err is not None:
                # the half-width written: most are far below the marker
                for a, b, e in zip(xx, y, err):
                    if np.isfinite(e):
                        ax.annotate("+-%.2g" % e, (a, b), fontsize=6,
                                    xytext=(3, -9),
                                    textcoords="offset points")
        ax.set_xticks(x)
        ax.set_xticklabels(targets, rotation=20, fontsize=7)
        ax.set_ylabel("[%s]" % shown)
        ax.set_title(LABELS[ind], fontsize=9)
        ax.grid(alpha=0.3)
    axs[0].legend(fontsize=6)
    fig.suptitle("%g MPa, %g ns: the indicators per target for the base case"
                 " and each material variant%s" % (
                     g["overpressure"]*1e-6, g["duration"]*1e9,
                     "; the calibration's 95 %% intervals carried by "
                     "linearisation about '%s'" % u["about"]
                     if u["parameters"] else ""), fontsize=9)
    fig.tight_layout()
    path = os.path.join(out, "uncertainty_%s.png" % g["label"])
    script.saveFigure(fig, path, dpi=110)
    plt.close(fig)
    return path


def _fig10Band(plt, s, out, g, records):
    """fig10_<label>.png: probe 0 (cytoplasm-nucleus interface, 75 % of the
    nucleus height: paper Fig. 10) against time for the base case and each
    variant, the linearised 95 % band about 'about' (every run
    interpolated on the times of 'about')."""
    u = s["uncertainty"]

    def probe(name):
        label = g["label"] if name == "base" else "%s_%s" % (g["label"], name)
        return records[label]["series"].get("probe")

    ref = probe(u["about"])
    runs = ["base"] + list(u["variants"]) + [n for n, _ in unc.runs(u)]
    if any(probe(n) is None for n in runs):
        return None             # records of before the probe's series
    t = np.array(ref["t"])
    fig, axs = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    for ax, (key, k, ylabel) in zip(axs.flat, PROBE):
        def value(name):
            p = probe(name)
            return np.interp(t, p["t"], p[key])
        lin = unc.propagate(u, value)
        for name in ["base"] + list(u["variants"]):
            p = probe(name)
            if name == u["about"]:
                continue
            ax.plot(np.array(p["t"])*1e9, np.array(p[key])*k, lw=0.8,
                    label=name)
        ax.plot(t*1e9, lin["about"]*k, "k", lw=1.0, label=u["about"])
        ax.fill_between(t*1e9, (lin["about"] - lin["halfWidth"])*k,
                        (lin["about"] + lin["halfWidth"])*k, color="k",
                        alpha=0.25, lw=0,
                        label="%s: 95 %% band (linearised)" % u["about"])
        H = lin["halfWidth"]*k
        top = np.nanmax(np.abs(lin["about"]*k))
        i = int(np.nanargmax(H))
        ax.text(0.02, 0.03, "band: half-width at most %.2g (%.2g %% of the "
                "largest |value|), at %.1f ns" % (H[i], 100*H[i]/top,
                                                  t[i]*1e9),
                transform=ax.transAxes, fontsize=7)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    for ax in axs[1]:
        ax.set_xlabel("time [ns]")
    axs[0, 0].legend(fontsize=7)
    fig.suptitle("Cytoplasm-nucleus interface, 75 %% of the nucleus height "
                 "(paper Fig. 10), %g MPa, %g ns: material variants and the "
                 "calibration's 95 %% band" % (g["overpressure"]*1e-6,
                                               g["duration"]*1e9),
                 fontsize=9)
    fig.tight_layout()
    path = os.path.join(out, "fig10_%s.png" % g["label"])
    script.saveFigure(fig, path, dpi=110)
    plt.close(fig)
    return path


def main():
    ap = argparse.ArgumentParser(prog="pulseStudy", description="Run the "
                                 "blast scene over a grid of pulses and map "
                                 "the damage indicators")
    ap.add_argument("-case", default=".")
    ap.add_argument("-keep", action="store_true")
    ap.add_argument("-dict", default=ps.DICT)
    a = options.parse(ap)
    global OUT
    try:
        case = os.path.abspath(a.case)
        # the case path once, before anything runs: every point runs in a
        # folder under it (adv29 z5: each point failed with an unrelated
        # error of its Allrun)
        problem = options.casePathProblem(case)
        if problem:
            raise ps.StudyError(problem)
        # one study per folder: the run lock of the study's folder (the
        # solvers' .runLock, neuronFsi.caseLock), held to the end. A
        # second study started beside a running one took the first's
        # point for interrupted and moved its running case copy aside
        # (adv46b d34); an Allrun that runs the study holds it already
        try:
            caseLock.held(case, "pulseStudy").__enter__()
        except caseLock.CaseLockError as err:
            raise ps.StudyError("%s. Nothing was run or moved" % err)
        s = ps.read(case, a.dict)
        OUT = ps.output(a.dict)
        out = os.path.join(case, OUT)
        os.makedirs(os.path.join(out, "points"), exist_ok=True)
        for path in removeTemporaryFiles(out):
            print("pulseStudy: removed %s, the temporary file of an earlier "
                  "study stopped while it wrote its tables"
                  % os.path.relpath(path, case), flush=True)
        # a run left going by a study killed with SIGKILL: refused before
        # anything is removed or started (adv33 x07)
        for label in sorted(os.listdir(os.path.join(out, "points"))):
            caseRuns.checkNoEarlierRun(
                os.path.join(out, "points", label, "case"))
        # a file the base case reads from outside its folder by a path
        # relative to it: the points' copies read another one (adv45 b15)
        problem = caseRuns.relativeOutsideProblem(
            s["base"], "The study runs copies of the base case in %s"
            % os.path.join(out, "points", "<label>", "case"))
        if problem:
            raise ps.StudyError(problem)
        staging, digests = prepareBase(s, out)
        outside = ps.outsideInputs(staging)
        pts = ps.points(s)
        upts = ps.uncertaintyPoints(s)
        todo, records = [], {}
        for p in pts + upts:
            folder = os.path.join(out, "points", p["label"])
            p["folder"] = folder
            p["inputs"] = ps.inputs(digests, p, outside)
            p["inputs"]["strainRateWindow"] = s["window"]
            r = ps.readRecord(os.path.join(folder, "result.json"), p)
            if r is None:
                todo.append(p)
                continue
            diff = ps.differences(r["inputs"], p["inputs"])
            if r["inputs"].get("strainRateWindow") != s["window"]:
                diff.append(("strainRateWindow", "%s s then, %g s now" % (
                    r["inputs"].get("strainRateWindow"), s["window"])))
            if diff:
                raise ps.StudyError(
                    "%s: entry '%s' differs from that of the finished point "
                    "%s (%s): its result would not be that of this "
                    "dictionary. Nothing was run: restore the entry (or "
                    "the file named), or move %s away to start the study "
                    "over"
                    % (s["dict"], diff[0][0], p["label"], diff[0][1],
                       os.path.join(out, "points")))
            records[p["label"]] = r
        print("pulseStudy: %d points (%d overpressures x %d durations)%s, "
              "%d finished earlier, %d to run, %d at a time; base case %s"
              % (len(pts), len(s["overpressure"]), len(s["duration"]),
                 " and %d runs of the uncertainty (%d per pulse at %d "
                 "pulses)" % (len(upts), len(upts)//len(
                     s["uncertainty"]["pulses"]), len(
                         s["uncertainty"]["pulses"])) if upts else "",
                 len(records), len(todo), s["nProcs"], s["base"]),
              flush=True)
        for p in pts + upts:
            if p["label"] in records:
                print("    %s: finished earlier (%s), not run"
                      % (p["label"], os.path.relpath(os.path.join(
                          p["folder"], "result.json"), case)), flush=True)
        failed = []

        def job(p):
            t0 = time.time()
            try:
                r = runPoint(s, staging, p, p["inputs"], p["folder"], a.keep)
            except (caseRuns.RunError, di.IndicatorError, OSError,
                    postProcessing.ColumnFileError,
                    unc.UncertaintyError) as err:
                if signals.stopped():       # ended by the stop, not failed
                    return None
                failed.append((p["label"], str(err)))
                print("    %s: FAILED after %.1f s: %s" % (
                    p["label"], time.time() - t0, err), flush=True)
                return None
            print("    %s: overpressure %g Pa, duration %g s%s: done (wall "
                  "%.1f s, solver CPU %.1f s)" % (
                      p["label"], p["overpressure"], p["duration"],
                      ", uncertainty run %s" % p["run"] if "run" in p
                      else "", r["wall"], r["cpu"]), flush=True)
            return r

        for p, r in zip(todo, caseRuns.inParallel(s["nProcs"], job, todo)):
            if r is not None:
                records[p["label"]] = r
        if failed:
            raise ps.StudyError(
                "%d of %d points failed (%s): no table written; the "
                "finished points are kept, a new run runs the failed ones "
                "again" % (len(failed), len(todo), "; ".join(
                    "%s: %s" % f for f in failed)))
        rows, atEnd = [], {}
        for p in pts:
            row, ends = rowOf(s, records[p["label"]])
            rows.append(row)
            for col, e in ends.items():
                if e:
                    atEnd.setdefault(col, {})[p["label"]] = True
        targets = list(records[pts[0]["label"]]["series"]["targets"])
        writeTable(s, out, rows)
        for r, p in zip(rows, pts):
            r["label"] = p["label"]
        errors = {}
        if upts:
            errors, written = writeUncertainty(s, out, pts, records,
                                               targets)
        maps = writeMaps(s, out, rows, targets, atEnd, errors)
        # what the writes miss: the interfaces' peaks over the writes
        # against those of every step
        miss = {"pressure": [], "vonMises": []}
        for p in pts:
            ser = records[p["label"]]["series"]
            for name, step in ser["interfaces"].items():
                for k, ind in ((1, "pressure"), (2, "vonMises")):
                    w = di.peak(np.array(ser["targets"][name][ind], float))
                    miss[ind].append((1 - w/max(step[k]), p["label"], name))
        if miss["pressure"]:
            print("Sampling every %g s: the interface peaks over the writes "
                  "are below those of every step by %s" % (
                      s["sampleInterval"], ", ".join(
                          "%s to %s %% (%s; largest: %s %s)" % (
                              _percent(min(m)[0]), _percent(max(m)[0]), ind,
                              max(m)[1], max(m)[2])
                          for ind, m in miss.items())))
        if atEnd:
            print("Peaks at the run's last write (still rising at its end: "
                  "a later end time gives larger ones): " + "; ".join(
                      "%s %s" % (c, " ".join(sorted(v)))
                      for c, v in atEnd.items()))
        print("Written %s/table.{csv,h5} and %d maps (%s)" % (
            OUT, len(maps), " ".join(os.path.basename(m) for m in maps)))
        if upts:
            print("Written %s/%s" % (OUT, " ".join(
                os.path.basename(w) for w in written)))
        return 0
    except (ps.StudyError, caseRuns.RunError, OSError) as err:
        print("pulseStudy: error: %s" % err, file=sys.stderr)
        return 1


if __name__ == "__main__":
    # SIGTERM, SIGHUP, SIGINT end the runs started (signals.call) and exit
    # 128 + the signal: the interrupted points run again next time
    with signals.stopOn("pulseStudy"):
        sys.exit(main())
