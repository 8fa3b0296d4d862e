#!/bin/bash
# CASETIMEOUT=600
# l29 (new, class 6: the pulse study's grid size - a user pastes a fine grid, the study plans and stages every point):
# the pulse study (study helper: the small preview, one point) with (a) overpressure and duration lists of 300 values
# each (9e4 points of a preview run each), (b) 3000 x 3000 (9e6 points). pulseStudy.py run with a 120 s KILL timeout
# and /usr/bin/time. Expected: refused before anything is staged, naming the point count and a limit an option can raise
# (issue 19 class 6: "estimate the size first and refuse above a limit"); staging folders/cases for each point, or running
# them one after the other for hours without a word = HANG (resource); MemoryError = CRASH.
. "$(dirname "$0")/../lib.sh"
study; cp -a . $W/s0
for n in 300 3000; do cd $W; rm -rf study; cp -a s0 study; cd study
/usr/bin/python3 - system/pulseStudyDict $n <<'P'
import re, sys
p, n = sys.argv[1], int(sys.argv[2]); t = open(p).read()
op = ' '.join('%de6' % (10 + i) for i in range(n)); du = ' '.join('%.6ge-9' % (2 + 0.001 * i) for i in range(n))
t = re.sub(r'^overpressure .*', 'overpressure    (%s);' % op, t, flags=re.M); t = re.sub(r'^duration .*', 'duration        (%s);' % du, t, flags=re.M); open(p, 'w').write(t)
P
tryt 120 "($n x $n) pulseStudy.py" /usr/bin/time -f 'maxRSS %M kB, %e s' /usr/bin/python3 $ROOT/applications/utilities/pulseStudy/pulseStudy.py -case . -dict system/pulseStudyDict
echo "   said: $(say 2 | cut -c1-250) | last: $(tail -1 $W/try.log | cut -c1-120) | staged: $(find postProcessing -maxdepth 3 -type d 2>/dev/null | wc -l) folders, $(du -sh postProcessing 2>/dev/null | cut -f1)"; done
