#!/bin/bash
# chain2.sh (adv49a): stream B again after chain.sh's B (queueJ, queueG) ended at 02:01: j09 (adv47a's runOne.sh) -> out/J,
# then queue5b (the second half of item 3) -> out/Q5; one case at a time, beside chain.sh's stream A
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a; export ADVPREFIX=/tmp/adv49a-
CASETIMEOUT=480 ./runOne.sh -o ../../adv49a/out/J adv49a j09 >> ../adv49a/out/J.log 2>&1
CASETIMEOUT=480 NPAR=1 bash runQueue.sh ../adv49a/queue5b.txt ../../adv49a/out/Q5
