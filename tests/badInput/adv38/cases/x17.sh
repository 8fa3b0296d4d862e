#!/bin/bash
# x17: two -overwrite runs in a row, both SIGKILLed before their first write (the first run A's results moved aside by the first, then the second over that state): are A's results still all there and restored by the loop the restart message prints?
. "$(dirname "$0")/../lib.sh"
blastDone; contents > ../cA; sed -i 's/^maxCo .*/maxCo 0.05;/' system/controlDict; blastEnd 2e-8 1e-8
for k in 1 2; do cellBlastFoam -overwrite > log.o$k 2>&1 & p=$!; waitFor 30 bash -c 'find . -name ".*overwritten" | grep -q .'; sleep 0.5; kill -KILL $p; wait $p 2>/dev/null; echo "kill $k: aside $(find . -name '.*overwritten*' | wc -l): $(find . -name '.*overwritten*' | tr '\n' ' ' | cut -c1-300)"; done
sed -i 's/^maxCo .*/maxCo 0.5;/' system/controlDict; blastEnd 2e-9 1e-9; latest
run 60 cellBlastFoam > log.r 2>&1; fatal log.r 25 | grep -a "find\|overwritten\|mv\|FATAL" | head -6
loop=$(grep -a -o "find \. -depth.*done;" log.r | head -1); echo "loop: $loop"; [ -n "$loop" ] && bash -c "$loop"
echo "lost of A: $(lost ../cA | wc -l)"; run 60 cellBlastFoam > log.r2 2>&1; tail -1 log.r2; fatal log.r2 3
