#!/bin/bash
# chain1.sh: phase 1's queues one after another, each NPAR=2: queueB (adv45's b01-b48, c01-c05), queueN (ever non-OK,
# adv35-adv45), queueA44 (adv44's other a-cases), queueS (a sample of adv35-adv43's other cases); a file STOP here stops
# the chain between queues
cd "$(dirname "$0")"
for q in B N A44 S; do [ -f STOP ] && break; NPAR=2 bash runQueue.sh queue$q.txt $q; done
