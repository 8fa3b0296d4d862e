#!/bin/bash
# CASETIMEOUT=1200
# k07 (adv49a j07, adv49b i33/i35 / fix19f's whole loading-table estimate varied): the estimate N printed with maxSteps 1,
# then maxSteps N-1 (refused, the same N) and N (accepted; run to the end where it is short: it must not stop at maxSteps
# before the table's end), for tables the earlier cases did not use: (a) the smoke table with maxDepthIncrement 0.07e-6
# (rows not whole multiples of the increment: 0.3/0.07 = 4.29); (b) the smoke table with holdGrowth 1.0000000000000002
# (a hold of nearly equal steps) and holdDeltaT0 0.1; (c) the killed smoke run (ik) restarted with (a)'s increment edited
# (refused as an input change, or the estimate of what is left); (d) the tutorial's whole table (23 rows), N-1 refused
# and N accepted (the run killed after 45 s). Never a run that stops at maxSteps = N before its end, never N refused.
. "$(dirname "$0")/../lib.sh"
ms() { sed -i '/^maxSteps/d' system/controlDict; echo "maxSteps $1;" >> system/controlDict; }
est() { grep -a -o "about [0-9.e+]* time steps\|at least [0-9.e+]* steps\|about [0-9.e+]* steps" $W/try.log | head -1 | grep -o "[0-9][0-9.e+]*"; }
edge() { local l=$1 full=$2 n; ms 1; tryt 120 "$l: maxSteps 1" cellIndentationFoam; echo "   msg: $(msg 3 | cut -c1-400)"; n=$(est); rm -rf postProcessing .runLock
  [ -z "$n" ] && { echo "   no figure found"; return; }; n=$(/usr/bin/python3 -c "print(int(float('$n')))")
  ms $((n-1)); tryt 120 "$l: maxSteps $((n-1)) (N-1)" cellIndentationFoam; echo "   figure now: $(est) | written: $(ls postProcessing 2>/dev/null)"; rm -rf postProcessing .runLock
  ms $n; tryt $full "$l: maxSteps $n (N)" cellIndentationFoam; echo "   sig: $(sig) | End: $(grep -a -c '^End' $W/try.log) | steps: $(grep -a -c '^Time = ' $W/try.log) | force.dat rows $(nLines postProcessing/indentation/force.dat) | maxSteps lines: $(grep -a -m2 -i 'maxSteps' $W/try.log | cut -c1-200 | tr '\n' '|')"; rm -rf postProcessing .runLock; }
ind; rm -f .runLock; sete constant/indenterProperties maxDepthIncrement 0.07e-6; edge "(a) smoke, maxDepthIncrement 0.07e-6" 400
cd $W; rm -rf ind; ind; rm -f .runLock; sete constant/indenterProperties holdGrowth 1.0000000000000002; sete constant/indenterProperties holdDeltaT0 0.1; edge "(b) smoke, holdGrowth 1.0000000000000002, holdDeltaT0 0.1" 400
cd $W; rm -rf ind; ik; rm -f .runLock; sums > ../s0; sete constant/indenterProperties maxDepthIncrement 0.07e-6; ms 1; tryt 120 "(c) killed smoke run, increment edited, restart maxSteps 1" cellIndentationFoam; echo "   msg: $(msg 4 | cut -c1-500) | changed: $(changed ../s0)"
cd $W; rm -rf ind; mkdir -p ind; cp -r "$ROOT/tutorials/indentation/averageCell"/{system,constant} ind/; cp $ADV/indBase/constant/cell.msh ind/constant/; cd ind; rm -f .runLock; edge "(d) the tutorial's whole table" 45
