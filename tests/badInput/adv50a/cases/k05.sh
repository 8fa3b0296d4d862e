#!/bin/bash
# CASETIMEOUT=1500
# k05 (adv49b i02/i55/i03 / fix19f's per-block structured count varied at the limit +/- 1 per block): (a) the r-z cell of
# i55 (nucleus 2e-6, cytoplasm 2e-6, membrane 0.1e-6, meshType structured): maxElements 1, then for every figure N the
# refusal prints ("at least N quadrilaterals", the blocks built so far and the next one) maxElements N-1 (refused with
# the same N) and N (that block passes: refused with a larger figure, or meshed), until meshed; the whole count C, then
# maxElements C-1 (refused) and C (meshed exactly C); (b) the quarter3D cell with coarse sizes (0.5/0.5/0.4 um): the same
# walk, at most 6 steps, and C-1/C if meshed in time; (c) the r-z cell with membraneSize 2e-10 and 1e-10 (finer than i55
# (d)'s 5e-10) under `ulimit -v 3000000`: refused, with maxRSS and the wall time; (d) maxElements 2147483647 (the largest)
# with membraneSize 5e-10 under the same ulimit: meshed or a clean out-of-memory refusal, never an abort; (e) maxElements
# 2147483648 and 9223372036854775807 (beyond the label: refused naming it). Never a mesh above maxElements written,
# never a figure that is refused when given as maxElements, never an abort or a signal.
. "$(dirname "$0")/../lib.sh"
fig() { grep -a -o 'at least [0-9.e+]* \(quadrilaterals\|hexahedra\|elements\)' $W/try.log | head -1 | awk '{print $3}'; }
made() { grep -a -o '\(quadrilaterals\|hexahedra\) [0-9]*' $W/try.log | head -1 | awk '{print $2}'; }
rz() { mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 0.1e-6; }
q3() { mdir quarter3D; }
walk() { local mk=$1 steps=$2 m=1 n k=0 prev=""; while [ $k -lt $steps ]; do k=$((k+1)); $mk; mset maxElements $m; cm "" 300 > /dev/null; n=$(fig)
    if [ -z "$n" ]; then echo "   maxElements $m: meshed ($(made) written, rc $(grep -a -c FATAL $W/try.log) FATAL lines, $(tail -1 $W/try.log | cut -c1-120))"; C=$(made); return; fi
    n=$(/usr/bin/python3 -c "print(int(float('$n')))"); echo "   maxElements $m: refused 'at least $n'"
    [ "$n" -le "$m" ] && { echo "   FINDING: figure $n not above maxElements $m"; return; }
    $mk; mset maxElements $((n-1)); cm "" 300 > /dev/null; echo "   maxElements $((n-1)): $( [ -n "$(fig)" ] && echo "refused 'at least $(fig)'" || echo "meshed $(made)")"; m=$n; done; C=""; }
echo "(a) r-z walk:"; walk rz 30
if [ -n "$C" ]; then for m in $((C-1)) $C $((C+1)); do rz; mset maxElements $m; cm "" 300 > /dev/null; echo "   maxElements $m (C = $C): $( [ -n "$(fig)" ] && echo "refused 'at least $(fig)'" || echo "meshed $(made), cell.msh $(ls -s constant/cell.msh 2>/dev/null | cut -d' ' -f1) kB") | $(grep -a -m1 'more than maxElements' $W/try.log | cut -c1-200)"; done; fi
echo "(b) quarter3D walk (coarse):"; walk q3 6
if [ -n "$C" ]; then for m in $((C-1)) $C; do q3; mset maxElements $m; cm "" 300 > /dev/null; echo "   maxElements $m (C = $C): $( [ -n "$(fig)" ] && echo "refused 'at least $(fig)'" || echo "meshed $(made)") | $(grep -a -m1 'more than maxElements' $W/try.log | cut -c1-200)"; done; fi
[ -n "${K05WALKONLY:-}" ] && exit 0   # k05b: the walks only
for s in 2e-10 1e-10; do mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize $s; echo "(c) membraneSize $s, ulimit -v 3000000:"; (ulimit -v 3000000; cm "" 300); echo "   sig: $(sig) | bad_alloc/terminate: $(grep -a -c 'bad_alloc\|terminate\|Abort' $W/try.log) | $(grep -a -m1 'maxElements\|memory' $W/try.log | cut -c1-250)"; done
mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 5e-10; mset maxElements 2147483647; echo "(d) membraneSize 5e-10, maxElements 2147483647, ulimit -v 3000000:"; (ulimit -v 3000000; cm "" 400); echo "   sig: $(sig) | bad_alloc/terminate: $(grep -a -c 'bad_alloc\|terminate\|Abort' $W/try.log) | $(grep -a -m2 'maxElements\|memory\|FATAL' $W/try.log | tr '\n' ' ' | cut -c1-300) | written: $(ls constant/cell.msh 2>/dev/null)"
for m in 2147483648 9223372036854775807; do rz; mset maxElements $m; cm "" 120; done
