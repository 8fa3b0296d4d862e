#!/bin/bash
# runRest.sh QUEUE DIR [-r]: runs, one at a time, every "PASS ID" line of QUEUE (-r: from its end) whose output
# out/DIR/PASS_ID.txt does not exist yet (runOne.sh creates it when the case starts): a second runner beside a running
# runQueue.sh of the same queue (two at a time in all); log in out/DIR.log
q=$(realpath "$1"); cd "$(dirname "$0")"; d=$2; mkdir -p out
grep -v "^#" "$q" | awk 'NF>=2{print $1, $2}' | { [ "$3" = -r ] && tac || cat; } | while read p i; do
  [ -e out/$d/${p}_$i.txt ] && continue; ./runOne.sh -o $d $p $i >> out/$d.log 2>&1; done
echo "$(date +%H:%M:%S) runRest $3 done" >> out/$d.log
