#!/bin/bash
# d26 (class 2+1, pulseStudy re-run after a finished one-point study with a threshold value changed (axonMorphologicalOptimal 0.21 -> 0.25): the point is not run again and the map uses 0.25, or a refusal naming the threshold; SILENT if the table still uses 0.21 without a word.
. "$(dirname "$0")/../lib.sh"
study; tryt 280 "first study" pulseStudy; ls -R postProcessing 2>/dev/null | head -5; grep -rl "0.21" . --include="*.md" --include="*.csv" --include="*.dat" 2>/dev/null | head -3
sed -i "0,/value       0.21 \[-\];/s//value       0.25 [-];/" system/pulseStudyDict; grep -c "0.25 \[-\]" system/pulseStudyDict
tryt 200 "second study, threshold 0.25" pulseStudy; grep -a -i "run\|skip\|record\|threshold" $W/try.log | head -4 | cut -c1-200; echo "   files naming 0.25: $(grep -rl "0\.25" . --exclude-dir=points 2>/dev/null | grep -v system | head -5 | tr "\n" " ")"
