#!/bin/bash
# chain.sh: phase 1's queues one after another (NPAR=2 each): queue1 (the lead's fixes: adv46a e01, adv46b d40, d65, d67,
# d77 and my variants f01-f06) -> out/Q1, queue1b (d77 a second time) -> out/Q1b, queue2 (adv46b d01-d76 but those of
# queue1, then adv46a's queueB: adv45 b01-b48, c01-c05) -> out/Q2, queue3 (adv46a queueN's 114 not reached: adv40 z03 on)
# -> out/Q3, queue4 (adv46a queueA44) -> out/Q4, queue5 (adv46a queueS) -> out/Q5; a file STOP here stops taking cases
cd "$(dirname "$0")"
for q in 1 1b 2 3 4 5; do [ -f STOP ] && break; NPAR=2 bash runQueue.sh queue$q.txt Q$q; done
