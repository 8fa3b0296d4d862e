#!/bin/bash
# run1.sh DIR PASS ID... (adv54): adv47a's runOne.sh (called from its folder) for each ID in turn, my prefix
# (ADVPREFIX, default /tmp/adv54-) and out folder; log lines to out/DIR.log (as runQueue.sh's)
here=$(cd "$(dirname "$0")" && pwd); d=$1 p=$2; shift 2; cd $here/../adv47a; export ADVPREFIX=${ADVPREFIX:-/tmp/adv54-} CASETIMEOUT=${CASETIMEOUT:-900}
for i in "$@"; do ./runOne.sh -o ../../adv54/out/$d $p $i >> $here/out/$d.log 2>&1; done
