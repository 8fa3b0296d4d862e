#!/bin/bash
# i03 (class 6, structured 3D counts): quarter3D (structured only) with (a) azimuthSize 1e-8 (every ring's elements per quarter
# turn and the pole disc), (b) membraneSize 2e-8 with nucleus/cytoplasm 3e-6, (c) membraneLayers 20 and azimuthSize 0.3e-6,
# and the fluid box left as the tutorial's (hex maxCells). Each refused before meshing (maxElements or hexCoeffs/maxCells,
# the count and the limit named) or meshed within memory (maxRSS < 1.5 GB) under 300 s; never killed by the timeout ((a) is given 900 s since P1b: it was killed at 300 s wall in P1 at load ~15).
. "$(dirname "$0")/../lib.sh"
mdir quarter3D; mset azimuthSize 1e-8; cm "" 900; grep -a -i -m2 'maxElements\|maxCells' $W/try.log | cut -c1-250
mdir quarter3D; mset membraneSize 2e-8; mset nucleusSize 3e-6; mset cytoplasmSize 3e-6; cm; grep -a -i -m2 'maxElements\|maxCells' $W/try.log | cut -c1-250
mdir quarter3D; mset membraneLayers 20; mset azimuthSize 0.3e-6; cm; grep -a -i -m2 'maxElements\|maxCells' $W/try.log | cut -c1-250
