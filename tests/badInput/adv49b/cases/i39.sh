#!/bin/bash
# i39 (class 1/2, pulseStudy stopped and resumed with a changed dictionary): the small study (study: 20 um column, 2 ns) with two
# points (30, 40 MPa; nProcs 1), SIGTERMed once the first point's result.json exists (the second running). Resumed with
# (a) sampleInterval 1e-9: refused before anything runs, naming sampleInterval and the finished point, nothing moved;
# (b) baseOptions with -cell 0.4e-6: refused likewise; (c) the dictionary back but a threshold added, nProcs 2 and a third
# point (50 MPa): the finished point is not run again (its record unchanged), the interrupted one's copy moved aside to
# case.interrupted (said), the other two run; the table has 3 rows; exit 0.
. "$(dirname "$0")/../lib.sh"
study; setStudy overpressure "(30e6 40e6)"; cp system/pulseStudyDict ../d0; P=postProcessing/pulseStudy/points
pulseStudy > ../log.s1 2>&1 & p=$!; waitFor 400 bash -c "ls $P/*/result.json" && echo "   first record: $(ls $P/*/result.json)"; sleep 2; kill -TERM $p; wait $p; echo "   study exit $? | $(tail -2 ../log.s1 | cut -c1-160 | tr '\n' '|')"
ls $P; md5sum $P/*/result.json > ../r0; echo "   running left: $(inDir $W/study)"; snap ../snap0
setStudy sampleInterval 1e-9; tryt 120 "(a) sampleInterval 1e-9" pulseStudy; echo "   moved/changed: $(gone ../snap0 | tr '\n' ' ')"; cp ../d0 system/pulseStudyDict
setStudy baseOptions "(-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.4e-6 -Z 20e-6 -endTime 2e-9)"; tryt 120 "(b) baseOptions -cell 0.4e-6" pulseStudy; echo "   moved/changed: $(gone ../snap0 | tr '\n' ' ')"; cp ../d0 system/pulseStudyDict
setStudy overpressure "(30e6 40e6 50e6)"; setStudy nProcs 2; /usr/bin/python3 - <<'P'
p = 'system/pulseStudyDict'; t = open(p).read(); i = t.index('thresholds'); j = t.index('{', i) + 1
t = t[:j] + '\n    extraPressure { indicator pressure; value 1e6 [Pa]; source "a test threshold (adv49b i39)"; }\n' + t[j:]; open(p, 'w').write(t)
P
tryt 900 "(c) resumed: threshold added, nProcs 2, a third point" pulseStudy; tail -4 $W/try.log | cut -c1-200 | sed 's/^/   /'
echo "   points: $(ls $P | tr '\n' ' ') | aside: $(ls -d $P/*/case.interrupted* 2>/dev/null | tr '\n' ' ')"; md5sum -c ../r0 | sed 's/^/   /'; echo "   table rows: $(grep -vc '^#' postProcessing/pulseStudy/table.csv 2>/dev/null)"
