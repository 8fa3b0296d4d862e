#!/bin/bash
# runnew.sh [-o DIR] ID...: each case (ADV default /tmp/adv39a: the base cases) under nice -n 10 and a 300 s KILL timeout, output in out/DIR/ID.txt (DIR: new)
cd "$(dirname "$0")"; d=new; [ "$1" = -o ] && { d=$2; shift 2; }; OUT=$PWD/out/$d; mkdir -p $OUT
for id in "$@"; do
  start=$(date +%s.%N)
  ADV=${ADV:-/tmp/adv39a} timeout -s KILL 300 nice -n 10 bash cases/$id.sh > $OUT/$id.txt 2>&1; rc=$?
  echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> $OUT/$id.txt
done
