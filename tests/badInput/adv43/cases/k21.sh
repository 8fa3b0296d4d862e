#!/bin/bash
# k21 (class 2, k07/k20 (c) with a longer point so that the kill lands while it runs; added after k07's and k20's kills landed after the point had finished on the faster final build): a one-point study whose point runs to 8 ns, SIGKILLed (its group) once points/<label>/case/1e-09 exists; the user's notes.txt into points/<label>/case/ and into points/<label>/case/postProcessing/fsi/0/, notes.md into postProcessing/pulseStudy/base/ and notes.md into points/<label>/ (g13); ./Allrun again: which are kept, which named?
. "$(dirname "$0")/../lib.sh"
S=postProcessing/pulseStudy; study; sed -i 's/-endTime 2e-9)/-endTime 8e-9)/' system/pulseStudyDict; grep -a '^baseOptions\|^duration' system/pulseStudyDict | tr -s ' ' | tr '\n' ' '; echo
setsid ./Allrun > ../log.c1 2>&1 & p=$!; waitFor 120 bash -c 'ls -d postProcessing/pulseStudy/points/*/case/1e-09'; sleep 0.3; kill -KILL -- -$p; wait $p 2>/dev/null; sleep 0.5
pt=$(ls -d $S/points/* | head -1); echo "   killed: $pt holds $(ls $pt | tr '\n' ' '); case times: $(ls -d $pt/case/[1-9]* 2>/dev/null | xargs -n1 basename 2>/dev/null | tr '\n' ' ')"
echo "k21 case notes" > $pt/case/notes.txt; echo "k21 case fsi notes" > $pt/case/postProcessing/fsi/0/notes.txt; echo "# k21 base notes" > $S/base/notes.md; echo "# k21 point notes" > $pt/notes.md
run 280 ./Allrun > ../log.c2 2>&1; grep -a -i -m4 'error\|refus\|kept\|again\|yours' ../log.c2 | cut -c1-240; echo "   $pt: $(ls $pt 2>/dev/null | tr '\n' ' ')"; kept "k21 case notes" "k21 case fsi notes" "k21 base notes" "k21 point notes"
