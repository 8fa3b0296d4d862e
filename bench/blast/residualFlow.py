#!/usr/bin/python3
"""The flow left behind by the pulse in the blast preview (not a test).

    bench/blast/residualFlow.py CASE [--time T] [--bin B] [--extent E]
                                [--energy AFTER]

CASE: a finished axisymmetric preview case. In the exact answer (the 1D
plane wave) every particle is at rest once the pulse and its echo have
passed, so any velocity left at T (default the latest time directory) is
error. Prints the largest water speed |U| [cm/s] in r-z bins of B [m]
(default 2e-6) up to E [m] (default 22e-6) in r and z, then the solid's
nodal speeds (largest and rms per region, m/s) at the write of solid.h5
nearest T. --energy AFTER: instead, the solid's kinetic energy [J] (the
whole cell: lumped ring masses 2 pi r A rho0/4 per quadrilateral and
node, rho0 = 1000 kg/m^3, every region's in the tutorial) at every write
of solid.h5 from AFTER [s] on, and its ratio to the previous write's (as
residualFlow3D.py prints it for the quarter; docs/results/blast3D.md,
"What keeps the 3D cell flowing"). The water's cell centres come from `postProcess -func
writeCellCentres` in a scratch copy of the case (the case itself is not
written to). docs/results/blastPlaneWave.md, "The default at x0.7".
"""
import argparse
import os
import shutil
import subprocess
import tempfile

import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import bench, damageIndicators, foamField
from neuronFsi.solidResults import SolidResults

def latestTime(case):
    times = []
    for d in os.listdir(case):
        try:
            times.append((float(d), d))
        except ValueError:
            continue
    if not times:
        raise SystemExit(f"residualFlow.py: error: no time directory in {case}")
    return max(times)[1]


def cellCentres(case, time):
    """Cell centres [m] of the water at time (its moved mesh), written by
    OpenFOAM in a scratch copy"""
    work = tempfile.mkdtemp(prefix="residualFlow.")
    try:
        for d in ("constant", "system", time):
            shutil.copytree(os.path.join(case, d), os.path.join(work, d),
                            ignore=shutil.ignore_patterns("solid*", "*.h5"))
        subprocess.run(["postProcess", "-case", work, "-func",
                        "writeCellCentres", "-time", time], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        return foamField.internalField(os.path.join(work, time, "C"))
    finally:
        shutil.rmtree(work, ignore_errors=True)


def solidEnergy(case, after):
    with SolidResults(os.path.join(case, "solid", "solid.h5")) as s:
        X, C = s.mesh("coordinates"), s.mesh("connectivity")
        x, y = X[C][:, :, 0], X[C][:, :, 1]
        area = 0.5*np.abs((x[:, 0] - x[:, 2])*(y[:, 1] - y[:, 3])
                          - (x[:, 1] - x[:, 3])*(y[:, 0] - y[:, 2]))
        m = np.zeros(len(X))
        np.add.at(m, C.ravel(),
                  np.repeat(1000.0*2*np.pi*x.mean(1)*area/4, 4))
        print(f"solid: {len(X)} nodes, mass {m.sum():.4g} kg (whole cell)")
        prev = None
        for step in s.steps():
            t = s.time(step)
            if t < after:
                continue
            v = s.field(step, "velocity")
            K = 0.5*(m*(v*v).sum(1)).sum()
            ratio = f"{K/prev:.3f}" if prev else "-"
            print(f"{t*1e9:7.2f} ns: kinetic energy {K:.4g} J, ratio to "
                  f"the previous write {ratio}")
            prev = K


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("--time", default=None)
    ap.add_argument("--bin", type=float, default=2e-6)
    ap.add_argument("--extent", type=float, default=22e-6)
    ap.add_argument("--energy", type=float, default=None)
    a = bench.parse(ap)
    if a.energy is not None:
        return solidEnergy(a.case, a.energy)
    time = a.time or latestTime(a.case)
    U = foamField.internalField(os.path.join(a.case, time, "U"))
    C = cellCentres(a.case, time)
    r, z = np.hypot(C[:, 0], C[:, 2]), C[:, 1]
    speed = np.linalg.norm(U, axis=1)
    edges = np.arange(0.0, a.extent + 0.5*a.bin, a.bin)
    print(f"water at t = {time} s: largest |U| [cm/s] per {a.bin*1e6:g} um "
          f"bin; rows: z from the top, columns: r from 0 ('--': no water)")
    print("z\\r [um] " + " ".join(f"{x*1e6:5.0f}" for x in edges[:-1]))
    for j in range(len(edges) - 2, -1, -1):
        row = []
        for i in range(len(edges) - 1):
            m = ((r >= edges[i]) & (r < edges[i + 1])
                 & (z >= edges[j]) & (z < edges[j + 1]))
            row.append(f"{100*speed[m].max():5.1f}" if m.any() else "   --")
        print(f"{edges[j]*1e6:8.0f} " + " ".join(row))
    print(f"water: largest |U| {speed.max():.4f} m/s, rms "
          f"{np.sqrt(np.mean(speed**2)):.4f} m/s over {len(speed)} cells")
    with SolidResults(os.path.join(a.case, "solid", "solid.h5")) as s:
        step = s.nearest(float(time))
        v = np.linalg.norm(s.field(step, "velocity"), axis=1)
        conn, reg = s.mesh("connectivity"), s.mesh("region")
        print(f"solid at t = {s.time(step):.6g} s: nodal speed per region, "
              f"largest / rms [m/s]")
        names, _ = damageIndicators.regionNames(a.case)
        for k, name in enumerate(names):
            nodes = np.unique(conn[reg == k])
            if nodes.size:
                print(f"  {name:10s} {v[nodes].max():.4f} / "
                      f"{np.sqrt(np.mean(v[nodes]**2)):.4f}")


if __name__ == "__main__":
    main()
