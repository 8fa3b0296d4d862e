#!/bin/bash
# w53: cellMesh resources: full3D with 0.05 um sizes (about 1e8 elements) and a quarter3D hex water with 1e-8 m axialSize: refused by the estimates before meshing, the message naming the count and the option?
. "$(dirname "$0")/../lib.sh"
ind; cp system/cellMeshDict ../orig; sed -i 's/^mode .*/mode full3D;/; s/^nucleusSize .*/nucleusSize 0.05e-6;/; s/^cytoplasmSize .*/cytoplasmSize 0.05e-6;/; s/^membraneSize .*/membraneSize 0.05e-6;/' system/cellMeshDict; grep -q "^mode" system/cellMeshDict || echo "mode full3D;" >> system/cellMeshDict
/usr/bin/time -f "%e s %M kB" timeout -s KILL 60 cellMesh > log.a 2>&1; echo "rc=$?"; fatal log.a 3; tail -1 log.a
cp ../orig system/cellMeshDict; sed -i 's/^mode .*/mode quarter3D;/' system/cellMeshDict; grep -q "^mode" system/cellMeshDict || echo "mode quarter3D;" >> system/cellMeshDict
printf 'fluid { boxSize 100e-6; nearSize 0.5e-6; farSize 5e-6; growthDistance 20e-6; type hex; hexCoeffs { axialSize 1e-8; } }\n' >> system/cellMeshDict
/usr/bin/time -f "%e s %M kB" timeout -s KILL 60 cellMesh > log.b 2>&1; echo "rc=$?"; fatal log.b 3; tail -1 log.b
