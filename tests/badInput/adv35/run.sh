#!/bin/bash
# run.sh ID...: runs each case (timeout 300 s), output in out/ID.txt
cd "$(dirname "$0")"
for id in "$@"; do
  start=$(date +%s.%N)
  timeout -s KILL 300 nice -n 10 bash cases/$id.sh > out/$id.txt 2>&1; rc=$?
  echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> out/$id.txt
done
