#!/bin/bash
# run1.sh DIR PASS ID...: adv47a's runOne.sh (called from its folder) for each ID in turn, my prefix and out folder;
# log lines to out/DIR.log (as runQueue.sh's)
here=$(cd "$(dirname "$0")" && pwd); d=$1 p=$2; shift 2; cd $here/../adv47a; export ADVPREFIX=${ADVPREFIX:-/tmp/adv53-} CASETIMEOUT=${CASETIMEOUT:-900}
for i in "$@"; do ./runOne.sh -o ../../adv53/out/$d $p $i >> $here/out/$d.log 2>&1; done
