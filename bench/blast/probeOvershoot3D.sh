#!/bin/bash
# The 3D quarter's probe pressure overshoot (issue 17; docs/results/
# blast3D.md, "The probe's pressure overshoot in 3D"); not a test. In a
# scratch copy of tutorials/blast/quarter3D (inputs only): Allrun -noRun
# -noPlots -lateral 2e-6 -far 10e-6 -endTime 8e-8 [options], then
# cellBlastFoam to 52.4 ns (a write time, before the pulse reaches the
# cell), then on from there to 80 ns with the solid written every 0.2 ns
# (solid/solid.h5: every element's pressure through the incident passage),
# then bench/blast/probeOvershoot.py on the case with the 1D answer on a
# grid of heights (planeWave's column, 50 nm cells, cached in
# DIR/ref1d.npz).
#
#   bench/blast/probeOvershoot3D.sh DIR [Allrun options...]
#       DIR   scratch folder (created; must not exist); the case is
#             DIR/quarter3D, kept for inspection
#     e.g. bench/blast/probeOvershoot3D.sh /tmp/po -dz 0.25e-6
#   SOLID_OVERRIDE='...' in the environment: appended to the copy's
#   constant/solidProperties.allrun before the run (e.g. 'materials {
#   nucleus { b1 0.2; } cytoplasm { b1 0.2; } }': the linear bulk
#   viscosity of nucleus and cytoplasm)
set -euo pipefail
[ $# -ge 1 ] || { sed -n 2,21p "$0"; exit 1; }
dir=$1; shift
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
[ ! -e "$dir" ] || { echo "probeOvershoot3D.sh: $dir exists" >&2; exit 1; }
c=$dir/quarter3D
python3 -m neuronFsi.scratch "$root/tutorials/blast/quarter3D" "$c" \
    0.orig constant system Allrun --ignore polyMesh '*.msh'
cd "$c"
echo "== $(date -u '+%F %H:%M UTC'), commit $(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet HEAD -- src applications tutorials/blast bench/blast || echo ' (with uncommitted changes)'), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "== ./Allrun -noRun -noPlots -lateral 2e-6 -far 10e-6 -endTime 8e-8 $*"
PROJECT_DIR=$root ./Allrun -noRun -noPlots -lateral 2e-6 -far 10e-6 \
    -endTime 8e-8 "$@" > log.prepare 2>&1 || { tail -20 log.prepare; exit 1; }
grep '^Pulse' log.prepare || true
if [ -n "${SOLID_OVERRIDE:-}" ]
then
    echo "$SOLID_OVERRIDE" >> constant/solidProperties.allrun
    echo "== constant/solidProperties.allrun + $SOLID_OVERRIDE"
fi
# stage 1: to 52.4 ns = 8 x writeInterval 6.55 ns, a write time
# (controlDict.allrun holds Allrun's endTime: replaced, each entry once)
sed -i 's/^endTime .*;/endTime 5.24e-8;/' system/controlDict.allrun
echo "== nice -n 10 cellBlastFoam (to 52.4 ns)"
nice -n 10 /usr/bin/time -v -o log.time.1 cellBlastFoam > log.cellBlastFoam.1 2>&1
# stage 2: on to 80 ns, writes every 0.2 ns
sed -i 's/^endTime .*;/endTime 8e-8;/' system/controlDict.allrun
echo "startFrom latestTime; writeInterval 2e-10;" >> system/controlDict.allrun
echo "== nice -n 10 cellBlastFoam (52.4 to 80 ns, writes every 0.2 ns)"
nice -n 10 /usr/bin/time -v -o log.time.2 cellBlastFoam > log.cellBlastFoam.2 2>&1
grep "CPU time of the time loop" log.cellBlastFoam.1 log.cellBlastFoam.2
echo "== probeOvershoot.py"
nice -n 10 /usr/bin/python3 "$here/probeOvershoot.py" . --reference "$dir/ref1d.npz"
