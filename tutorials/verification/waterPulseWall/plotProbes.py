#!/usr/bin/python3
"""Pressure at the probes of waterPulseWall against time, with the values the
exact Hugoniot gives: the 50 MPa incident plateau, its arrival at mid-column
(the shock speed C0 + s up) and the pressure of its reflection from the rigid
wall (two colliding 50 MPa states, from the exact Riemann solver). Writes
probes.png and prints the measured peaks."""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import sys
try:
    from neuronFsi import script
except ImportError:
    sys.exit("plotProbes.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import postProcessing

data = postProcessing.series(".", "probes/p")
t, pMid, pWall = data[:, 0], data[:, 1], data[:, 2]

fig, ax = plt.subplots(figsize=(7, 4))
ax.plot(t*1e9, pMid/1e6, label="x = 50 um")
ax.plot(t*1e9, pWall/1e6, label="x = 99.9 um (at the wall)")
ax.axhline(50, color="k", lw=0.6, ls="--", label="incident 50 MPa")
ax.axhline(104.43, color="k", lw=0.6, ls=":",
           label="exact reflection 104.4 MPa")
ax.set_xlabel("time [ns]")
ax.set_ylabel("pressure [MPa]")
ax.legend(fontsize=8)
ax.grid(alpha=0.3)
fig.tight_layout()
script.saveFigure(fig, "probes.png", dpi=110)
arrival = t[np.argmax(pMid > 25e6)]
print(f"plotProbes: mid-column peak {pMid.max()/1e6:.2f} MPa, arrival"
      f" (p > 25 MPa) {arrival*1e9:.2f} ns; wall peak {pWall.max()/1e6:.2f}"
      " MPa; wrote probes.png")
