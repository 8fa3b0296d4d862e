#!/usr/bin/python3
"""Where a probe's incident 1-ns peak is reached (planeWave's
peakIncident) in a finished blast case, and when the echo from the
substrate reaches the probe in the scene and in the 1D answer.

    incidentWindow.py CASE [--level P] [--foot P] [--series T0 T1 DT]

Reads the case's probes (neuronFsi.planeWave.caseProbes) and the
reference planeWave wrote (CASE/postProcessing/planeWave/0/reference.dat:
the solid probes against the 1D answer along their material paths, the
water probes at their heights), and prints per probe:
  - the incident window of planeWave.measures (1-ns window centres from
    the reference's arrival ta to ta + min(T, 2 z/(1.1 c0)) - 0.5 ns) and
    the scene's and the reference's largest 1-ns mean in it, with the
    centre where the scene's is reached;
  - the same with the window's last 0.5 ns left out (centres to
    ta + min(T, echo) - 1 ns), for the diagnosis only;
  - the whole-history 1-ns peak (planeWave's peak1ns), scene and
    reference, and the centres where each is reached;
  - the first time after ta + 2 ns at which p reaches --level (default
    75 MPa: half way between the 50 MPa incident wave and its 104 MPa
    reflection), scene and reference: the echo's arrival, and its
    difference [ns]; the same for --foot (default 55 MPa, a tenth of
    the way up): the echo's foot;
  - the scene's largest sample in the incident window (times ta to
    ta + min(T, echo) - 0.5 ns, no mean) and its time: whether the
    window's 1-ns peak is a raw value inside the window or a mean
    reaching past its end.
With --series (times in ns): then p [MPa] of every probe, scene and
reference, at T0, T0 + DT, ... T1 (the sample at or after each time).
Not a check; docs/results/blast3D.md, "The 10 and 15 ns pulses at the
item-1 setting".
"""
import argparse
import math
import os
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import planeWave as pw
from neuronFsi import options, resultDigest
from neuronFsi.postProcessing import ColumnFileError


def pressure(text):
    """--level, --foot: a finite pressure in (0, 1e9] Pa (adv51 m06: nan,
    inf, -1, 1e400 accepted; nan printed every echo column as "-")"""
    v = float(text)
    if not (math.isfinite(v) and 0 < v <= 1e9):
        raise argparse.ArgumentTypeError("%s is not a pressure in the valid "
                                         "range (0, 1e9] Pa" % text)
    return v


