#!/bin/bash
# chain2.sh (adv48a phase 1; chain.sh stopped at 22:59 while queue1c's last case h09 ran, to use the idle slot): two
# streams of one case each, with adv47a's runQueue.sh (called, not copied; prefix /tmp/adv48a-): A: queue3 -> out/Q3,
# then queue5a (queue5's odd lines) -> out/Q5; B: after queue1c ends (its 'queue done' in out/P1.log), queue4 -> out/Q4,
# then queue5b (queue5's even lines) -> out/Q5. CASETIMEOUT 480 s unless a case sets its own
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a; mkdir -p $here/out/Q3 $here/out/Q4 $here/out/Q5
export CASETIMEOUT=480 ADVPREFIX=/tmp/adv48a- NPAR=1
( bash runQueue.sh $here/queue3.txt ../../adv48a/out/Q3; bash runQueue.sh $here/queue5a.txt ../../adv48a/out/Q5 ) &
until [ "$(grep -c 'queue done' $here/out/P1.log)" -ge 3 ]; do sleep 5; done
bash runQueue.sh $here/queue4.txt ../../adv48a/out/Q4; bash runQueue.sh $here/queue5b.txt ../../adv48a/out/Q5
wait
