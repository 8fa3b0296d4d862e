#!/bin/bash
# chain4.sh (adv49a): stream B again after chain3.sh's queue5c ended at 02:30: queue5d (the last 17 of queue5.txt's
# first half, after the split of 02:23) -> out/Q5, one case at a time, beside chain.sh's stream A (queueZ's rest, queue2, queue5)
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a; export ADVPREFIX=/tmp/adv49a-
CASETIMEOUT=480 NPAR=1 bash runQueue.sh ../adv49a/queue5d.txt ../../adv49a/out/Q5
