#!/bin/bash
# y05: preview Allrun SIGKILLed (whole group) at several moments (after 0.3 s, 1.5 s, 4 s from the start), then ./Allrun again unchanged each time: the re-run ends at 8 ns or refuses naming the step; never exit 0 with the times short
. "$(dirname "$0")/../lib.sh"
for s in 0.3 1.5 4; do prev; setsid ./Allrun $PREV -endTime 8e-9 > ../log.a1 2>&1 & p=$!; sleep $s; kill -KILL -- -$p; wait $p 2>/dev/null; sleep 0.3
  echo "kill at $s s: logs $(ls log.* 2>/dev/null | tr '\n' ' ')"; run 200 ./Allrun $PREV -endTime 8e-9 > ../log.a2 2>&1; echo "  re-run: $(grep -a -i "already\|error\|refus\|stopped\|again" ../log.a2 | head -2 | cut -c1-200 | tr '\n' '|') times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"
  cd $W; rm -rf $W/c; done
