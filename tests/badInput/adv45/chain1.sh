#!/bin/bash
# chain1.sh: phase 1's queues one after another (each NPAR=2): queueB (new cases) must be done, then queueN (ever-non-OK),
# queueA44 (adv44's other cases), queue35 (adv35's other cases)
cd "$(dirname "$0")"; until grep -q 'queue done' out/B.log 2>/dev/null; do sleep 10; done
for q in N A44 35; do [ -f STOP ] && break; NPAR=2 bash runQueue.sh queue$q.txt $q; done
