#!/bin/bash
# i08 (class 2/4, the structured preview end to end): `Allrun $MYPREV -meshType structured -endTime 5e-9` (-noVTK -noPlots) (all
# its steps, the planeWave check included): exit 0, log.cellMesh says structured and that the contact entries are not used,
# coupling.dat and solidProbes written with finite values, and its water probes (fluidProbes/p) within 2 % of the
# unstructured base's (xbd: the same options but -predictor extrapolated; the water column is the same; the solid's logs
# are of another mesh, printed only); a second identical Allrun
# runs nothing again and changes nothing.
. "$(dirname "$0")/../lib.sh"
xbd; B=$PWD; prev; tryt 600 "Allrun -meshType structured" ./Allrun $MYPREV -meshType structured -endTime 5e-9; tail -3 $W/try.log | sed 's/^/   /'
echo "   cellMesh: $(grep -a -i -m3 'structured\|contact\|not used' log.cellMesh | cut -c1-160 | tr '\n' '|')"
echo "   logs: $(ls log.* | tr '\n' ' ')"; echo "   nan/inf in logs: $(grep -ril --include='*.dat' 'nan\|inf' postProcessing | tr '\n' ' ')"; closeTo $B
sums > ../s0; tryt 600 "same Allrun again" ./Allrun $MYPREV -meshType structured -endTime 5e-9; echo "   changed: $(changed ../s0)"
