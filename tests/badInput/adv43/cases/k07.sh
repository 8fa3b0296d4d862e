#!/bin/bash
# k07 (class 2, re-run of an INTERRUPTED pulseStudy with the user's files at every level): a one-point study SIGKILLed (its group) while its point runs; the user then adds notes in points/<label>/case/postProcessing/ (inside the point's case copy), points/<label>/result.json.mine, points/notes.md, base/notes.md (the study's base copy) and postProcessing/pulseStudy/coupling.dat (a log's name in the wrong folder); ./Allrun again: which are kept, which named?
. "$(dirname "$0")/../lib.sh"
study; setsid ./Allrun > ../log.s1 2>&1 & p=$!; waitFor 120 bash -c 'ls -d postProcessing/pulseStudy/points/*/case/1e-09'; sleep 0.5; kill -KILL -- -$p; wait $p 2>/dev/null; sleep 0.5
S=postProcessing/pulseStudy; pt=$(ls -d $S/points/* | head -1); echo "   killed: $pt holds $(ls $pt | tr '\n' ' '); $S: $(ls $S | tr '\n' ' ')"
mkdir -p $pt/case/postProcessing; echo "k07 in case copy" > $pt/case/postProcessing/k07notes.txt; echo "k07 result mine" > $pt/result.json.mine; echo "# k07 points notes" > $S/points/notes.md; [ -d $S/base ] && echo "k07 base notes" > $S/base/notes.md; echo "k07 coupling in study" > $S/coupling.dat
run 280 ./Allrun > ../log.s2 2>&1; grep -a -i -m4 'error\|refus\|user\|not written\|yours\|kept' ../log.s2 | cut -c1-220; echo "   $pt: $(ls $pt 2>/dev/null | tr '\n' ' '); table: $(ls $S/table.csv 2>/dev/null)"
kept "k07 in case copy" "k07 result mine" "k07 points notes" "k07 base notes" "k07 coupling in study"
