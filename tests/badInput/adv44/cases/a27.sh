#!/bin/bash
# a27 (class 3, pulseStudy copies a base case IN USE): the study's base case is a preview prepared by its Allrun (-noRun) in which the user's own cellBlastFoam runs (to 8 ns, its .runLock there) while ./Allrun of a one-point study starts: refused (the base case is in use), or the half-run case (its lock, times, postProcessing) copied into the study, and what does the point do?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base; cd $W/base; ./Allrun $PREV -endTime 8e-9 -noRun > log.prep 2>&1 || echo "prep failed"; cellBlastFoam > log.cellBlastFoam 2>&1 & p=$!; waitFor 120 test -f 1e-09/.writeCommitted; echo "   base case running: $(lockOf | cut -c1-60)"
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; run 250 ./Allrun > ../log.s1 2>&1; echo "   study: $(grep -a -i -m4 'error\|refus\|in use\|lock\|done\|FAIL' ../log.s1 | cut -c1-260 | tr '\n' '|')"
echo "   base copy holds: $(ls -a postProcessing/pulseStudy/base 2>/dev/null | tr '\n' ' ')"; kill -TERM $p; wait $p; echo "   the user's run: rc=$? (SIGTERMed by the case)"
