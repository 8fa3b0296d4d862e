#!/bin/bash
# CASETIMEOUT=600
# n27 (new, class 2/5: an interrupted -overwrite over digested results, then the advice followed - the put-back of the
# moved-aside files must bring back their sidecars too): idn (finished); `cellIndentationFoam -overwrite` with 10x finer
# steps SIGKILLed at 0.3, 1.5 s (before and after its first checkpoint); the case's files then (aside .*.overwritten);
# the run again as its messages advise (plain, then -overwrite); plotIndentation.py at each stage. Expected: the earlier
# results (force.dat, peaks.dat and their sidecars) restored whole and measured, or the new ones whole; never a force.dat
# of one run with the other's sidecar measured or refused as "edited by hand" (UNCLEAR), nor the earlier results lost.
. "$(dirname "$0")/../lib.sh"
idn; cp -a . $W/i0; d=postProcessing/indentation; md5sum $d/* > $W/m0
for s in 0.3 1.5; do cd $W; rm -rf ind; cp -a i0 ind; cd ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
  cellIndentationFoam -overwrite > log.ow 2>&1 & p=$!; sleep $s; kill -KILL $p; wait $p 2>/dev/null
  echo "   killed at $s s: aside $(find . -name '*.overwritten*' | tr '\n' ' ' | cut -c1-250) | $d: $(ls $d 2>/dev/null | tr '\n' ' ')"
  pi; echo "   plot after the kill: $(pk) | said: $(say 1 | cut -c1-200)"
  rm -f .runLock; tryt 400 "(a) the run again, no option" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"
  echo "   earlier results: $(md5sum -c $W/m0 2>/dev/null | grep -c ': OK$') of $(wc -l < $W/m0) back | aside now: $(find . -name '*.overwritten*' | wc -l)"
  pi; echo "   plot: $(pk) | said: $(say 1 | cut -c1-200)"
  rm -f .runLock; tryt 400 "(b) -overwrite again to the end" cellIndentationFoam -overwrite; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"; pi; echo "   plot: $(pk) | said: $(say 1 | cut -c1-200)"; ok_ $d/force.dat; done