def nanoseconds(text):
    """--series' times: finite, in [0, 1e9] ns"""
    v = float(text)
    if not (math.isfinite(v) and 0 <= v <= 1e9):
        raise argparse.ArgumentTypeError("%s is not a time in the valid "
                                         "range [0, 1e9] ns" % text)
    return v


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("--level", type=pressure, default=75e6)
    ap.add_argument("--foot", type=pressure, default=55e6)
    ap.add_argument("--series", type=nanoseconds, nargs=3, default=None)
    ap.add_argument("--accept-hand-made", action="store_true",
                    help="measure a reference.dat and probe logs that do "
                    "not carry their run's digests or differ from them "
                    "(made or edited by hand): refused by default")
    # negative values as values, an option given twice refused (adv53
    # u14: "--series 0 2 -1e-3" was "expected 3 arguments", a second
    # --series replaced the first without a word)
    a = options.parse(ap)
    # the reference and the logs as their runs wrote them (adv52 p06b)
    resultDigest.measuring("--accept-hand-made", a.accept_hand_made)
    if a.series and not (a.series[1] >= a.series[0] and a.series[2] > 0):
        ap.error("--series T0 T1 DT: T1 must not be before T0 and DT must "
                 "be positive")
    # the rows it prints, bounded (adv52 p34: DT 1e-6 ns over 1e6 ns asked
    # numpy for 7.28 TiB, a traceback; over 100 ns 1e8 rows printed for
    # hours)
    maxRows = 100000
    if a.series and (a.series[1] - a.series[0])/a.series[2] + 1 > maxRows:
        ap.error("--series %g %g %g would print %.3g rows, more than %d: a "
                 "longer DT or a shorter span" % (a.series[0], a.series[1],
                                                  a.series[2],
                                                  (a.series[1] - a.series[0])
                                                  / a.series[2] + 1, maxRows))
    # a folder that is no case, or a case planeWave never ran on: one
    # line, no traceback (adv50b k20)
    if not os.path.isfile(os.path.join(a.case, "system", "controlDict")):
        print("incidentWindow.py: %s is not a case (no system/controlDict)"
              % a.case, file=sys.stderr)
        return 1
    refFile = os.path.join(a.case, "postProcessing", "planeWave", "0",
                           "reference.dat")
    if not os.path.lexists(refFile):
        print("incidentWindow.py: %s: no planeWave reference (%s): write it "
              "with planeWave -case %s" % (a.case, refFile, a.case),
              file=sys.stderr)
        return 1
    try:
        ref = pw.readReference(refFile)
        amplitude, duration = pw.pulseShape(pw.appliedPressure(a.case))
        probes = list(pw.caseProbes(a.case))
    except (pw.PlaneWaveError, ColumnFileError, resultDigest.DigestError,
            OSError) as e:
        print("incidentWindow.py: error: %s" % e, file=sys.stderr)
        return 1
    c0 = 1450.0     # [m/s] planeWave.measures' default, as planeWave uses
    print("# probe  z[um]  window[ns]  peakIncident scene/ref [MPa] (err %%) "
          "at centre [ns] | window less 0.5 ns: scene/ref (err %%) | "
          "peak1ns scene/ref [MPa] (err %%) at centres [ns] | "
          "echo at %g MPa, at %g MPa: scene/ref [ns] (diff) | "
          "raw max in the window, scene [MPa] at [ns]"
          % (a.level/1e6, a.foot/1e6))
    series = []
    # probes above the mesh's water (caseProbes returns them unchecked):
    # OpenFOAM's fill -1e300 is no pressure (adv51 m06: printed as
    # -1e+294 MPa in --series)
    top = pw.meshTop(a.case)
    for name, z, t, p in probes:
        if top is not None and z > top*(1 + 1e-9):
            print("%s  %.3f  above the water (the mesh's water ends at "
                  "%.3f um): outside the mesh, not measured"
                  % (name.replace(" ", "_"), z*1e6, top*1e6))
            continue
        if name.startswith("solid "):
            m = ref.material.get(min(ref.material, key=lambda h: abs(h - z)))
            tr, pr = ref.t, m["p"]
        else:
            k = int(np.argmin(np.abs(np.asarray(ref.heights) - z)))
            tr, pr = ref.t, ref.p[:, k]
        ta = pw.arrival(tr, pr, amplitude)
        if ta is None:
            # the wave has not reached the probe's height in the 1D answer
            # by the run's end (adv50b k21: a TypeError): said, the other
            # probes measured
            print("%s  %.3f  no arrival of the incident wave in the "
                  "reference by t = %.2f ns: not measured"
                  % (name.replace(" ", "_"), z*1e6, tr[-1]*1e9))
            continue
        # a history shorter than the 1-ns window has no 1-ns mean (adv51
        # m06: "argmax of an empty sequence", a traceback)
        short = [w for w, tt in (("scene", t), ("reference", tr))
                 if len(tt) < 2 or tt[-1] - tt[0] < 1e-9]
        if short:
            print("%s  %.3f  the %s history is shorter than the 1-ns "
                  "window: not measured" % (name.replace(" ", "_"), z*1e6,
                                            " and ".join(short)))
            continue
        echo = 2*z/(1.1*c0)
        end = ta + min(duration, echo) - 0.5e-9
        row = [name.replace(" ", "_"), "%.3f" % (z*1e6),
               "%.2f-%.2f" % (ta*1e9, end*1e9)]
        for e in (end, end - 0.5e-9):
            vals = []
            for tt, pp in ((t, p), (tr, pr)):
                tc, mean = pw.runningMean(tt, pp, 1e-9)
                sel = (tc >= ta) & (tc <= e)
                i = np.argmax(np.where(sel, mean, -np.inf))
                vals.append((mean[i], tc[i]))
            err = 100*(vals[0][0]/vals[1][0] - 1)
            row.append("%.2f/%.2f (%+.2f %%)%s" % (
                vals[0][0]/1e6, vals[1][0]/1e6, err,
                " at %.2f" % (vals[0][1]*1e9) if e == end else ""))
        pk = []
        for tt, pp in ((t, p), (tr, pr)):
            tc, mean = pw.runningMean(tt, pp, 1e-9)
            i = int(np.argmax(mean))
            pk.append((mean[i], tc[i]))
        row.append("%.2f/%.2f (%+.2f %%) at %.2f/%.2f" % (
            pk[0][0]/1e6, pk[1][0]/1e6, 100*(pk[0][0]/pk[1][0] - 1),
            pk[0][1]*1e9, pk[1][1]*1e9))
        for level in (a.level, a.foot):
            es = pw.crossingAfter(t, p, ta + 2e-9, level)
            er = pw.crossingAfter(tr, pr, ta + 2e-9, level)
            row.append("%s/%s (%s)" % (
                "-" if es is None else "%.2f" % (es*1e9),
                "-" if er is None else "%.2f" % (er*1e9),
                "-" if es is None or er is None
                else "%+.2f" % ((es - er)*1e9)))
        raw = np.flatnonzero((t >= ta) & (t <= end))
        if len(raw):
            k = raw[np.argmax(p[raw])]
            row.append("%.2f at %.3f" % (p[k]/1e6, t[k]*1e9))
        else:
            row.append("-")
        print("  ".join(row))
        series.append((name.replace(" ", "_"), t, p, tr, pr))
    if a.series:
        t0, t1, dt = a.series
        print("# t [ns]  " + "  ".join("%s scene/ref [MPa]" % s[0]
                                       for s in series))
        for tt in np.arange(t0, t1 + 0.5*dt, dt)*1e-9:
            vals = []
            for _, t, p, tr, pr in series:
                i = min(np.searchsorted(t, tt), len(t) - 1)
                j = min(np.searchsorted(tr, tt), len(tr) - 1)
                vals.append("%.2f/%.2f" % (p[i]/1e6, pr[j]/1e6))
            print("%.2f  " % (tt*1e9) + "  ".join(vals))


if __name__ == "__main__":
    sys.exit(main())
