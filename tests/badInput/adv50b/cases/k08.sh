#!/bin/bash
# k08 (class 6, the elliptic smoothing's cost at a fine size): axisymmetric structured scaledCell at 0.06 um (nucleus, cytoplasm; membrane 0.05 um, 2 layers): well below maxElements; none, then elliptic (Gauss-Seidel until a move below 1e-7 of the smallest size). Expected: both end within 300 s each, or elliptic refuses up front with an estimate/limit; never a run that only the KILL timeout ends (rc 137) with no word on its progress. (P1b: run with K08T=1200, a 1200 s limit for the elliptic run, to see whether it ends)
. "$(dirname "$0")/../lib.sh"
mdir; mset meshType structured; mset nucleusShape scaledCell; mset nucleusSize 0.06e-6; mset cytoplasmSize 0.06e-6; mset membraneSize 0.05e-6; mset membraneLayers 2
cm "" 300; grep -a -i -m2 'quadrilaterals\|elements' $W/try.log | cut -c1-160
mset structuredSmoothing elliptic; cm "" ${K08T:-300}; grep -a -i -m3 'sweep\|quadrilaterals' $W/try.log | cut -c1-160; tail -3 $W/try.log | cut -c1-200
