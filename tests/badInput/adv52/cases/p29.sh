#!/bin/bash
# CASETIMEOUT=900
# p29 (new, class 2: a user's own <dictionary>.allrun files, the untracked files an Allrun writes its options into, when
# the Allrun runs): a copy of tutorials/blast/axisymmetricPreview where the user wrote (by hand, the way the dictionaries'
# #sinclude invites) system/controlDict.allrun "endTime 3e-9; // my run" and constant/fsiProperties.allrun
# "coupling { maxIter 50; }", then `./Allrun -noRun` with the small sizes (no option for those entries). Then (b) the same
# in the indentation tutorial with a user's constant/indenterProperties.allrun. Expected: the user's files kept and used,
# or the Allrun refusing to replace a file it did not write (naming it); the user's files removed or replaced without a
# word = DATALOSS (low if the docs say .allrun files are the Allrun's own).
. "$(dirname "$0")/../lib.sh"
cp -r $ROOT/tutorials/blast/axisymmetricPreview $W/p; cd $W/p; ./Allclean > /dev/null 2>&1
printf 'endTime 3e-9; // my run\n' > system/controlDict.allrun; printf 'coupling { maxIter 50; } // mine\n' > constant/fsiProperties.allrun
tryt 400 "(a) ./Allrun -noRun with the user's controlDict.allrun and fsiProperties.allrun" ./Allrun -noRun -noPlots -noVTK -h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6
echo "   said: $(grep -a -m2 -i 'error\|refus\|allrun' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"
echo "   controlDict.allrun now: $(tr '\n' ' ' < system/controlDict.allrun 2>/dev/null | cut -c1-200) | fsiProperties.allrun now: $(tr '\n' ' ' < constant/fsiProperties.allrun 2>/dev/null | cut -c1-200)"
echo "   user's lines kept: endTime $(grep -c 'my run' system/controlDict.allrun 2>/dev/null), maxIter $(grep -c 'mine' constant/fsiProperties.allrun 2>/dev/null)"
cp -r $ROOT/tutorials/indentation/averageCell $W/i; cd $W/i; ./Allclean > /dev/null 2>&1; ls constant system | tr '\n' ' ' | sed 's/^/   indentation files: /'; echo
printf 'maxDepthIncrement 0.2e-6; // mine\n' > constant/indenterProperties.allrun
tryt 60 "(b) the indentation ./Allrun with a user's indenterProperties.allrun (stopped after 60 s)" ./Allrun; killAll $W/i
echo "   said: $(grep -a -m2 -i 'error\|refus\|allrun' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300) | indenterProperties.allrun now: $(tr '\n' ' ' < constant/indenterProperties.allrun 2>/dev/null | cut -c1-200)"
