#!/bin/bash
# a42 (class 2, pulseStudy's interrupted point's copy moved aside, around it): a one-point study whose point runs to 8 ns; the user's own folder points/<label>/case.interrupted/ (notes.txt) made before; the study SIGKILLed (its group and the point's Allrun) while the point runs; the user's note into points/<label>/case/; ./Allrun again: the point run again; the user's case.interrupted/ and the killed copy (with its note) both kept and named, none replaced?
. "$(dirname "$0")/../lib.sh"
S=postProcessing/pulseStudy; study; sed -i 's/-endTime 2e-9)/-endTime 8e-9)/' system/pulseStudyDict; L=p3e+07_T2e-09; mkdir -p $S/points/$L/case.interrupted; echo "a42 my own case.interrupted" > $S/points/$L/case.interrupted/notes.txt
setsid ./Allrun > ../log.c1 2>&1 & p=$!; waitFor 120 bash -c "ls -d $S/points/$L/case/1e-09"; sleep 0.3; kill -KILL -- -$p; wait $p 2>/dev/null; killIn $W/study/$S; sleep 0.5
echo "   killed: $(ls -a $S/points/$L | tr '\n' ' ')"; echo "a42 note in the killed copy" > $S/points/$L/case/notes.txt
run 280 ./Allrun > ../log.c2 2>&1; grep -a -i -m4 'error\|refus\|kept\|again\|aside\|interrupted' ../log.c2 | cut -c1-260; echo "   now: $(ls -a $S/points/$L | tr '\n' ' ')"; kept "a42 my own case.interrupted" "a42 note in the killed copy"
