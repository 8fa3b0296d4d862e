#!/bin/bash
# Numbers are read as numbers (issue 16): cellIndentationFoam on a small
# r-z block (constant/solidProperties mesh rectangle, one region) with
# c0 = 1.6700001 Pa and with c0 = 1.6700004 Pa. Before, the entries went
# through a 6-digit text round trip and both runs were bit-identical.
# Asserted: materials.dat carries every digit of each c0, the fields of
# solid.h5 differ between the two values, and a second run with the first
# value equals the first run bit for bit (the difference is the 8th digit
# of c0, not run-to-run noise).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
head='FoamFile { version 2.0; format ascii; class dictionary; object'
makeCase()  # <dir> <c0 [Pa]>
{
    mkdir -p "$1/system" "$1/constant"
    cat > "$1/system/controlDict" <<DICT
$head controlDict; }
application cellIndentationFoam; startFrom startTime; startTime 0;
stopAt endTime; endTime 1; deltaT 1; writeControl timeStep;
writeInterval 1; fieldWriteInterval 0.25;
DICT
    cat > "$1/constant/solidProperties" <<DICT
$head solidProperties; }
mesh { type rectangle; cells (8 4); min (0 0); max (10e-6 5e-6); }
fixed ((bottom 0) (bottom 1) (left 0));
materials { solid { c0 $2; d0 0; mu1 107.78; tau1 0.01; } }
DICT
    cat > "$1/constant/indenterProperties" <<DICT
$head indenterProperties; }
radius 5e-6; contactPatch top; tolerance 1e-9; maxDepthIncrement 0.1e-6;
holdDeltaT0 0.01; maxDeltaT 0.5;
protocol ((A load 1e-6 0.5e-6) (B hold 0 0.5));
DICT
}
for run in a:1.6700001 b:1.6700004 c:1.6700001
do
    makeCase "$work/${run%%:*}" "${run#*:}"
    (cd "$work/${run%%:*}" && cellIndentationFoam > log 2>&1) \
        || { tail -20 "$work/${run%%:*}/log"; exit 1; }
done
/usr/bin/python3 - "$work" <<'PY'
import sys, numpy as np
from neuronFsi.postProcessing import materials
from neuronFsi.solidResults import SolidResults
work = sys.argv[1]
def c0(run):
    m = materials(work + "/%s/postProcessing/indentation/materials.dat"
                  % run)
    assert list(m) == ["solid"], m
    return m["solid"]["c0"]
def fields(run):
    with SolidResults(work + "/%s/postProcessing/indentation/solid.h5"
                      % run) as f:
        return [(f.time(k), f.field(k, "displacement"),
                 f.field(k, "pressure")) for k in f.steps()]
assert c0("a") == 1.6700001 and c0("b") == 1.6700004, (c0("a"), c0("b"))
a, b, c = fields("a"), fields("b"), fields("c")
assert len(a) >= 2 and len(a) == len(b) == len(c), (len(a), len(b), len(c))
for (ta, ua, pa), (tb, ub, pb), (tc, uc, pc) in zip(a, b, c):
    assert ta == tb == tc
    assert np.array_equal(ua, uc) and np.array_equal(pa, pc), "a != c"
last = a[-1][1] - b[-1][1]
assert np.abs(last).max() > 0, "c0 1.6700001 and 1.6700004 gave the same"
print("materialPrecision: c0 %r and %r Pa: %d field steps, displacements "
      "differ by up to %.3e m (of %.3e m); the same c0 twice: bit-equal"
      % (c0("a"), c0("b"), len(a), np.abs(last).max(),
         np.abs(a[-1][1]).max()))
PY
echo "materialPrecision: passed"
