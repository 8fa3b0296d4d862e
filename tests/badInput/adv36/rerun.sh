#!/bin/bash
OUT=$(cd "$(dirname "$0")" && pwd)/out; cd "$(dirname "$0")/../adv35"
for id in "$@"; do
  start=$(date +%s.%N)
  ADV=${ADV:-/tmp/adv36x} timeout -s KILL 300 nice -n 10 bash cases/$id.sh > $OUT/rerun/$id.txt 2>&1; rc=$?
  echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> $OUT/rerun/$id.txt
done
