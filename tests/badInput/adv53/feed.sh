#!/bin/bash
# feed.sh QUEUE DIR: one stream of cases, the lines "PASS ID" of QUEUE taken one after the other with adv47a's runOne.sh
# (called from its folder), QUEUE read again after each case (lines may be appended while it runs); ends when QUEUE has
# no line left and the file QUEUE.end exists (checked every 10 s). Log lines in out/DIR.log
here=$(cd "$(dirname "$0")" && pwd); q=$(realpath "$1"); d=$2; cd $here/../adv47a; export ADVPREFIX=${ADVPREFIX:-/tmp/adv53-} CASETIMEOUT=${CASETIMEOUT:-900}
n=0
while true; do
  line=$(grep -v '^#' "$q" | awk 'NF>=2' | sed -n "$((n+1))p")
  if [ -z "$line" ]; then [ -e "$q.end" ] && break; sleep 10; continue; fi
  n=$((n+1)); set -- $line; ./runOne.sh -o ../../adv53/out/$d $1 $2 >> $here/out/$d.log 2>&1
done
echo "$(date +%H:%M:%S) feed done" >> $here/out/$d.log
