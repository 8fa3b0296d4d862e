#!/bin/bash
# chainZ.sh: phase 2 on the merge of fix19d (1f172fc8 on branch adv47a; fix19d 22a6f4f6, Python only: no rebuild, the
# Python tools run from the source tree): queueZ -> out/Z, then phase 1's queues not reached, on the same merge:
# queue3 (adv46a queueN's 114: adv40 z03 on) -> out/Q3, queue4 -> out/Q4, queue5 -> out/Q5; NPAR=2 each
cd "$(dirname "$0")"
for q in Z 3 4 5; do NPAR=2 bash runQueue.sh queue$q.txt $( [ $q = Z ] && echo Z || echo Q$q ); done
