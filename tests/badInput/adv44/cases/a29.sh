#!/bin/bash
# a29 (class 3+5, a run lock left damaged by a power loss): a blast case (planeWaveInflow top, iblast) whose .runLock is (a) NUL bytes of a real lock's size, (b) empty, (c) cut in its middle (the first line only); cellBlastFoam, then planeWave -inflow, then sweepCase: each refused saying what the lock is and what to do (not taken over), the same way by the C++ and the Python tools?
. "$(dirname "$0")/../lib.sh"
iblast; iEnd 1e-9; cellBlastFoam > log.r 2>&1 & p=$!; waitFor 60 test -s .runLock; cp .runLock ../lock.real; kill -KILL $p; wait $p 2>/dev/null; rm -rf 1e-09 solid postProcessing .runLock; echo "   a real lock: $(wc -c < ../lock.real) bytes, $(wc -l < ../lock.real) lines"
for k in nul empty cut; do case $k in nul) head -c $(wc -c < ../lock.real) /dev/zero > .runLock;; empty) : > .runLock;; cut) head -1 ../lock.real > .runLock;; esac
  tryf "($k) cellBlastFoam" cellBlastFoam; tryf "($k) planeWave -inflow" planeWave $IW; tryf "($k) sweepCase" sweepCase -case . -entry constant/fsiProperties/coupling/solidSubcycles -values "2" -run cellBlastFoam -output "x=log.cellBlastFoam:/End(.*)/"
  echo "   lock still there: $(test -e .runLock && echo yes || echo no); results: $(ls -d [1-9]* solid 2>/dev/null | tr '\n' ' ')"; rm -rf .runLock [1-9]* solid postProcessing; done
