#!/bin/bash
# k13 (class 1, the probes' locations read indirectly, changed before a restart): fluidProbes' probeLocations through #include "probes/locations" (system/probes/locations); finished to 2 ns; the third location moved 20 um -> 30 um; restart to 3 ns: refused, or continued (then the fluidProbes/p series of the two segments are of different points: does the restart say so? does neuronFsi's series() join them?)
. "$(dirname "$0")/../lib.sh"
blast; mkdir -p system/probes; /usr/bin/python3 - system/controlDict system/probes/locations <<'P'
import re, sys; p, q = sys.argv[1:3]; t = open(p).read(); m = re.search(r'probeLocations\s*\((.*?)\n\s*\);', t, re.S)
open(q, 'w').write('probeLocations\n(' + m.group(1) + '\n);\n'); t = t[:m.start()] + '#include "probes/locations"' + t[m.end():]; open(p, 'w').write(t)
P
cat system/probes/locations | grep -v '^ *$' | tr -s ' ' | tr '\n' ' '; echo; cellBlastFoam > log.first 2>&1; echo "   first run rc $?: times $(ls -d [1-9]* | tr '\n' ' ')"; head -4 postProcessing/fluidProbes/0/p | tr '\n' '|' | cut -c1-200; echo
latest; blastEnd 3e-9 1e-9; sed -i 's/(1e-7 20e-6 0)/(1e-7 30e-6 0)/' system/probes/locations; sums > ../s; tryf "probe 2 moved 20 -> 30 um, restart" cellBlastFoam; grep -a -i -A2 'other inputs\|probe' $W/try.log | head -3 | cut -c1-200; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"
[ -d postProcessing/fluidProbes/2e-09 ] && { echo "   segment 2e-09 header: $(head -4 postProcessing/fluidProbes/2e-09/p | tr '\n' '|' | cut -c1-200)"; PYTHONPATH=$ROOT/src/python /usr/bin/python3 -c "
from neuronFsi.postProcessing import series
try:
    a = series('.', 'fluidProbes/p'); print('   series(fluidProbes/p) joined:', a.shape)
except Exception as e: print('   series(fluidProbes/p) refused:', str(e)[:250])
"; }
