#!/bin/bash
# chain3.sh (adv49a): stream B again after chain2.sh's queue5b ended at 02:20: queue5c (the last 32 of queue5.txt's first
# half) -> out/Q5, one case at a time, beside chain.sh's stream A (queueZ's rest, queue2, queue5)
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a; export ADVPREFIX=/tmp/adv49a-
CASETIMEOUT=480 NPAR=1 bash runQueue.sh ../adv49a/queue5c.txt ../../adv49a/out/Q5
