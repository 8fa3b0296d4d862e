#!/bin/bash
# Smoke run of tutorials/blast/axisymmetricPreview (coarse meshes, a 30 um
# water column, 22 ns): the whole Allrun chain (cellMesh,
# blockMesh wedge, cellBlastFoam with robin coupling, foamToVTK, solidToFoam
# + foamToVTK -region solid). Asserts:
#  - the FSI force map is conservative (solid nodal forces = fluid ring
#    force, relative 1e-12) and exact in r-z: the axial ring force of a unit
#    pressure = -pi a^2 (the projected area; relative 1e-9), the radial one
#    = -pi^2 a H/2 within 1e-3 (the polygonal surface against the spheroid);
#  - the pulse reaches the probe (cytoplasm-nucleus interface, 75 % of the
#    nucleus height; p above half its peak, which must exceed 25 MPa) at
#    0.05 ns + (Z - z_probe)/Us,
#    Us = C0 + s up = 1515.65 m/s (50 MPa Hugoniot of water), within 3 %;
#  - every coupling step converged; fluid and solid VTK files exist;
#  - a restart after the Allrun's post-processing (solidToFoam wrote
#    constant/solid/polyMesh) continues to a later end time (adv40 z19:
#    refused as "constant/solid/polyMesh/boundary (added)").
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=${TMPDIR:-/tmp}/blastSmoke.$$
trap 'rm -rf "$work"' EXIT
bash "$here/runPreview.sh" "$work" -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 \
    -Z 30e-6 -endTime 2.2e-8 -noPlots > "$work.log" 2>&1 \
    || { cat "$work.log"; exit 1; }
rm -f "$work.log"
case=$work/axisymmetricPreview
ls "$case"/VTK/*.vtm > /dev/null
ls "$case"/VTK/solid > /dev/null
/usr/bin/python3 "$here/checkPreview.py" "$case" 30e-6
# The tutorial's pictures (Fig. 10 curves, interface maxima, the r-z
# section at the write nearest 65.5 ns)
/usr/bin/python3 "$here/../../tutorials/blast/plotBlast.py" "$case" > "$work.log" 2>&1 \
    || { cat "$work.log"; rm -f "$work.log"; exit 1; }
rm -f "$work.log"
for png in fig10 interfaceMaxima snapshot65.5ns
do
    [ -s "$case/$png.png" ] || { echo "FAIL: no $png.png"; exit 1; }
done
# The documented restart (startFrom latestTime) after the whole chain
ls -d "$case"/constant/solid/polyMesh > /dev/null
sed -i 's/^startFrom .*/startFrom       latestTime;/' "$case/system/controlDict"
foamDictionary -entry endTime -set 2.4e-8 "$case/system/controlDict.allrun" \
    > /dev/null
cellBlastFoam -case "$case" > "$work.log" 2>&1 \
    || { echo "FAIL: the restart after solidToFoam"; cat "$work.log"; exit 1; }
rm -f "$work.log"
last=$(foamListTimes -case "$case" -latestTime 2>/dev/null | tail -1)
# (its last time within a step before 2.4e-8 s: OpenFOAM's end)
/usr/bin/python3 -c "import sys; t = float(sys.argv[1]); \
assert 2.35e-8 < t <= 2.4e-8, t" "$last" \
    || { echo "FAIL: the restart ended at $last s, not at 2.4e-8 s"; exit 1; }
echo "restart after solidToFoam: continued to $last s"
