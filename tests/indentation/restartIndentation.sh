#!/bin/bash
# Restart of cellIndentationFoam (issue 8): the validation cell with a
# shortened table (force-controlled A, hold B, one fast cycle, a slow load
# and unload, hold E) is run once uninterrupted, and once killed twice
# (SIGKILL, then SIGTERM, at fixed numbers of written steps) and continued
# with startFrom latestTime. Asserted: force.dat and peaks.dat byte-equal
# to the uninterrupted run, the same field steps (times) in solid.h5 and
# bit-equal displacement and pressure in its last step; a checkpoint of
# another mesh is refused with a clear message and the outputs untouched.
set -euo pipefail
. "$(dirname "$0")/../lib/restartTools.sh"

ref=$work/reference
cp -r "$root/tutorials/indentation/validationCell" "$ref"
cd "$ref"
rm -rf postProcessing log.* *.png results.md constant/*.msh
/usr/bin/python3 "$root/tests/lib/setProtocol.py" constant/indenterProperties \
    "A load 0.3e-6 3e-6" "B hold 0 15" "C1 load 10e-6 2e-6" \
    "C1 unload 10e-6 2e-6" "C3 load 0.1e-6 1e-6" "C3 unload 0.1e-6 1e-6" \
    "E hold 0 20"
printf '\ncheckpointInterval 5;\n' >> system/controlDict
cellMesh > log.cellMesh 2>&1 || { tail log.cellMesh; exit 1; }
cp -r "$ref" "$work/killed"
cellIndentationFoam > log.reference 2>&1 || { tail log.reference; exit 1; }
nLines=$(grep -vc '^#' postProcessing/indentation/force.dat)
echo "reference: $nLines steps"

cd "$work/killed"
sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
out=postProcessing/indentation
# Run until force.dat has $1 lines, then send signal $2
runAndKill()
{
    runUntil "$2" "[ \$(grep -vs '^#' $out/force.dat | wc -l) -ge $1 ]" \
        log.run.$2 cellIndentationFoam
    echo "killed with SIG$2 at $(grep -vs '^#' $out/force.dat | wc -l) lines"
}
runAndKill $((nLines/3)) KILL
runAndKill $((2*nLines/3)) TERM
cellIndentationFoam > log.final 2>&1 || { tail log.final; exit 1; }
grep -q "Continuing from" log.final || { echo "did not continue"; exit 1; }
grep "Continuing from" log.run.TERM log.final

cmp "$ref/$out/force.dat" "$out/force.dat"
cmp "$ref/$out/peaks.dat" "$out/peaks.dat"
/usr/bin/python3 - "$ref/$out/solid.h5" "$out/solid.h5" <<'PY'
import sys, numpy as np
from neuronFsi.solidResults import SolidResults
def steps(f):
    return [(int(k), f.time(k)) for k in f.steps()]
with SolidResults(sys.argv[1]) as a, SolidResults(sys.argv[2]) as b:
    sa, sb = steps(a), steps(b)
    assert sa == sb, (sa, sb)
    k = str(sa[-1][0])
    for d in ("displacement", "pressure", "vonMises"):
        x, y = a.field(k, d), b.field(k, d)
        assert np.array_equal(x, y), (d, np.abs(x - y).max())
    print("solid.h5: %d steps, last (t = %g s) bit-equal" % (len(sa), sa[-1][1]))
PY
echo "restart: force.dat, peaks.dat and solid.h5 equal to the uninterrupted run"

# A checkpoint that does not fit the mesh is refused, nothing overwritten
cd "$work/killed"
sed -i 's/^cytoplasmSize .*/cytoplasmSize 1.2e-6;/' system/cellMeshDict
cellMesh > /dev/null 2>&1
sum0=$(md5sum $out/force.dat $out/peaks.dat)
if cellIndentationFoam > log.mismatch 2>&1; then
    echo "a checkpoint of another mesh was accepted"; exit 1
fi
grep -q "Cannot continue from" log.mismatch || { tail log.mismatch; exit 1; }
grep -A2 "Cannot continue" log.mismatch | head -3
[ "$sum0" = "$(md5sum $out/force.dat $out/peaks.dat)" ] \
    || { echo "outputs changed by the refused run"; exit 1; }
echo "restartIndentation: passed"
