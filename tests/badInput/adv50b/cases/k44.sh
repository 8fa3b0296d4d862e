#!/bin/bash
# k44 (class 3, two quarter Allruns at once on one fresh copy, one straight and one -oGrid orthogonal): both started within 0.2 s with the smoke sizes and -noRun. Expected: one refused naming the other (the Allrun lock), the other prepares the case; .allrunOptions names the options of the meshes in the case (checked: oGrid in cellMeshDict.allrun against .allrunOptions, and the fluid.msh against a cellMesh of the recorded options).
. "$(dirname "$0")/../lib.sh"
S="-box 30e-6 -h 1e-6 -dz 1e-6 -lateral 2e-6 -far 5e-6 -noRun -noPlots"
cp -r "$ROOT/tutorials/blast/quarter3D" $W/qa; cd $W/qa; (./Allrun $S > $W/a1.log 2>&1; echo "rc=$?" >> $W/a1.log) & a=$!; sleep 0.2; (./Allrun $S -oGrid orthogonal > $W/a2.log 2>&1; echo "rc=$?" >> $W/a2.log) & b=$!; wait $a $b
echo "   straight: $(grep -a -i -m1 'refus\|in use\|lock\|error' $W/a1.log | cut -c1-200) $(tail -1 $W/a1.log)"; echo "   orthogonal: $(grep -a -i -m1 'refus\|in use\|lock\|error' $W/a2.log | cut -c1-200) $(tail -1 $W/a2.log)"
echo "   .allrunOptions: $(tr -d '\n ' < .allrunOptions 2>/dev/null | cut -c1-200)"; echo "   cellMeshDict.allrun: $(tr '\n' ' ' < system/cellMeshDict.allrun | cut -c1-250)"; grep -a -i -m1 'sweep' log.cellMesh | cut -c1-120
