#!/bin/bash
# fluidWedgeMesh.sh: tutorials/blast/fluidWedgeMesh.py's radial grading
# (-outer): without it (or with -outer = -far) the blocks of the uniform
# mesh bit for bit; with -outer 4e-6 blockMesh and checkMesh pass and the
# ring beside the cell's box goes from about -far at r = 12.4 um to about
# -outer at r = 50 um, monotonically, at a ratio per cell below 1.2; bad
# sizes (and a column that ends below one cell above the box around the
# cell) are refused with the option named and a non-zero exit, the
# blockMeshDict left untouched. Quiet unless it fails.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
gen=$here/../../tutorials/blast/fluidWedgeMesh.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cp -r "$here/../../tutorials/blast/axisymmetricPreview/system" .
foamDictionary -entry writeFormat -set ascii system/controlDict > /dev/null
fail() { echo "FAIL fluidWedgeMesh: $*"; exit 1; }

# 1. No grading: -outer = -far writes the blocks of the default
/usr/bin/python3 "$gen" -h 0.25e-6 -far 1e-6 -o d0 > /dev/null
/usr/bin/python3 "$gen" -h 0.25e-6 -far 1e-6 -outer 1e-6 -o d1 > /dev/null
cmp -s <(grep -v '^//' d0) <(grep -v '^//' d1) \
    || fail "-outer = -far changed the blocks: $(diff d0 d1 | head -5)"
grep -q 'simpleGrading (1 1 1)' d0 || fail "uniform blocks not graded 1"

# 2. Graded: mesh valid, sizes as asked
out=$(/usr/bin/python3 "$gen" -h 0.25e-6 -far 1e-6 -outer 4e-6 \
      -o system/blockMeshDict)
blockMesh > log.blockMesh 2>&1 || { tail log.blockMesh; fail "blockMesh"; }
checkMesh > log.checkMesh 2>&1 || true
grep -q '^Mesh OK.' log.checkMesh || { tail -20 log.checkMesh; fail "checkMesh"; }
/usr/bin/python3 - "$out" <<'PY' || fail "graded sizes"
import re, sys
import numpy as np
s = open("constant/polyMesh/points").read()
body = s[s.index("(", s.index("}")) + 1:]
n = int(s[s.index("}") + 1:].split("(")[0].split()[-1])
pts = np.array([m.split() for m in re.findall(r"\(([^()]+)\)", body)[:n]],
               dtype=float)
# the radial line of points on the substrate y = 0, front side z <= 0
r = np.sort(np.unique(np.round(pts[(np.abs(pts[:, 1]) < 1e-12)
                                   & (pts[:, 2] <= 0), 0], 12)))
r = r[r > 12.4e-6*np.cos(np.radians(2.5)) - 1e-9]
d = np.diff(r)/np.cos(np.radians(2.5))
ok = (abs(d[0]/1e-6 - 1) < 0.1 and abs(d[-1]/4e-6 - 1) < 0.1
      and np.all(d[1:]/d[:-1] > 1) and np.all(d[1:]/d[:-1] < 1.2))
cells = int(re.search(r"(\d+) cells", sys.argv[1]).group(1))
ok &= cells < 7398
print(f"{'ok  ' if ok else 'FAIL'} ring cells {len(d)}: first {d[0]*1e6:.3f}"
      f" um, last {d[-1]*1e6:.3f} um, ratio {(d[1:]/d[:-1]).min():.4f}-"
      f"{(d[1:]/d[:-1]).max():.4f}; {cells} cells (uniform: 7398)")
sys.exit(0 if ok else 1)
PY

# 3. Bad sizes: refused, the existing blockMeshDict untouched (-Z 13e-6:
# the column must reach one -dz cell, 1 um here, above the box around the
# cell, 12.4 um, as a short scene of Allrun -inflow would)
cp system/blockMeshDict keep
for bad in "-outer 0.5e-6" "-outer -1" "-far 0" "-h 0" "-dz 0" "-Z 13e-6" \
    "-Z nan"
do
    # -far 1e-6 unless the bad value is -far's (an option given twice is
    # refused as such)
    far=(-far 1e-6)
    [ "${bad%% *}" != -far ] || far=()
    # shellcheck disable=SC2086
    if msg=$(/usr/bin/python3 "$gen" "${far[@]}" $bad -o system/blockMeshDict 2>&1)
    then
        fail "$bad accepted"
    fi
    opt=${bad%% *}
    grep -q -- "error: $opt " <<< "$msg" || fail "$bad: message without $opt: $msg"
    cmp -s keep system/blockMeshDict || fail "$bad overwrote blockMeshDict"
done
echo "fluidWedgeMesh: ok"
