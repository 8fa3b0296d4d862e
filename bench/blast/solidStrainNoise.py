#!/usr/bin/python3
"""The solid's element strains against the plane wave's (not a test).

    bench/blast/solidStrainNoise.py CASE [--near R]

CASE: a blast preview case with solid/solid.h5 (r-z, bilinear quads). In
the exact answer the cell is in uniaxial strain: eps_rr = eps_tt = eps_rz
= 0 and eps_zz a function of z only. Per write and region (small strain
from the displacement gradient at each element's centroid; eps_tt =
u_r/r there): the rms of the departure from uniaxial strain sqrt(eps_rr^2
+ eps_tt^2 + 2 eps_rz^2), the rms of eps_zz and its mean |eps_zz|; with
--near R [m], the mean and scatter of eps_zz over the elements of each
side within R of the Fig. 10 point (3.8461, 4.108) um.
docs/results/blastPlaneWave.md, "Unseen interface modes" and
"Element-scale noise and the deviatoric viscosity".
"""
import argparse
import os

import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import bench
from neuronFsi.solidResults import SolidResults

FIG10 = np.array([3.8461e-6, 4.108e-6])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("--near", type=float, default=0)
    a = bench.parse(ap)
    with SolidResults(os.path.join(a.case, "solid", "solid.h5")) as s:
        X = s.mesh("coordinates")[:, :2]
        C = s.mesh("connectivity")
        reg = s.mesh("region")
        g = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]])/4.0
        dN = np.array([g @ np.linalg.inv(X[e].T @ g) for e in C])
        cen = X[C].mean(axis=1)
        near = np.linalg.norm(cen - FIG10, axis=1) < a.near
        names = {0: "nucleus", 1: "cytoplasm", 2: "membrane"}
        for step in s.steps():
            u = s.field(step, "displacement")[:, :2][C]
            H = np.einsum("eai,eaj->eij", u, dN)
            ezz = H[:, 1, 1]
            ert = 0.5*(H[:, 0, 1] + H[:, 1, 0])
            ett = u[:, :, 0].mean(axis=1)/cen[:, 0]
            nonU = np.sqrt(H[:, 0, 0]**2 + ett**2 + 2*ert**2)
            out = []
            for r in np.unique(reg):
                m = reg == r
                text = ("%s: non-uniaxial rms %.2e, eps_zz rms %.2e, "
                        "mean |eps_zz| %.2e" % (names.get(r, r),
                        np.sqrt((nonU[m]**2).mean()),
                        np.sqrt((ezz[m]**2).mean()), np.abs(ezz[m]).mean()))
                if a.near > 0 and (m & near).any():
                    text += ", near the Fig. 10 point (%d): %.4e +- %.1e" % (
                        (m & near).sum(), ezz[m & near].mean(),
                        ezz[m & near].std())
                out.append(text)
            print("t %.4g ns | %s" % (s.time(step)*1e9, " | ".join(out)))


if __name__ == "__main__":
    bench.main(main)
