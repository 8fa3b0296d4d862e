#!/bin/bash
# i55 (class 6, maxElements against the structured section's real count): meshType structured r-z with nucleusSize 2e-6,
# cytoplasmSize 2e-6, membraneSize 0.1e-6 (the membrane's count drives the blocks around it): the count C cellMesh reports
# for it, then maxElements C/2 and C-1: refused (the limit holds for the mesh written), or the log's estimate and the count
# shown; a mesh of more elements than maxElements written is a finding (how many times the limit).
. "$(dirname "$0")/../lib.sh"
mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 0.1e-6; cm
C=$(grep -a -o 'quadrilaterals [0-9]*' $W/try.log | grep -o '[0-9]*' | head -1); echo "   count C = $C"
for m in $((C/4)) $((C/2)) $((C-1)); do mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 0.1e-6; mset maxElements $m; cm
  echo "   maxElements $m: written $(grep -a -o 'quadrilaterals [0-9]*' $W/try.log | head -1) | $(grep -a -i -m1 'estimat\|at least\|maxElements' $W/try.log | cut -c1-200)"; done
# (d) (added after P1b's i02 (a): 1.33e6 quadrilaterals at 580 MB written with the default maxElements): membraneSize 5e-10 with
# 2e-6 elsewhere and the default maxElements (about 1e8 elements if meshed): refused before the memory is taken (maxRSS
# below 200 MB, a few seconds), naming the count and maxElements (run under `ulimit -v 3000000`: 3 GB of address space at most,
# so that an unrefused mesh fails instead of taking the shared machine's memory)
mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 5e-10; (ulimit -v 3000000; cm "" 300); echo "   (d) $(grep -a -i -m1 'maxElements' $W/try.log | cut -c1-250)"
