#!/bin/bash
# i33 (class 6/4, cellIndentationFoam's step estimate against controlDict maxSteps, at its edges): the smoke indentation
# (ind: mesh made, no results): maxSteps 1 -> refused with the estimate N printed (a whole count); then maxSteps N-1 refused,
# maxSteps N accepted: the run ends (exit 0) without more than N steps taken, or stops at maxSteps saying so - never a
# run past its maxSteps without a word; maxSteps 2147483648 (beyond the label), 0.5, 1e-301, -1, nan: refused naming the
# entry, value and range; nothing written by any refused run.
. "$(dirname "$0")/../lib.sh"
ind; ms() { sed -i '/^maxSteps/d' system/controlDict; echo "maxSteps $1;" >> system/controlDict; }
ms 1; tryt 120 "maxSteps 1" cellIndentationFoam; N=$(grep -a -o 'about [0-9]*\|[0-9][0-9]* steps\|[0-9][0-9]* time steps' $W/try.log | grep -o '[0-9]*' | head -1); echo "   estimate N = $N; written: $(ls postProcessing 2>/dev/null)"
[ -n "$N" ] && { ms $((N-1)); tryt 120 "maxSteps N-1 = $((N-1))" cellIndentationFoam; echo "   written: $(ls postProcessing 2>/dev/null)"
  ms $N; tryt 400 "maxSteps N = $N" cellIndentationFoam; echo "   rows: force.dat $(nLines postProcessing/indentation/force.dat); steps in log: $(grep -a -c '^Time = ' $W/try.log) | $(grep -a -i -m2 'maxSteps\|steps' $W/try.log | cut -c1-160 | tr '\n' '|')"; rm -rf postProcessing; }
for v in 2147483648 0.5 1e-301 -1 nan; do ms $v; tryt 60 "maxSteps $v" cellIndentationFoam; echo "   written: $(ls postProcessing 2>/dev/null)"; rm -rf postProcessing; done
