#!/bin/bash
# a11 (class 2, 52916a0 and the point copies with a base case holding RESULTS): the base case is a preview that was RUN by its Allrun (its own postProcessing/, solid/, time folders, logs; its Allclean removes them in the study's copy); one point; the user then writes notes.md into base/postProcessing/ (a folder the base case has) and base/1e-09/ (a time folder of the base case); ./Allrun: refused naming them, or removed as the base case's results?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base; (cd $W/base && run 200 ./Allrun $PREV -endTime 2e-9 > log.Allrun.user 2>&1; echo "   base case run by its Allrun: $(ls -d [1-9]* postProcessing solid 2>/dev/null | tr "\n" " ")")
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; run 250 ./Allrun > ../log.s1 2>&1; echo "   first: $(grep -a -i -m2 'error\|done' ../log.s1 | cut -c1-160 | tr '\n' '|')"; B=postProcessing/pulseStudy/base; echo "   base copy: $(ls $B | tr '\n' ' ')"
mkdir -p $B/postProcessing $B/1e-09; echo "a11 notes in postProcessing" > $B/postProcessing/notes.md; echo "a11 notes in time" > $B/1e-09/notes.md
run 250 ./Allrun > ../log.s2 2>&1; echo "   again: $(grep -a -i -m3 'error\|refus\|kept\|holds\|not run' ../log.s2 | cut -c1-300 | tr '\n' '|')"; where "a11 notes in postProcessing" "a11 notes in time"
