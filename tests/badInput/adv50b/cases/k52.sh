#!/bin/bash
# k52 (class 4/silent, elliptic in full3D and with azimuthSize): quarter3D and full3D scaledCell at 1.4 um with azimuthSize 3e-6, structuredSmoothing none and elliptic (the guide: the count and connectivity of none; full3D exactly four quarters). Expected: equal counts none/elliptic per mode, full = 4 x quarter, no inverted element; elliptic's nodes differ from none's.
. "$(dirname "$0")/../lib.sh"
ne() { /usr/bin/python3 -c "import sys; t=open('constant/cell.msh').read(); i=t.index('\$Elements'); print(t[i:].split('\n')[1].split()[1], hash(t[t.index('\$Nodes'):t.index('\$EndNodes')]) % 100000)"; }
for m in quarter3D full3D; do for s in none elliptic; do qm; mset nucleusShape scaledCell; mset azimuthSize 3e-6; mset mode $m; mset structuredSmoothing $s; sed -i '/^fluid/d' system/cellMeshDict.allrun; echo "fluid { type hex; boxSize 30e-6; nearSize 1e-6; farSize 5e-6; growthDistance 20e-6; hexCoeffs { axialSize 1e-6; lateralSize 2e-6; } }" >> system/cellMeshDict.allrun
  cm "" 300; echo "   $m $s: elements, node hash: $(ne 2>&1 | tail -1)"; done; done
