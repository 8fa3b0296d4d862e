#!/bin/bash
# chain2.sh QUEUE DIR (phase 2): chain.sh with the base prefix from the environment (ADVPREFIX, default /tmp/adv51b-: the
# bases rebuilt on the merge of fix19h, whose Allrun drops the water probes above -Z; the phase-1 bases keep two probes
# outside the 20 um column, which the merged solver refuses at the start, so every restart of them was n/r)
here=$(cd "$(dirname "$0")" && pwd); cd $here/../adv47a; export ADVPREFIX=${ADVPREFIX:-/tmp/adv51b-} CASETIMEOUT=900; mkdir -p $here/out
( while [ -e /proc/$$ ]; do echo "$(date +%H:%M:%S) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 60; done ) >> $here/out/load.log 2>&1 &
NPAR=${NPAR:-2} bash runQueue.sh $here/$1 ../../adv51/out/$2
