#!/bin/bash
# chainR.sh: after phase 1's queues (P1's two runners, then A3) queueA4 (a33, a36), then the rest of the earlier cases (queueR.txt) by two runRest.sh runners
cd "$(dirname "$0")"
while pgrep -f "runRest.sh queueP1.txt" > /dev/null || pgrep -f "runQueue.sh queueA3.txt" > /dev/null || ! grep -q "queue done" out/A3.log 2>/dev/null; do sleep 3; done
NPAR=2 ./runQueue.sh queueA4.txt A4; ./runRest.sh queueR.txt R & ./runRest.sh queueR.txt R -r & wait
