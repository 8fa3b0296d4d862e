#!/bin/bash
# f24 (class 6, a huge grid): pulseStudy with 3000 overpressures x 3000 durations (9e6 points, maxPoints 1000): refused within seconds naming maxPoints and the count; never minutes of building the grid (a 1e6 grid hung before).
. "$(dirname "$0")/../lib.sh"
study; o=$(/usr/bin/python3 -c "print(' '.join('%.6ge6' % (1 + i * 0.01) for i in range(3000)))"); d=$(/usr/bin/python3 -c "print(' '.join('%.6ge-9' % (1 + i * 0.001) for i in range(3000)))")
setStudy overpressure "($o)"; setStudy duration "($d)"; wc -c system/pulseStudyDict
s=$(date +%s.%N); tryt 120 "9e6 points" pulseStudy; echo "   took $(echo "$(date +%s.%N) - $s" | bc | cut -c1-5) s (load $(cut -d' ' -f1 /proc/loadavg))"
