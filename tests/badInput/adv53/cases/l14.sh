#!/bin/bash
# CASETIMEOUT=600
# l14 (new, class 3: two mesh writers at once in one folder, a second terminal): (a) two `cellMesh` 0.3 s apart in the
# quarter's mesh folder (qm: gmsh, a few seconds each); (b) two fluidWedgeMesh.py writing the same system/blockMeshDict
# with different -h, 0.05 s apart (the preview's water dictionary); (c) two `planeWave -inflow 20e-6 -Z 40e-6 -case .`
# 0.3 s apart in the inflow preview ibd (both write constant/inflowWave). Expected: the second refused naming the first,
# or both outputs whole (each file written atomically: the one on disk is one run's, complete); a mixed or cut file
# (gmsh's .msh, the dictionary, inflowWave with rows of both) = SILENT/DATALOSS.
. "$(dirname "$0")/../lib.sh"
qm; cellMesh > $W/m1.log 2>&1 & p1=$!; sleep 0.3; tryt 300 "(a) a second cellMesh 0.3 s after the first" cellMesh; wait $p1; r1=$?
echo "   first rc $r1 $(grep -a -i -m1 'error\|in use' $W/m1.log | cut -c1-150) | second said: $(say 2 | cut -c1-200) | cell.msh: $(head -c 200 constant/cell.msh | grep -c MeshFormat) MeshFormat, ends $(tail -c 20 constant/cell.msh | tr '\n' ' ') | fluid.msh ends $(tail -c 20 constant/fluid.msh 2>/dev/null | tr '\n' ' ')"
cd $W; mkdir -p w/system; cd w; FW="/usr/bin/python3 $ROOT/tutorials/blast/fluidWedgeMesh.py -Z 20e-6 -R 20e-6"
$FW -h 0.1e-6 > $W/w1.log 2>&1 & p2=$!; sleep 0.05; $FW -h 0.5e-6 > $W/w2.log 2>&1; r2=$?; wait $p2; r1=$?
echo "   (b) two fluidWedgeMesh.py: rc $r1 / $r2 | blockMeshDict: $(wc -c < system/blockMeshDict) B, ends: $(tail -c 60 system/blockMeshDict | tr '\n' ' ') | blockMesh: $(blockMesh > $W/bm.log 2>&1; echo rc $?; grep -a -m1 -i 'error' $W/bm.log | cut -c1-100)"
cd $W; ibd; md5sum constant/inflowWave > $W/iw0; planeWave -inflow 20e-6 -Z 40e-6 -case . > $W/p1.log 2>&1 & p3=$!; sleep 0.3; tryt 300 "(c) a second planeWave -inflow 0.3 s after the first" planeWave -inflow 20e-6 -Z 40e-6 -case .; wait $p3; r3=$?
echo "   first rc $r3 $(grep -a -i -m1 'error\|in use' $W/p1.log | cut -c1-200) | second said: $(say 2 | cut -c1-200) | inflowWave: $(md5sum -c $W/iw0 > /dev/null 2>&1 && echo unchanged || echo rewritten) rows $(grep -vc '^#' constant/inflowWave)"
