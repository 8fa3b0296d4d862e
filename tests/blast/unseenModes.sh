#!/bin/bash
# A solid interface finer than the fluid's is refused (r-z faces map):
# with -cell 0.25e-6 against the fluid's -h 0.25e-6 the cell's outer
# surface has more nodes than the fluid patch has points, so displacement
# patterns of the membrane vanish at every fluid point; unrefused they grew
# into a sawtooth along the membrane (docs/results/blastPlaneWave.md,
# "Unseen interface modes"). Asserts: cellBlastFoam exits non-zero naming
# constant/fsiProperties, the face set and the count, and writes no time;
# the same cell with the fluid refined to -h 0.1e-6 runs (to 0.2 ns).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=${TMPDIR:-/tmp}/blastUnseen.$$
trap 'rm -rf "$work"' EXIT
for h in 0.25e-6 0.1e-6
do
    bash "$here/runPreview.sh" "$work/h$h" -h $h -far 2e-6 -dz 0.25e-6 -cell 0.25e-6 \
        -Z 30e-6 -endTime 2e-10 -noRun > "$work.log" 2>&1 \
        || { cat "$work.log"; rm -f "$work.log"; exit 1; }
    rm -f "$work.log"
done
case=$work/h0.25e-6/axisymmetricPreview
if (cd "$case" && cellBlastFoam > log.cellBlastFoam 2>&1)
then
    echo "FAIL: a solid interface finer than the fluid's was accepted"
    exit 1
fi
for m in "constant/fsiProperties" "solid face set outerSurface" \
    "displacement patterns of the solid interface vanish" "Allrun -h"
do
    grep -q "$m" "$case/log.cellBlastFoam" \
        || { echo "FAIL: no '$m' in the error:"; tail -20 "$case/log.cellBlastFoam"; exit 1; }
done
n=$(grep -o "): [0-9]* displacement patterns" "$case/log.cellBlastFoam" | grep -o "[0-9]*")
[ "${n:-0}" -gt 0 ] || { echo "FAIL: no count of unseen patterns"; exit 1; }
[ -z "$(cd "$case" && foamListTimes -noZero 2> /dev/null)" ] \
    || { echo "FAIL: the refused run wrote a time"; exit 1; }
echo "refused: $n unseen patterns (-cell 0.25e-6, -h 0.25e-6)"
case=$work/h0.1e-6/axisymmetricPreview
(cd "$case" && cellBlastFoam > log.cellBlastFoam 2>&1) \
    || { echo "FAIL: -h 0.1e-6 refused"; tail -20 "$case/log.cellBlastFoam"; exit 1; }
grep "see every solid interface displacement pattern" "$case/log.cellBlastFoam"
