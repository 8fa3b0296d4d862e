#!/bin/bash
# chain.sh QUEUE DIR (adv53): adv47a's runQueue.sh (called, not copied) with my out folder and prefix (ADVPREFIX,
# default /tmp/adv53-), NPAR (default 2), CASETIMEOUT 900; out/load.log every 60 s while it runs
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a; export ADVPREFIX=${ADVPREFIX:-/tmp/adv53-} CASETIMEOUT=900; mkdir -p $here/out
( while [ -e /proc/$$ ]; do echo "$(date +%H:%M:%S) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 60; done ) >> $here/out/load.log 2>&1 &
NPAR=${NPAR:-2} bash runQueue.sh $here/$1 ../../adv53/out/$2
