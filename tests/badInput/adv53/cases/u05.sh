#!/bin/bash
# CASETIMEOUT=600
# u05 (fix19i row "a planeWave reference cut in its last row" (readReference), varied: the damage elsewhere than the last
# row): the finished preview with its planeWave reference (pwd0); postProcessing/planeWave/0/reference.dat (a) a middle
# row cut to 3 columns, (b) a middle row's bytes zeroed (NUL, as a power loss leaves), (c) a middle row with an extra
# column, (d) the header's column line removed, (e) only the header left (no rows), (f) a row's time duplicated;
# each read by incidentWindow.py and by planeWave -check -reference <file>. Expected: refused naming the file and line
# (or, for (f), the times not increasing); a measure printed rc 0 from the damaged file = SILENT; a traceback = CRASH.
. "$(dirname "$0")/../lib.sh"
pwd0; R=postProcessing/planeWave/0/reference.dat; cp $R $W/ref0; n=$(grep -vc '^#' $R); echo "   reference rows: $n"
iw .; echo "   (0) control incidentWindow: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-200)"
tryt 300 "(0) control planeWave -check -reference" planeWave -case . -check -reference $W/ref0; echo "   $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-200)"
ed_() { /usr/bin/python3 - $R "$1" <<'P'
import sys
p, how = sys.argv[1:3]; b = open(p, 'rb').read().split(b'\n'); rows = [i for i, l in enumerate(b) if l.strip() and not l.startswith(b'#')]; k = rows[len(rows) // 2]
if how == 'cut': b[k] = b' '.join(b[k].split()[:3])
elif how == 'nul': b[k] = b'\0' * len(b[k])
elif how == 'extra': b[k] = b[k] + b' 12345'
elif how == 'nohead': b = [l for l in b if not l.startswith(b'# time')]
elif how == 'empty': b = [l for l in b if l.startswith(b'#')] + [b'']
elif how == 'dup': b[k + 1] = b[k].split()[0] + b' ' + b' '.join(b[k + 1].split()[1:])
open(p, 'wb').write(b'\n'.join(b)); print('   %s: %s (row index %d)' % (p, how, k))
P
}
for h in cut nul extra nohead empty dup; do cp $W/ref0 $R; ed_ $h; cp $R $W/refx
  iw .; echo "   ($h) incidentWindow said: $(grep -a -v '^ *$' $W/try.log | tail -2 | tr '\n' '|' | cut -c1-300) | tracebacks $(grep -a -c Traceback $W/try.log)"
  tryt 300 "($h) planeWave -check -reference" planeWave -case . -check -reference $W/refx; echo "   ($h) planeWave said: $(grep -a -v '^ *$' $W/try.log | tail -2 | tr '\n' '|' | cut -c1-300) | tracebacks $(grep -a -c Traceback $W/try.log)"; done
cp $W/ref0 $R
