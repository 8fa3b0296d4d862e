#!/bin/bash
# runQueue.sh QUEUE [DIR]: adv46a's: runs every "PASS ID" line of QUEUE (# comments skipped) with runOne.sh, NPAR (default
# 2) at a time; log in out/DIR.log (each line with the load average at the case's end); a file STOP here stops taking new cases
q=$(realpath "$1"); cd "$(dirname "$0")"; d=${2:-A}; mkdir -p out
grep -v "^#" "$q" | awk 'NF>=2{print $1, $2}' | while read p i; do [ -f STOP ] && break; echo "$p $i"; done | xargs -P ${NPAR:-2} -n 2 ./runOne.sh -o $d >> out/$d.log 2>&1
echo "$(date +%H:%M:%S) queue done" >> out/$d.log
