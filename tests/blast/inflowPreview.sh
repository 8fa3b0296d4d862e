#!/bin/bash
# Allrun -inflow HEIGHT prepares the shortened preview (issue 17 item 2):
# a copy run with -inflow 20e-6 -Z 30e-6 -pulse 3e-9 -endTime 1.2e-8
# -noRun (a 10 um trip from the column's top to the inflow plane: the
# pulse arrives there after about 6.7 ns). Asserts: the water mesh ends at
# 20 um; the top of 0/p, 0/U, 0/T is planeWaveInflow with columnHeight
# 30 um and the 3 ns pulse table; constant/inflowWave is there (height,
# columnHeight, pulse as in 0/p; times from 0 to the end time and one
# step of the scene (maxDeltaT) beyond; the 50 MPa
# plateau arrived, its velocity downwards); the water probes at or above
# 20 um are left out (controlDict.allrun), none is edited in the tracked
# dictionaries; Allrun -inflow 12e-6 (below one -dz cell above the box
# around the cell) is refused naming -inflow and the valid range. Needs the
# solver-free part of the build only (cellMesh, OpenFOAM's blockMesh, and
# rhoRiemannFoam for the column). About 10 s.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL inflowPreview: $*"; exit 1; }

bash "$here/runPreview.sh" "$work/a" -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 \
    -Z 30e-6 -pulse 3e-9 -endTime 1.2e-8 -inflow 20e-6 -noRun \
    > "$work/log" 2>&1 || { cat "$work/log"; fail "Allrun -inflow 20e-6"; }
case=$work/a/axisymmetricPreview
[ ! -e "$case/log.cellBlastFoam" ] || fail "-noRun ran the solver"

/usr/bin/python3 - "$case" "$here/../../tutorials/blast/axisymmetricPreview" <<'PY' || fail "the prepared case"
import re
import sys

import numpy as np

from neuronFsi import foamDict, planeWave

case, tutorial = sys.argv[1:]
ok = True


def check(cond, what):
    global ok
    print("%s %s" % ("ok  " if cond else "FAIL", what))
    ok &= bool(cond)


# the water's top: the highest mesh point (points in ascii or binary: the
# blockMeshDict's vertices give the same top)
text = open(case + "/system/blockMeshDict").read()
body = text[text.index("vertices"):text.index("blocks")]
y = [float(m.split()[1]) for m in re.findall(r"\(([^()]+)\)", body)]
check(abs(max(y) - 20e-6) < 1e-15, "the water ends at %.6g m" % max(y))

pulse = [(0.0, 0.0), (1e-10, 5e7), (3e-9, 5e7), (3.1e-9, 0.0), (1.0, 0.0)]
top = {f: foamDict.read("%s/0/%s" % (case, f))["boundaryField"]["top"]
       for f in ("p", "U", "T")}
check(all(t["type"] == "planeWaveInflow" for t in top.values()),
      "0/p, 0/U, 0/T top: planeWaveInflow")
check(top["p"]["columnHeight"] == 3e-5, "columnHeight %g m"
      % top["p"]["columnHeight"])
check(planeWave.appliedPressure(case) == pulse,
      "the pulse table of -pulse 3e-9: %s" % planeWave.appliedPressure(case))
check(top["p"]["file"] == "constant/inflowWave", "file %s"
      % top["p"]["file"])

d = planeWave.readInflow(case + "/constant/inflowWave")
check((d["height"], d["columnHeight"], d["pulse"]) == (2e-5, 3e-5, pulse),
      "inflowWave: height %g m, columnHeight %g m, the pulse of 0/p"
      % (d["height"], d["columnHeight"]))
# to the end time and one step of the scene beyond (maxDeltaT 1e-9 s)
check(d["t"][0] == 0 and abs(d["t"][-1] - 1.3e-8) < 1e-20,
      "inflowWave: %d times from %g to %g s" % (len(d["t"]), d["t"][0],
                                                d["t"][-1]))
arrival = planeWave.arrival(d["t"], d["p"], 5e7)
plateau = (d["t"] > arrival + 1e-9) & (d["t"] < arrival + 2.5e-9)
check(arrival is not None and 6.0e-9 < arrival < 7.5e-9,
      "the pulse at the inflow plane after %.4g ns" % (arrival*1e9))
check(abs(d["p"][plateau].mean()/5e7 - 1) < 0.01
      and (d["u"][plateau] < -30).all(),
      "its plateau %.4g MPa, u %.4g m/s (downwards)"
      % (d["p"][plateau].mean()*1e-6, d["u"][plateau].mean()))

probes = foamDict.read(case + "/system/controlDict")["functions"][
    "fluidProbes"]["probeLocations"]
tracked = foamDict.read(tutorial + "/system/controlDict")["functions"][
    "fluidProbes"]["probeLocations"]
check([q[1] for q in probes] == [q[1] for q in tracked if q[1] < 2e-5]
      and len(probes) < len(tracked),
      "water probes at %s m (of %s)" % ([q[1] for q in probes],
                                        [q[1] for q in tracked]))
sys.exit(0 if ok else 1)
PY
cmp -s <(grep -v '^#sinclude\|^$' "$case/system/controlDict") \
    <(grep -v '^#sinclude\|^$' "$here/../../tutorials/blast/axisymmetricPreview/system/controlDict") \
    || fail "system/controlDict edited"

# too short a water column: refused, naming -inflow and the range
if bash "$here/runPreview.sh" "$work/b" -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 \
    -Z 30e-6 -endTime 1.2e-8 -inflow 12e-6 -noRun > "$work/log" 2>&1
then
    fail "Allrun -inflow 12e-6 accepted"
fi
for m in "valid range -Z >= 1.265e-05 m" "Allrun: -inflow 12e-6 is the water's -Z"
do
    grep -qF -- "$m" "$work/log" || { cat "$work/log"; fail "-inflow 12e-6: no '$m'"; }
done
[ ! -e "$work/b/axisymmetricPreview/constant/inflowWave" ] \
    || fail "-inflow 12e-6 wrote constant/inflowWave"
echo "inflowPreview: ok"
