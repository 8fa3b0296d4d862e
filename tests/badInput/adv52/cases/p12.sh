#!/bin/bash
# CASETIMEOUT=900
# p12 (new, class 2: a tutorial's Allrun run again in a FINISHED case with other mesh options, without -overwrite):
# the finished preview bd with the tutorial's Allrun and Allclean copied in: (a) `./Allrun -noRun -cell 0.7e-6` (other
# meshes over the results of 1e-09, 2e-09, solid/), (b) `./Allrun -cell 0.7e-6 -endTime 2e-9` (a whole re-run);
# (c) the smoke indentation (idn) with its Allrun: `./Allrun` again. Expected: refused before the meshes are replaced
# (the results would no longer belong to the case's mesh), naming the results and -overwrite or Allclean; meshes replaced
# under the kept results (constant/cell.msh, polyMesh new, 1e-09 old) = DATALOSS (the results can no longer be
# restarted, converted or read with their mesh).
. "$(dirname "$0")/../lib.sh"
bd; cp $ROOT/tutorials/blast/axisymmetricPreview/{Allrun,Allclean} .; sums > $W/s0; msh > $W/m0
st() { echo "   meshes: $( [ "$(msh)" = "$(cat $W/m0)" ] && echo kept || echo "REPLACED ($(cat $W/m0) -> $(msh))") | times: $(ls -d [0-9]* 2>/dev/null | tr '\n' ' ') | solid.h5 $(h5steps solid/solid.h5 2>/dev/null) steps | changed: $(changed $W/s0 | cut -c1-300)"; echo "   said: $(grep -a -m2 -i 'error\|refus\|overwrite\|exist' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"; }
tryt 400 "(a) ./Allrun -noRun -cell 0.7e-6 in the finished case" ./Allrun -noRun -noPlots -noVTK -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.7e-6 -Z 20e-6; st
tryt 600 "(b) ./Allrun -cell 0.7e-6 -endTime 2e-9" ./Allrun -noPlots -noVTK -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.7e-6 -Z 20e-6 -endTime 2e-9 -writeInterval 1e-9; st
cd $W; idn; cp $ROOT/tutorials/indentation/averageCell/{Allrun,Allclean} .; sums > $W/s0; msh > $W/m0
tryt 600 "(c) the indentation ./Allrun again in the finished case" ./Allrun; echo "   force.dat rows $(grep -vc '^#' postProcessing/indentation/force.dat 2>/dev/null) | changed: $(changed $W/s0 | cut -c1-300)"; echo "   said: $(grep -a -m2 -i 'error\|refus\|overwrite\|exist' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"
