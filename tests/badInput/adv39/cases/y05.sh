#!/bin/bash
# y05: preview Allrun SIGKILLed (whole group) at several moments, each polled (log.cellMesh appears; log.blockMesh appears; log.checkMesh appears; 1e-09 written by the solver; log.cellBlastFoam.status appears), then ./Allrun again unchanged: the re-run ends at 8 ns or refuses naming the step; never exit 0 with the times short
. "$(dirname "$0")/../lib.sh"
for m in "-f log.cellMesh" "-f log.blockMesh" "-f log.checkMesh" "-d 1e-09" "-f log.cellBlastFoam.status"; do prev; setsid ./Allrun $PREV -endTime 8e-9 > ../log.a1 2>&1 & p=$!; waitFor 60 test $m; kill -KILL -- -$p 2>/dev/null || echo "  (the Allrun had ended before the kill)"; wait $p 2>/dev/null; sleep 0.3
  echo "kill at [$m]: logs $(ls log.* 2>/dev/null | tr '\n' ' '); times $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; run 200 ./Allrun $PREV -endTime 8e-9 > ../log.a2 2>&1; echo "  re-run ($(tail -1 ../log.a2)):"; grep -a -v "^ *$" ../log.a2 | grep -a -i "error\|refus\|stopped\|again\|Running\|stale" | cut -c1-300 | sed 's/^/    /'; echo "  times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"
  cd $W; rm -rf $W/c; done
