#!/bin/bash
# d26 (class 2+1, pulseStudy re-run after a finished one-point study with a threshold value changed (axonMorphologicalOptimal 0.21 -> 1e-20, which every region crosses: corrected after the first run, where 0.25 was crossed by no region like 0.21): the point is not run again and the table's timeAbove:axonMorphologicalOptimal columns are > 0 s, or a refusal naming the threshold; SILENT if they stay 0 without a word.
. "$(dirname "$0")/../lib.sh"
study; tryt 280 "first study" pulseStudy; ls -R postProcessing 2>/dev/null | head -5; grep -rl "0.21" . --include="*.md" --include="*.csv" --include="*.dat" 2>/dev/null | head -3
python3 -c "import csv; r=list(csv.DictReader(open('postProcessing/pulseStudy/table.csv'))); print('   first: timeAbove axonMorphologicalOptimal:', {k.split(':')[0]: r[0][k] for k in r[0] if 'timeAbove:axonMorphologicalOptimal' in k})"
sed -i "0,/value       0.21 \[-\];/s//value       1e-20 [-];/" system/pulseStudyDict; grep -c "1e-20 \[-\]" system/pulseStudyDict
tryt 200 "second study, threshold 1e-20" pulseStudy; grep -a -i "run\|skip\|record\|threshold" $W/try.log | head -4 | cut -c1-200; python3 -c "import csv; r=list(csv.DictReader(open('postProcessing/pulseStudy/table.csv'))); print('   timeAbove axonMorphologicalOptimal:', {k.split(':')[0]: r[0][k] for k in r[0] if 'timeAbove:axonMorphologicalOptimal' in k})"
