#!/bin/bash
# CASETIMEOUT=900
# j07 (class 6, fix19e's step estimate (adv48b g44) and whole step counts (adv47b f70) at maxSteps-1, maxSteps, maxSteps+1):
# the estimate N read from the refusal with maxSteps 1, then maxSteps N-1 (refused naming about/at least N steps), N and
# N+1 (accepted: the run starts; killed at 45 s or ends) for: (a) cellBlastFoam, the preview to 2e-11; (b) cellBlastFoam,
# endTime 3e-12 with maxDeltaT 1e-13 (3e-12/1e-13 = 29.999999999999996 in doubles); (c) the same with maxWrites at its
# count-1/count/count+1 (writeInterval 1e-12); (d) rhoRiemannFoam, the sod tube; (e) cellIndentationFoam, the smoke table;
# (f) cellIndentationFoam, holdDeltaT0 1e-3 with holdGrowth 1 (a hold of 1 s: about 1000 steps in that row). Never an
# accepted count refused or a refused one run; the count printed whole.
. "$(dirname "$0")/../lib.sh"
est() { grep -a -o "about [0-9.e+]* time steps\|at least [0-9.e+]* steps\|about [0-9.e+]* steps\|[0-9.e+]* writes" $W/try.log | head -1 | grep -o "[0-9][0-9.e+]*"; }
edge() { local l=$1 f=$2 k=$3; shift 3; cp $f ../edge0; sed -i "/^$k /d" $f; echo "$k 1;" >> $f; tryt 60 "$l: $k 1" "$@"; echo "   msg: $(msg 3 | cut -c1-400)"; local n; n=$(est); rm -rf postProcessing solid [1-9]* .runLock
  [ -z "$n" ] && { echo "   no count found"; cp ../edge0 $f; return; }; n=$(/usr/bin/python3 -c "print(int(float('$n')))")
  for m in $((n-1)) $n $((n+1)); do sed -i "/^$k /d" $f; echo "$k $m;" >> $f; tryt 45 "$l: $k $m (count $n)" "$@"; echo "   sig: $(sig) | $(grep -a -c 'more than\|FATAL' $W/try.log) refusal lines | started: $(grep -a -c '^Time = \|^Step\|^Time =' $W/try.log) step lines | msg: $(msg 2 | cut -c1-300)"; rm -rf postProcessing solid [1-9]* .runLock; done; cp ../edge0 $f; }
blast; short; rm -f .runLock; cp -a . ../b0
edge "(a) preview to 2e-11" system/controlDict maxSteps cellBlastFoam
sete system/controlDict maxDeltaT 1e-13; blastEnd 3e-12 1e-12; edge "(b) 3e-12 in steps of 1e-13" system/controlDict maxSteps cellBlastFoam
edge "(c) writes of 1e-12 to 3e-12" system/controlDict maxWrites cellBlastFoam
cd $W; sod; rm -f .runLock; edge "(d) sod" system/controlDict maxSteps rhoRiemannFoam
cd $W; ind; rm -f .runLock; edge "(e) smoke indentation" system/controlDict maxSteps cellIndentationFoam
sete constant/indenterProperties holdDeltaT0 1e-3; sete constant/indenterProperties holdGrowth 1; grep -a "hold" constant/indenterProperties | head -5 | tr '\n' ' '; echo; edge "(f) hold in steps of 1e-3 s" system/controlDict maxSteps cellIndentationFoam
