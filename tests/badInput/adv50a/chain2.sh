#!/bin/bash
# chain2.sh (adv50a, 05:53): once one of the two running cases (pids given) ends, queueE -> out/E (one at a time:
# two cases at a time with the other); out/load.log every 60 s until queueE is done
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a; export ADVPREFIX=/tmp/adv50a- CASETIMEOUT=900
( while [ -e /proc/$$ ]; do echo "$(date +%H:%M:%S) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 60; done ) >> $here/out/load.log 2>&1 &
while [ -e /proc/$1 ] && [ -e /proc/$2 ]; do sleep 5; done
NPAR=1 bash runQueue.sh $here/queueE.txt ../../adv50a/out/E
