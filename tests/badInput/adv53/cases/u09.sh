#!/bin/bash
# CASETIMEOUT=600
# u09 (fix19i row "a user's DICT.allrun" (allrunSettingsOwn), varied: links and the tracked dictionary it appends to):
# the preview tutorial copied as A (prepared by its Allrun -noRun, small options) and B, A's copy without results, with
# (a) B/system/controlDict.allrun a symbolic link to a user's file ~/my.allrun (first line: the Allrun's header, then
# "endTime 7e-9;"): B's ./Allrun -noRun; (b) B/system/controlDict a link to A's controlDict, whose "#sinclude
# controlDict.allrun" line A's user had removed: B's ./Allrun -noRun (does it append the line into A's file?); (c) B's
# system/cellMeshDict.allrun a hard link to A's: B's ./Allrun -noRun with other sizes. Expected: a user's or another case's
# file never changed (refused naming it, or written as B's own file); A's files changed = DATALOSS.
. "$(dirname "$0")/../lib.sh"
O="-h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6 -Z 20e-6 -noPlots -noVTK"
prev; tryt 300 "(0) A prepared: ./Allrun $O -noRun" ./Allrun $O -endTime 2e-9 -noRun; echo "   A holds: $(ls | tr '\n' ' ' | cut -c1-200)"; cd $W; mv c A
mkB() { rm -rf $W/B; mkdir $W/B; cp -r $ROOT/tutorials/blast/axisymmetricPreview/. $W/B/; cd $W/B; ./Allclean > /dev/null 2>&1; }
printf '// Written by Allrun from its options (removed by Allclean)\nendTime 7e-9;\n' > $W/my.allrun; cp $W/my.allrun $W/my.orig
mkB; ln -s $W/my.allrun system/controlDict.allrun; tryt 300 "(a) B/system/controlDict.allrun a link to the user's ~/my.allrun" ./Allrun $O -noRun
echo "   said: $(say 2 | cut -c1-250) | user's file: $(cmp -s $W/my.allrun $W/my.orig && echo kept || echo CHANGED) | B's controlDict.allrun: $([ -L system/controlDict.allrun ] && echo still a link || echo own file)"
cd $W/A; sed -i '/^#sinclude "controlDict.allrun"/d' system/controlDict; sums > $W/sA
mkB; rm system/controlDict; ln -s $W/A/system/controlDict system/controlDict; tryt 300 "(b) B/system/controlDict a link to A's (A's without the #sinclude line)" ./Allrun $O -endTime 5e-9 -noRun
echo "   said: $(say 2 | cut -c1-250) | A changed: $(cd $W/A; changed $W/sA | cut -c1-250) | A's controlDict #sinclude lines: $(grep -c 'sinclude' $W/A/system/controlDict)"
cd $W/A; sums > $W/sA; mkB; ln $W/A/system/cellMeshDict.allrun system/cellMeshDict.allrun 2>/dev/null || echo "   (A has no cellMeshDict.allrun)"
tryt 300 "(c) B/system/cellMeshDict.allrun a hard link to A's, B's Allrun with -cell 1.2e-6" ./Allrun ${O/-cell 1e-6/-cell 1.2e-6} -noRun
echo "   said: $(say 2 | cut -c1-250) | A changed: $(cd $W/A; changed $W/sA | cut -c1-250)"
