#!/bin/bash
# feed.sh QUEUE DIR (adv54, as adv53's feed.sh with my folder): one stream of cases, the lines "PASS ID" of QUEUE taken one
# after the other with adv47a's runOne.sh (called from its folder), QUEUE read again after each case (lines may be
# appended while it runs); ends when QUEUE has no line left and QUEUE.end exists. Log lines in out/DIR.log
here=$(cd "$(dirname "$0")" && pwd); q=$(realpath "$1"); d=$2; cd $here/../adv47a; export ADVPREFIX=${ADVPREFIX:-/tmp/adv54-} CASETIMEOUT=${CASETIMEOUT:-900}
mkdir -p $here/out; ( while [ -e /proc/$$ ]; do echo "$(date +%H:%M:%S) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 60; done ) >> $here/out/load.log 2>&1 &
n=0
while true; do
  line=$(grep -v '^#' "$q" | awk 'NF>=2' | sed -n "$((n+1))p")
  if [ -z "$line" ]; then [ -e "$q.end" ] && break; sleep 10; continue; fi
  n=$((n+1)); set -- $line; ./runOne.sh -o ../../adv54/out/$d $1 $2 >> $here/out/$d.log 2>&1
done
echo "$(date +%H:%M:%S) feed done" >> $here/out/$d.log
