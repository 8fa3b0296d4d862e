#!/bin/bash
# chain.sh (adv49a): two streams of one case each (two cases at a time), nice -n 10 and KILL timeouts by the runOne.sh called:
# A: adv48a's queueZ (adv47a's runOne.sh, CASETIMEOUT 480 s unless a case sets its own) -> out/Z, then queue2 -> out/Q2,
#    then queue5 -> out/Q5;
# B: my queueJ (adv47a's runOne.sh) -> out/J, then queueG (adv48b's rows, adv46b's runOne.sh, CASETIMEOUT 900 s) -> out/G,
#    B stops after G; queue5 is A's (see the report for what ran).
# Each line of out/load.log: the time and the load averages, every 60 s while the chain runs.
here=$(cd "$(dirname "$0")" && pwd); cd $here/..; export ADVPREFIX=/tmp/adv49a-
( while [ -e /proc/$$ ]; do echo "$(date +%H:%M:%S) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 60; done ) >> $here/out/load.log 2>&1 &
( cd adv47a && CASETIMEOUT=480 NPAR=1 bash runQueue.sh ../adv48a/queueZ.txt ../../adv49a/out/Z && CASETIMEOUT=480 NPAR=1 bash runQueue.sh ../adv49a/queue2.txt ../../adv49a/out/Q2 && CASETIMEOUT=480 NPAR=1 bash runQueue.sh ../adv49a/queue5.txt ../../adv49a/out/Q5 ) &
( cd adv47a && CASETIMEOUT=480 NPAR=1 bash runQueue.sh ../adv49a/queueJ.txt ../../adv49a/out/J; cd ../adv46b && CASETIMEOUT=900 NPAR=1 bash runQueue.sh ../adv49a/queueG.txt ../../adv49a/out/G ) &
wait
