#!/bin/bash
# k07 (class 4/6, elliptic at the edges of the sizes' ranges): structured scaledCell axisymmetric with elliptic and (a) nucleusSize = cytoplasmSize = membraneSize = cellHeight (7.9e-6, the range's edge (0, H]), (b) the sizes at 7.9e-6 + 1 ulp (7.900000000000002e-06: refused with digits that show it above H), (c) membraneLayers 20 (edge) with 0.5 um sizes. Expected: meshed or refused naming the entry, never a crash, a hang (300 s) or an inverted element written.
. "$(dirname "$0")/../lib.sh"
mdir; mset meshType structured; mset nucleusShape scaledCell; mset structuredSmoothing elliptic
for k in nucleusSize cytoplasmSize membraneSize; do mset $k 7.9e-6; done; cmk "(a) every size = H"; grep -a -i -m2 'sweep\|scaled Jacobian' $W/try.log | cut -c1-160
for k in nucleusSize cytoplasmSize membraneSize; do mset $k 7.900000000000002e-06; done; cmk "(b) every size = H + 1 ulp"
for k in nucleusSize cytoplasmSize; do mset $k 0.5e-6; done; mset membraneSize 0.4e-6; mset membraneLayers 20; cmk "(c) membraneLayers 20 + elliptic"; grep -a -i -m2 'sweep\|scaled Jacobian' $W/try.log | cut -c1-160
