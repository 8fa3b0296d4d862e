#!/bin/bash
# chain.sh (adv50a): two streams of one case each (two cases at a time), adv47a's runOne.sh/runQueue.sh called with my out
# folder and base prefix (nice -n 10 and the KILL timeout are runOne.sh's; CASETIMEOUT 900 s unless a case sets its own):
# stream 1: queueK (my variants) -> out/K, then queueB -> out/B; stream 2: queueA -> out/A, then queueC -> out/C.
# out/load.log: the time and the load averages every 60 s while the chain runs. A file tests/badInput/adv47a/STOP would
# stop the queues taking new cases (adv47a's runQueue.sh): not used by me (it is adv47a's folder), I stop by pid.
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a; export ADVPREFIX=/tmp/adv50a- CASETIMEOUT=900; mkdir -p $here/out
( while [ -e /proc/$$ ]; do echo "$(date +%H:%M:%S) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 60; done ) >> $here/out/load.log 2>&1 &
( NPAR=1 bash runQueue.sh $here/queueK.txt ../../adv50a/out/K; NPAR=1 bash runQueue.sh $here/queueB.txt ../../adv50a/out/B ) &
( NPAR=1 bash runQueue.sh $here/queueA.txt ../../adv50a/out/A; NPAR=1 bash runQueue.sh $here/queueC.txt ../../adv50a/out/C ) &
wait
