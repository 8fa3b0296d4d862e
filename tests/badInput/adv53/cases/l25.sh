#!/bin/bash
# CASETIMEOUT=900
# l25 (new, class 6: many probes - a user samples a line of points by generating probeLocations - each searched in the
# mesh at the start (checkProbesInMesh) and sampled every step): the short preview sb with (a) 2000, (b) 20000 probe
# points on the axis column (inside the water), endTime 2e-11. Each under /usr/bin/time and a 400 s KILL timeout.
# Expected: runs within a few times the plain run's time and memory, or refused above a limit naming it; no end at 400 s
# = HANG (a resource not estimated).
. "$(dirname "$0")/../lib.sh"
sb; cp -a . $W/b0; tryt 300 "(0) plain" /usr/bin/time -f 'maxRSS %M kB, %e s' cellBlastFoam; echo "   $(tail -1 $W/try.log)"
for n in 2000 20000; do cd $W; rm -rf blast; cp -a b0 blast; cd blast
/usr/bin/python3 - system/controlDict $n <<'P'
import re, sys
p, n = sys.argv[1], int(sys.argv[2]); t = open(p).read()
pts = '\n'.join('            (1e-07 %r 0)' % (13e-6 + 6e-6 * i / n) for i in range(n))
t = re.sub(r'probeLocations\s*\(.*?\n\s*\);', 'probeLocations\n        (\n' + pts + '\n        );', t, flags=re.S); open(p, 'w').write(t)
P
tryt 400 "($n) $n probes" /usr/bin/time -f 'maxRSS %M kB, %e s' cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200) | $(tail -1 $W/try.log)"; done
