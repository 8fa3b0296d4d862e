#!/bin/bash
# chain2.sh: chain.sh resumed at 19:43 after I stopped it (its pid, then runQueue's and xargs's; the two cases running,
# adv45 b06 and b08, finished on their own) to run item 1's later variants first: queue1c (f11, f10, f09, adv46b d77 the
# second time, f03 with its own 900 s) -> out/Q1c, then queue2b (queue2 after adv45 b08) -> out/Q2, then queue3 (adv46a
# queueN's 114 not reached), queue4 (queueA44), queue5 (queueS) -> out/Q3, Q4, Q5, NPAR=2 each
cd "$(dirname "$0")"
while pgrep -f "runOne.sh -o Q2 adv45 b0[68]" > /dev/null; do sleep 5; done
for q in 1c 2b 3 4 5; do d=Q$q; [ $q = 2b ] && d=Q2; NPAR=2 bash runQueue.sh queue$q.txt $d; done
