#!/bin/bash
# a31 (class 6, sizes in the 3D modes and planeWave): peak memory and time of each refusal (/usr/bin/time): cellMesh quarter3D with (a) nucleusSize = cytoplasmSize = membraneSize 2e-8 (cell ~1e9 elements), (b) azimuthSize 1e-9, (c) hexCoeffs lateralSize 5e-9 and axialSize 5e-9 (~1e13 hex cells, maxCells default), (d) mode full3D with (a)'s sizes; planeWave -inflow on a planeWaveInflow case (iblast) (e) -dz 1e-12 (cells), (f) -endTime 1 (steps): refused quickly naming the entry, the count and the limit, without allocating?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/quarter3D" $W/q; cd $W/q; f=system/cellMeshDict; cp $f ../orig
m() { /usr/bin/time -f "%e s wall, %M kB peak" -o ../time timeout -s KILL 120 "$@" > ../log.m 2>&1; local rc=$?; echo "   rc=$rc, $(cat ../time | tail -1) | $(grep -a -m1 -A2 -i 'error\|refus' ../log.m | tr '\n' ' ' | tr -s ' ' | cut -c1-300)"; }
sed -i 's/^nucleusSize .*/nucleusSize 2e-8;/; s/^cytoplasmSize .*/cytoplasmSize 2e-8;/; s/^membraneSize .*/membraneSize 2e-8;/' $f; echo "(a) cell sizes 2e-8"; m cellMesh; cp ../orig $f
echo 'azimuthSize 1e-9;' >> $f; echo "(b) azimuthSize 1e-9"; m cellMesh; cp ../orig $f
sed -i 's/axialSize   0.5e-6;/axialSize 5e-9;/; s/lateralSize 1e-6;/lateralSize 5e-9;/' $f; echo "(c) hex 5e-9"; m cellMesh; cp ../orig $f
sed -i 's/^mode .*/mode full3D;/; s/^nucleusSize .*/nucleusSize 2e-8;/; s/^cytoplasmSize .*/cytoplasmSize 2e-8;/; s/^membraneSize .*/membraneSize 2e-8;/' $f; echo "(d) full3D, sizes 2e-8"; m cellMesh; cp ../orig $f
cd $W; iblast; echo "(e) planeWave -inflow -dz 1e-12 -overwrite"; m planeWave $IW -dz 1e-12 -overwrite; echo "(f) planeWave -inflow -endTime 1 -overwrite"; m planeWave $IW -endTime 1 -overwrite
