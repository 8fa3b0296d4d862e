#!/bin/bash
# k16 (class 2, pulseStudy: a finished study, then a grid value added): the user's notes.md in the finished point's folder, a copy of table.csv in points/, result.json (a copy of the point's) in postProcessing/pulseStudy/mine/, and notes.md in the folder the NEW point will run in (made before: points/p4e+07_T2e-09/); ./Allrun with overpressure (30e6 40e6): kept? the new point run (or refused naming the folder)?
. "$(dirname "$0")/../lib.sh"
study; run 200 ./Allrun > ../log.s1 2>&1; S=postProcessing/pulseStudy; pt=$(ls -d $S/points/* | head -1); echo "   first study: $(tail -1 ../log.s1 | cut -c1-150); $pt: $(ls $pt | tr '\n' ' ')"
echo "# k16 finished point notes" > $pt/notes.md; cp $S/table.csv $S/points/table.csv; echo "k16 table copy" >> $S/points/table.csv; mkdir -p $S/mine; cp $pt/result.json $S/mine/result.json; mkdir -p $S/points/p4e+07_T2e-09; echo "# k16 new point notes" > $S/points/p4e+07_T2e-09/notes.md
setStudy overpressure "(30e6 40e6)"; run 250 ./Allrun > ../log.s2 2>&1; grep -a -i -m4 'error\|refus\|yours\|notes\|point' ../log.s2 | cut -c1-220; echo "   points: $(ls $S/points | tr '\n' ' '); new point: $(ls $S/points/p4e+07_T2e-09 2>/dev/null | tr '\n' ' '); table rows: $(grep -vc '^#\|^overpressure' $S/table.csv 2>/dev/null)"
kept "k16 finished point notes" "k16 table copy" "k16 new point notes"; echo "   mine/result.json: $(ls $S/mine 2>/dev/null)"
