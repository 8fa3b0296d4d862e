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
    interrupted (a folder without a result) is run again from the start.
    The record carries the digest of its own values and its point,
    verified on every read: a damaged record, or another point's, is
    refused naming the file (nothing runs; it is left for the user).
    A dictionary whose inputs differ from those of the finished points
    (another base case or options) is refused with the entry named:
    nothing is run (move postProcessing/pulseStudy/points away to start
    over). Thresholds may change between runs (no point runs again).

    Writes postProcessing/pulseStudy/table.csv and table.h5 (one row per
    point) and the maps postProcessing/pulseStudy/map_<indicator>.png and
    timeAbove_<threshold>.png (overpressure x duration, one panel per
    region and interface, the thresholds drawn as contours).

Usage
    pulseStudy [-case dir] [-keep]

    -keep    keep each point's case (postProcessing/pulseStudy/points/
             <label>/case; default: removed once its result is recorded)

\\*---------------------------------------------------------------------------*/
"""

import argparse
import math
import os
import shlex
import shutil
import sys
import textwrap
import time

import numpy as np

from neuronFsi import (caseRuns, damageIndicators as di, logs, options,
                       postProcessing, pulseStudy as ps, signals)

OUT = "postProcessing/pulseStudy"
LABELS = {"pressure": "peak pressure", "vonMises": "peak von Mises stress",
          "strain": "peak largest principal Green-Lagrange strain",
          "strainRate": "peak strain rate",
          "temperatureRise": "peak temperature rise"}
SCALE = {"Pa": (1e-6, "MPa"), "-": (1, "-"), "1/s": (1, "1/s"),
         "K": (1, "K")}


def prepareBase(s, out):
    """A copy of the base case after its Allclean (out/base), from which
    every point's case is copied; {file: digest} of its files."""
    staging = os.path.join(out, "base")
    if os.path.lexists(staging):
        shutil.rmtree(staging)
    shutil.copytree(s["base"], staging, symlinks=True)
    if os.path.isfile(os.path.join(staging, "Allclean")):
        # the log outside the copy: an Allclean removes log.*
        log = os.path.join(out, "log.Allclean")
        caseRuns.runIn(staging, "./Allclean", log)
        os.remove(log)
    return staging, ps.fileDigests(staging)


def runPoint(s, staging, point, inputs, folder, keep):
    """Run one point in folder/case; its record."""
    if os.path.lexists(folder):         # interrupted earlier: from scratch
        shutil.rmtree(folder)
    os.makedirs(folder)
    case = os.path.join(folder, "case")
    shutil.copytree(staging, case, symlinks=True)
    command = "./Allrun " + " ".join(shlex.quote(o) for o in point["options"])
    wall = caseRuns.runIn(case, command, "log.pulseStudy")
    t, series = di.series(case, s["window"])
    interfaces = di.interfaceMaxima(case)
    cpu = logs.executionTime(os.path.join(case, "log.cellBlastFoam"))[0]
    record = {
        "inputs": inputs, "label": point["label"],
        "overpressure": point["overpressure"],
        "duration": point["duration"], "wall": wall, "cpu": cpu,
        "series": {"t": t.tolist(),
                   "targets": {k: {i: v.tolist() for i, v in d.items()}
                               for k, d in series.items()},
                   "interfaces": {k: [x.tolist() for x in v]
                                  for k, v in interfaces.items()}}}
    ps.writeRecord(os.path.join(folder, "result.json"), record)
    if not keep:
        shutil.rmtree(case)
    return record


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


def _panel(ax, A, T, Z, title, unit, levels=(), atEnd=None):
    """One map: Z [len(A), len(T)] over overpressure A [Pa] x duration T
    [s]; threshold contours (value, name, style) where the map crosses
    them; atEnd [len(A), len(T)]: the points whose peak is the run's last
    write, marked '*'."""
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


def writeMaps(s, out, rows, targets, atEnd):
    """map_<indicator>.png and timeAbove_<threshold>.png; atEnd: {column:
    {label: whether its peak is the last write}}"""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    A, T = s["overpressure"], s["duration"]
    styles = ["-", "--", ":", "-."]

    def grid(col, values=None):
        Z = np.full((len(A), len(T)), math.nan)
        for r in rows:
            i, j = A.index(r["overpressure [Pa]"]), T.index(r["duration [s]"])
            Z[i, j] = r[col] if values is None else values.get(r["label"], 0)
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
                   ends)
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
        fig.suptitle("\n".join(lines), fontsize=10)
        fig.tight_layout()
        p = os.path.join(out, "map_%s.png" % ind)
        fig.savefig(p, dpi=110)
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
        fig.savefig(p, dpi=110)
        plt.close(fig)
        written.append(p)
    return written


def main():
    ap = argparse.ArgumentParser(prog="pulseStudy", description="Run the "
                                 "blast scene over a grid of pulses and map "
                                 "the damage indicators")
    ap.add_argument("-case", default=".")
    ap.add_argument("-keep", action="store_true")
    a = options.parse(ap)
    try:
        case = os.path.abspath(a.case)
        # the case path once, before anything runs: every point runs in a
        # folder under it (adv29 z5: each point failed with an unrelated
        # error of its Allrun)
        problem = options.casePathProblem(case)
        if problem:
            raise ps.StudyError(problem)
        s = ps.read(case)
        out = os.path.join(case, OUT)
        os.makedirs(os.path.join(out, "points"), exist_ok=True)
        staging, digests = prepareBase(s, out)
        pts = ps.points(s)
        todo, records = [], {}
        for p in pts:
            folder = os.path.join(out, "points", p["label"])
            p["folder"] = folder
            p["inputs"] = ps.inputs(digests, p)
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
                    "dictionary. Nothing was run: restore the entry, or "
                    "move %s away to start the study over"
                    % (s["dict"], diff[0][0], p["label"], diff[0][1],
                       os.path.join(out, "points")))
            records[p["label"]] = r
        print("pulseStudy: %d points (%d overpressures x %d durations), %d "
              "finished earlier, %d to run, %d at a time; base case %s"
              % (len(pts), len(s["overpressure"]), len(s["duration"]),
                 len(records), len(todo), s["nProcs"], s["base"]),
              flush=True)
        for p in pts:
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
                    postProcessing.ColumnFileError) as err:
                if signals.stopped():       # ended by the stop, not failed
                    return None
                failed.append((p["label"], str(err)))
                print("    %s: FAILED after %.1f s: %s" % (
                    p["label"], time.time() - t0, err), flush=True)
                return None
            print("    %s: overpressure %g Pa, duration %g s: done (wall "
                  "%.1f s, solver CPU %.1f s)" % (
                      p["label"], p["overpressure"], p["duration"],
                      r["wall"], r["cpu"]), flush=True)
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
        maps = writeMaps(s, out, rows, targets, atEnd)
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
        return 0
    except (ps.StudyError, caseRuns.RunError, OSError) as err:
        print("pulseStudy: error: %s" % err, file=sys.stderr)
        return 1


if __name__ == "__main__":
    # SIGTERM, SIGHUP, SIGINT end the runs started (signals.call) and exit
    # 128 + the signal: the interrupted points run again next time
    with signals.stopOn("pulseStudy"):
        sys.exit(main())
