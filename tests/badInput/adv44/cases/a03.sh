#!/bin/bash
# a03 (class 1+4, pulseStudy, two grid values that differ below the label's 6 digits): overpressure (30e6 30.0000001e6) (not "given twice": they differ), nProcs 1: both points get the label p3e+07_T2e-09 (one folder). The first point's record replaced by the second's, one table row per point or two rows of one run, said? Then ./Allrun again: refused (another point's record), or re-run?
. "$(dirname "$0")/../lib.sh"
study; setStudy overpressure "(30e6 30.0000001e6)"; run 250 ./Allrun > ../log.s1 2>&1; echo "   rc above; first: $(grep -a -i -m6 'error\|refus\|done\|points\|twice\|same' ../log.s1 | cut -c1-200 | tr '\n' '|')"
S=postProcessing/pulseStudy; echo "   points: $(ls $S/points | tr '\n' ' '); table: $(cut -c1-40 $S/table.csv 2>/dev/null | tr '\n' '|')"
/usr/bin/python3 -c "import json,sys; r=json.load(open(sys.argv[1])); print('   the record in the folder: overpressure', repr(r.get('overpressure')))" $S/points/p3e+07_T2e-09/result.json 2>&1 | tail -1
run 250 ./Allrun > ../log.s2 2>&1; echo "   rc above; again: $(grep -a -i -m4 'error\|refus\|done\|not run\|another' ../log.s2 | cut -c1-240 | tr '\n' '|')"
