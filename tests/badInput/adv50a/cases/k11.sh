#!/bin/bash
# CASETIMEOUT=600
# k11 (class 6/4, the element-count estimate of cellMesh at the reader's edge; found by hand at 05:58 after k05): sizes
# the reader takes (above 1e-300 m) whose count from the sizes overflows a double: the quarter3D cell with azimuthSize
# 1e-155 (count ~6e299), 1e-160, 1e-200, membraneSize 1e-200, nucleusSize 1e-200; the r-z cell with nucleusSize 1e-200,
# cytoplasmSize 1e-200, membraneSize 1e-300 and contactSize 1e-200 (unstructured and structured). Each refused rc 1
# naming the entry, the count (or "beyond any count") and maxElements, or the size's range; never a signal.
. "$(dirname "$0")/../lib.sh"
for kv in "azimuthSize 1e-155" "azimuthSize 1e-160" "azimuthSize 1e-200" "membraneSize 1e-200" "nucleusSize 1e-200"; do mdir quarter3D; set -- $kv; mset $1 $2; echo "quarter3D $kv:"; (ulimit -v 3000000; cm "" 60); echo "   sig: $(sig)"; done
for mt in unstructured structured; do for kv in "nucleusSize 1e-200" "cytoplasmSize 1e-200" "membraneSize 1e-300" "contactSize 1e-200"; do mdir; mset meshType $mt; set -- $kv; mset $1 $2; echo "r-z $mt $kv:"; (ulimit -v 3000000; cm "" 60); echo "   sig: $(sig)"; done; done
