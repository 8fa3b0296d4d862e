#!/bin/bash
# g06 (class 1, the indentation's table through an #include): indenterProperties' protocol moved to constant/protocolRows (#include "protocolRows"), the smoke rows, a fine run SIGKILLed soon after its first checkpoint; in copies: (a) row 1 (already run) edited in the included file: refused naming row 1? (b) the last row (not yet run) edited: continued, force.dat equal to an uninterrupted run of the edited table? (c) the included file replaced by an inline table with row 1 edited: refused?
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
/usr/bin/python3 - constant/indenterProperties <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); m = re.search(r'\nprotocol\s*\((?:\s*\([^()]*\))*\s*\);', t)
open(p.replace('indenterProperties', 'protocolRows'), 'w').write(m.group(0).lstrip() + '\n'); open(p, 'w').write(t[:m.start()] + '\n#include "protocolRows"\n' + t[m.end():])
P
cat constant/protocolRows | tr -s ' \n' ' '; echo
cd ..; cp -r ind clean; cd ind
cellIndentationFoam > log.first 2>&1 & p=$!; i=0; until [ -f postProcessing/indentation/restart.h5 ] || [ $i -ge 300 ]; do sleep 0.05; i=$((i+1)); done; sleep 0.2; kill -KILL $p; wait $p 2>/dev/null; latest
echo "   killed: force rows $(grep -vc '^#' postProcessing/indentation/force.dat), last time $(grep -v '^#' postProcessing/indentation/force.dat | tail -1 | awk '{print $1}') s"
cd ..; for c in a b c; do cp -r ind $c; done
cd a; sed -i '0,/0.3e-6 *0.3e-6/s//0.3e-6  0.31e-6/' constant/protocolRows; sums > ../s.a; tryf "(a) row 1 edited in the included file" cellIndentationFoam; grep -a -A2 'other inputs' $W/try.log | tail -2 | cut -c1-200; nochange ../s.a
cd ../b; sed -i 's/\(unload *10e-6 *\)0.5e-6/\10.4e-6/' constant/protocolRows; tail -2 constant/protocolRows | head -1; tryf "(b) last row edited in the included file" cellIndentationFoam; forceOk postProcessing/indentation/force.dat
cd ../clean; sed -i 's/\(unload *10e-6 *\)0.5e-6/\10.4e-6/' constant/protocolRows; cellIndentationFoam > log.u 2>&1; echo "   uninterrupted run of the edited table: rc $?"; cmp -s postProcessing/indentation/force.dat ../b/postProcessing/indentation/force.dat && echo "   (b) force.dat equal to the uninterrupted edited run's" || echo "   (b) force.dat DIFFERS from the uninterrupted edited run's"; cmp -s postProcessing/indentation/peaks.dat ../b/postProcessing/indentation/peaks.dat && echo "   (b) peaks.dat equal" || echo "   (b) peaks.dat DIFFERS"
cd ../c; /usr/bin/python3 - constant/indenterProperties constant/protocolRows <<'P'
import sys
p, r = sys.argv[1], sys.argv[2]; rows = open(r).read().replace('0.3e-6  0.3e-6', '0.3e-6  0.29e-6', 1)
open(p, 'w').write(open(p).read().replace('#include "protocolRows"', rows))
P
grep -c '#include' constant/indenterProperties; sums > ../s.c; tryf "(c) inline table, row 1 edited" cellIndentationFoam; grep -a -A2 'other inputs' $W/try.log | tail -2 | cut -c1-200; nochange ../s.c
