#!/bin/bash
# g13 (class 2, pulseStudy outputs with a user's files): a one-point study SIGKILLed (its whole group) while its point runs; the user's notes.md in postProcessing/pulseStudy/points/<label>/ (beside the case copy) and postProcessing/pulseStudy/notes.md; ./Allrun again ("a point without a record is run again from a fresh copy"): the user's files kept? then, the study finished, a user's file in points/<label>/ and ./Allrun once more: kept?
. "$(dirname "$0")/../lib.sh"
study; setsid ./Allrun > ../log.s1 2>&1 & p=$!; waitFor 120 bash -c 'ls -d postProcessing/pulseStudy/points/*/case/1e-09' ; sleep 0.5; kill -KILL -- -$p; wait $p 2>/dev/null; sleep 0.5
pt=$(ls -d postProcessing/pulseStudy/points/* | head -1); echo "   killed: $pt holds $(ls $pt | tr '\n' ' ')"
printf '# g13 my point notes\n' > $pt/notes.md; echo "g13 study notes" > postProcessing/pulseStudy/notes.md
run 280 ./Allrun > ../log.s2 2>&1; grep -a -i -m3 'error\|refus\|user\|not written\|point' ../log.s2 | cut -c1-220; echo "   $pt: $(ls $pt 2>/dev/null | tr '\n' ' ')"; kept "g13 my point notes" "g13 study notes"
echo "g13 after finish" > $pt/mine.txt; run 120 ./Allrun > ../log.s3 2>&1; tail -2 ../log.s3 | cut -c1-200; kept "g13 after finish" "g13 my point notes" "g13 study notes"
