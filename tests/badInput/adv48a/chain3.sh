#!/bin/bash
# chain3.sh (adv48a, after phase 2a): waits for queue5c's end (the second 'queue done' in out/Q5.log), then runs queue3m
# (queue3's cases not reached in phase 1) on the merge b43b25af -> out/Q3m, two at a time, with adv47a's runQueue.sh
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a; mkdir -p $here/out/Q3m
until [ "$(grep -c 'queue done' $here/out/Q5.log)" -ge 2 ]; do sleep 5; done
CASETIMEOUT=480 ADVPREFIX=/tmp/adv48a- NPAR=2 bash runQueue.sh $here/queue3m.txt ../../adv48a/out/Q3m
