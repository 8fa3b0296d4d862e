#!/bin/bash
# chain.sh (adv48a phase 1): waits for the running queue1b (its 'queue done' line in out/P1.log), then runs with
# adv47a's runQueue.sh (called, not copied; prefix /tmp/adv48a-, outputs here): queue1c -> out/P1, queue3 -> out/Q3,
# queue4 -> out/Q4, queue5 -> out/Q5; two cases at a time, CASETIMEOUT 480 s unless a case sets its own
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a
until [ "$(grep -c 'queue done' $here/out/P1.log)" -ge 2 ]; do sleep 5; done
export CASETIMEOUT=480 ADVPREFIX=/tmp/adv48a- NPAR=2
for q in queue1c:P1 queue3:Q3 queue4:Q4 queue5:Q5; do mkdir -p $here/out/${q#*:}; bash runQueue.sh $here/${q%%:*}.txt ../../adv48a/out/${q#*:}; done
