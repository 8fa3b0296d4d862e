#!/usr/bin/python3
"""Assertions on a pulseStudy run with -keep (pulseStudy.sh): its table
against each point's own outputs, read here directly (h5py, numpy), not
through the study's code: the same doubles (table.csv has every digit;
interfaceMaxima.dat 10 digits).
usage: checkPulseStudy.py studyCase"""
import csv
import os
import sys

import h5py
import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import msh, planeWave, postProcessing
from neuronFsi.checks import Checks

study = sys.argv[1]
out = os.path.join(study, "postProcessing/pulseStudy")
check = Checks()

with open(os.path.join(out, "table.csv")) as f:
    rows = list(csv.DictReader(f))
check(len(rows) == 2, "table.csv: 2 rows (%d)" % len(rows))
for png in ("map_pressure", "map_vonMises", "map_strain", "map_strainRate",
            "map_temperatureRise"):
    check(os.path.getsize(os.path.join(out, png + ".png")) > 0,
          "%s.png written" % png)
with h5py.File(os.path.join(out, "table.h5")) as h:
    check(np.array_equal(h["table/overpressure"][()],
                         [float(r["overpressure [Pa]"]) for r in rows]),
          "table.h5 overpressure column = table.csv's")
    check(len(h["thresholds"]) == 3, "table.h5: the 3 thresholds")

peaks = {}
for r in rows:
    A, T = float(r["overpressure [Pa]"]), float(r["duration [s]"])
    case = os.path.join(out, "points", "p%.6g_T%.6g" % (A, T), "case")
    # the overpressure reached the pulse: the table of 0/p's top
    amp, dur = planeWave.pulseShape(planeWave.appliedPressure(case))
    check(amp == A, "%s: 0/p pulse amplitude %g Pa = overpressure %g Pa"
          % (case, amp, A))
    check(abs(dur - T) < 1e-15, "%s: 0/p pulse duration %g s = %g s"
          % (case, dur, T))
    names = msh.physicalNames(os.path.join(case, "constant/cell.msh"), 2)
    with h5py.File(os.path.join(case, "solid/solid.h5")) as f:
        region = f["mesh/region"][()]
        conn = f["mesh/connectivity"][()]
        steps = sorted(f["steps"], key=int)
        t = np.array([f["steps"][k].attrs["time"] for k in steps])
        p = np.array([f["steps"][k]["pressure"][()] for k in steps])
        vm = np.array([f["steps"][k]["vonMises"][()] for k in steps])
        dT = np.array([f["steps"][k]["temperatureRise"][()] for k in steps])
    check(np.allclose(np.diff(t), 0.5e-9, rtol=1e-6, atol=0),
          "solid.h5 written every 0.5 ns (%d writes)" % len(t))
    for i, n in enumerate(names):
        m = region == i
        for col, ref in (("pressure [Pa]", p[:, m].max()),
                         ("vonMises [Pa]", vm[:, m].max())):
            check.relative("%s %s peak" % (n, col),
                           float(r["%s:%s" % (n, col)]), ref, 0)
        if n != "membrane":
            check.relative("%s temperature rise peak" % n,
                           float(r["%s:temperatureRise [K]" % n]),
                           dT[:, m].max(), 0)
        else:
            check(r["membrane:temperatureRise [K]"] == "nan",
                  "membrane temperature rise: none (no energy equation)")
    peaks[A] = float(r["nucleus:pressure [Pa]"])
    # the interfaces: the solver's maxima of every step
    log = "solidInterfaces/interfaceMaxima.dat"
    d = postProcessing.series(case, log)
    cols = postProcessing.names(case, log)
    for k in range(1, len(cols), 2):
        iface = cols[k].split(":", 1)[1]
        check.relative("%s pressure peak = max of interfaceMaxima.dat"
                       % iface, float(r["%s:pressure [Pa]" % iface]),
                       d[:, k].max(), 0)
        check.relative("%s von Mises peak = max of interfaceMaxima.dat"
                       % iface, float(r["%s:vonMises [Pa]" % iface]),
                       d[:, k + 1].max(), 0)
        # the elements along it (either side, sharing a node with the
        # other region), from solid.h5 at the write times: the solver's
        a, b = (names.index(x) for x in iface.split("-"))
        nodesA = np.isin(np.arange(conn.max() + 1), conn[region == a])
        nodesB = np.isin(np.arange(conn.max() + 1), conn[region == b])
        m = ((region == a) & nodesB[conn].any(axis=1)) \
            | ((region == b) & nodesA[conn].any(axis=1))
        rows_t = [np.argmin(abs(d[:, 0] - x)) for x in t]
        solver = d[rows_t, k]
        ours = p[:, m].max(axis=1)
        err = np.abs(ours - solver).max()/np.abs(solver).max()
        check(err < 1e-9, "%s: solid.h5 interface pressure maxima at the %d"
              " writes = the solver's (largest difference %.2e of the "
              "peak)" % (iface, len(t), err))

check.relative("nucleus peak pressure 30 MPa / 50 MPa (scales with the "
               "overpressure)", peaks[30e6]/peaks[50e6], 0.6, 0.05)
sys.exit(check.exitStatus())
