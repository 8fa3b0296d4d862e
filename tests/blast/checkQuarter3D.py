#!/usr/bin/python3
"""Assertions on a run of tutorials/blast/quarter3D (quarter3DSmoke.sh):
map check against the exact projected areas, arrival time at the probe,
coupling convergence, no NaN, and the fluid points of the symmetry planes
and the substrate still exactly on their planes at the last time (edges
and the axis, where two planes meet, included).
usage: checkQuarter3D.py case L [arrival|atRest|refineCell]   (L: side of
the water cube [m]; atRest: a run that ends before the pulse reaches the
cell: the map, convergence, no NaN, and the interface stays at rest,
round-off velocities below 1e-9 m/s, instead of the arrival; refineCell:
atRest on a case prepared with Allrun -refineCell: also the water's faces
on the cell four times cellMesh's (constant/fluid.msh), split-face
polyhedra around the refined cells, checkMesh clean, the geometric
conservation error round-off)"""
import glob
import math
import os
import re
import sys
import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import (cellRefinement, foamDict, foamField, logs, msh,
                       postProcessing)
from neuronFsi.checks import Checks

case, L = sys.argv[1], float(sys.argv[2])
mode = sys.argv[3] if len(sys.argv) > 3 else "arrival"
if mode not in ("arrival", "atRest", "refineCell"):
    sys.exit(f"checkQuarter3D.py: mode {mode}: arrival, atRest or "
             "refineCell")
refined = mode == "refineCell"
if refined:
    mode = "atRest"
a, H = 8.4e-6, 7.9e-6
check = Checks()


# Allrun -refineCell: the water's faces on the cell four times those of
# cellMesh's water (its physical group cellInterface), the refined cells'
# neighbours split-face polyhedra, the mesh clean
if refined:
    n0 = len(msh.read(f"{case}/constant/fluid.msh")[1]["cellInterface"][1])
    n1 = cellRefinement.interfaceFaces(f"{case}/constant/polyMesh/boundary")
    check(n1 == 4*n0, f"refined interface: {n1} water faces on the cell "
          f"against cellMesh's {n0} (4x asked)")
    text = open(f"{case}/log.checkMesh").read()
    poly = [int(x) for x in re.findall(r"polyhedra:\s+(\d+)", text)]
    check("Mesh OK." in text and bool(poly) and poly[-1] > 0,
          f"checkMesh of the refined water: 'Mesh OK.' "
          f"{'Mesh OK.' in text}, polyhedra {poly[-1] if poly else None} "
          "(> 0: the refined cells' neighbours)")

# Unit pressure on the quarter cell surface: the force is minus the
# projected areas, pi a H/4 on x = 0 and y = 0 (quarter ellipses) and
# pi a^2/4 on z = 0; the fluid's surface is inscribed (faces of about
# 1 um on radii of 8 um: areas about 0.5 % smaller)
log = f"{case}/log.cellBlastFoam"
fluid, solid = logs.fsiMapCheck(log)
exact = [-math.pi*a*H/4, -math.pi*a*H/4, -math.pi*a*a/4]
for i, c in enumerate("xyz"):
    check.relative(f"map conservation, {c}", solid[i], fluid[i], 1e-12)
    check.relative(f"unit-pressure force {c} = minus the projected area",
                   fluid[i], exact[i], 1e-2)

# load pressure (the fluid pressure on the solid's own faces): its total
# force for a unit pressure is the solid surface's, within 1 % of the exact
# projected areas and 0.5 % of the fluid's (two discretized surfaces)
m = logs.pressureLoadCheck(log)
pressureLoad = foamDict.read(f"{case}/constant/fsiProperties").get(
    "interface", {}).get("load") == "pressure"
if pressureLoad and not m:
    check(False, "load pressure is set, but the log has no unit-pressure "
          "check of it")
if m:
    ps, pf = m
    for i, c in enumerate("xyz"):
        check.relative(f"pressure load, unit-pressure force {c} = minus "
                       "the projected area", ps[i], exact[i], 1e-2)
        check.relative(f"pressure load against the fluid's force, {c}",
                       ps[i], pf[i], 5e-3)

# Arrival at the probe (its reference point from the header)
zc = postProcessing.probes(case)[0]["point"][2]
d = postProcessing.series(case, "solidProbes/solidProbes.dat")
if not np.isfinite(d).all():
    check(False, "NaN or Inf in solidProbes.dat")
    sys.exit(1)
t, p = d[:, 0], d[:, 1]
c = postProcessing.series(case, "fsi/coupling.dat")
if mode == "atRest":
    vmax = c[:, 8].max()
    check(vmax < 1e-9 and abs(p).max() < 1.0,
          f"at rest to {c[-1, 0]:.4g} s: largest"
          f" interface velocity {vmax:.3g} m/s (< 1e-9), probe pressure"
          f" {abs(p).max():.3g} Pa (< 1)")
rho0, C0, s, pulse = 1000.0, 1450.0, 1.99, 50e6
up = (-C0 + math.sqrt(C0**2 + 4*s*pulse/rho0))/(2*s)
Us = C0 + s*up
if mode == "arrival" and p.max() < 0.5*pulse:
    check(False, "the pulse reached the probe with "
          f"{p.max()/1e6:.3g} MPa only")
    sys.exit(1)
if mode == "arrival":
    arrival = t[np.argmax(p > p.max()/2)]
    check.relative(f"arrival at the probe (z = {zc*1e6:.3f} um, Us = "
                   f"{Us:.2f} m/s) [s]", arrival, 0.05e-9 + (L - zc)/Us, 0.03)



# Points that start on the planes x = 0, y = 0 (symmetry) and z = 0
# (substrate) stay on them (interfaceMotion's slip projectors; before, a
# point on two planes kept only one normal and interface points took the
# map's round-off: up to 1.3e-9 m off x = 0 on the axis in the default case)
times = [d for d in glob.glob(f"{case}/[0-9]*")
         if os.path.isfile(f"{d}/polyMesh/points")]
if not times:
    check(False, "no moved mesh points written")
    sys.exit(1)
last = max(times, key=lambda d: float(os.path.basename(d)))
x0 = foamField.points(f"{case}/constant/polyMesh/points")
x1 = foamField.points(f"{last}/polyMesh/points")
moved = np.abs(x1 - x0).max()
for k, plane in enumerate(("x = 0", "y = 0", "z = 0")):
    # gmsh writes some of them at 1e-21 m: that offset must not change
    on = np.abs(x0[:, k]) < 1e-15
    off = np.abs(x1[on, k] - x0[on, k]).max()
    check(off == 0 and on.sum() > 0,
          f"{on.sum()} fluid points on {plane}:"
          f" largest motion normal to the plane to t = "
          f"{os.path.basename(last)} s {off:.3g} m (exactly 0 asked; the"
          f" mesh moved up to {moved:.3g} m)")

# the moving band through the refined cells and their split-face
# neighbours: the fluid's geometric conservation error (coupling.dat's
# gclError, the swept volumes against the cells' volume change) stays
# round-off
if refined:
    gcl = np.abs(c[:, 9]).max()
    check(gcl < 1e-12, f"geometric conservation on the refined water: "
          f"largest gclError {gcl:.3g} (< 1e-12)")

nc = int(np.sum(c[:, 4] == 0))
finite = bool(np.isfinite(c).all())
check(nc == 0 and finite, f"coupling: {len(c)} "
      f"steps, iterations mean {c[:, 2].mean():.2f} max {int(c[:, 2].max())},"
      f" {nc} not converged, finite {finite}; peak probe pressure "
      f"{p.max()/1e6:.2f} MPa")
sys.exit(check.exitStatus())
