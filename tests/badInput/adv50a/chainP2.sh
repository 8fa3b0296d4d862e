#!/bin/bash
# chainP2.sh (adv50a phase 2, on the merge of fix19g): two streams of one case each: queueP2a -> out/P2a, queueP2b ->
# out/P2b (adv47a's runOne.sh/runQueue.sh with my out folder and prefix); out/load.log every 60 s
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a; export ADVPREFIX=/tmp/adv50a- CASETIMEOUT=900; mkdir -p $here/out
( while [ -e /proc/$$ ]; do echo "$(date +%H:%M:%S) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 60; done ) >> $here/out/load.log 2>&1 &
NPAR=1 bash runQueue.sh $here/queueP2a.txt ../../adv50a/out/P2a &
NPAR=1 bash runQueue.sh $here/queueP2b.txt ../../adv50a/out/P2b &
wait
