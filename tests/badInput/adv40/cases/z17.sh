#!/bin/bash
# z17: pulseStudy (one point, 30 MPa 2 ns, small preview) finished; then (a) a threshold's value changed (axonMorphologicalConservative 0.14 -> 1e-6) and a new threshold (tinyStrain, 1e-16: below the run's peak strains, about 1e-15) added, a user's notes.md in postProcessing/pulseStudy/: ./Allrun again: no point run again, the table's columns follow the new thresholds (userGuide: "the thresholds may change freely, the table and maps are computed again"), notes.md kept? (b) sampleInterval changed: refused naming it, table unchanged?
. "$(dirname "$0")/../lib.sh"
study; run 280 ./Allrun > ../log.s1 2>&1; echo "first: $(tail -2 ../log.s1 | tr '\n' '|' | cut -c1-200)"; T=postProcessing/pulseStudy/table.csv
echo "table header: $(head -1 $T | tr ',' '\n' | grep -i 'timeAbove' | tr '\n' ' ')"; /usr/bin/python3 - $T <<'P'
import csv,sys; r=list(csv.DictReader(open(sys.argv[1]))); print("row:", {k:v for k,v in r[0].items() if 'timeAbove' in k})
P
cp $T ../table1.csv; echo "my notes" > postProcessing/pulseStudy/notes.md
/usr/bin/python3 - system/pulseStudyDict <<'P'
import sys; f=sys.argv[1]; s=open(f).read()
s=s.replace("value       0.14 [-];", "value       1e-6 [-];")
s=s.replace("thresholds\n{", "thresholds\n{\n    tinyStrain\n    {\n        indicator   strain;\n        value       1e-16 [-];\n        source      \"adv40 test threshold\";\n    }", 1)
open(f,'w').write(s)
P
grep -c '1e-6 \[-\]\|tinyStrain' system/pulseStudyDict
run 200 ./Allrun > ../log.s2 2>&1; echo "(a) second: rc=$(grep -o 'rc=.*' <<< "rc=$?") $(grep -a -i -m3 'run\b\|running\|error\|refus' ../log.s2 | cut -c1-160 | tr '\n' '|')"
/usr/bin/python3 - $T <<'P'
import csv,sys; r=list(csv.DictReader(open(sys.argv[1]))); print("(a) row now:", {k:v for k,v in r[0].items() if 'timeAbove' in k})
P
echo "   notes.md: $(cat postProcessing/pulseStudy/notes.md 2>/dev/null || echo GONE)"; cp $T ../table2.csv
sed -i 's/^sampleInterval .*/sampleInterval  1e-9;/' system/pulseStudyDict; run 100 ./Allrun > ../log.s3 2>&1; echo "(b) sampleInterval changed: rc=$? $(grep -a -i -m2 'differ\|refus\|error\|sampleInterval' ../log.s3 | cut -c1-220 | tr '\n' '|')"
cmp -s $T ../table2.csv && echo "   table unchanged" || echo "   table CHANGED"
