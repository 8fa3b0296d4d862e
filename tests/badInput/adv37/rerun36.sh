#!/bin/bash
# rerun36.sh [-o DIR] ID...: adv36's reproducers (tests/badInput/adv36/cases/ID.sh) with this worktree's build, each under
# nice -n 10 and a 300 s KILL timeout; output in out/DIR/adv36_ID.txt (DIR: p2). ADV (default /tmp/adv37p2) holds the
# base cases they build (remove it to rebuild them with another build).
d=p2; [ "$1" = -o ] && { d=$2; shift 2; }
OUT=$(cd "$(dirname "$0")" && pwd)/out/$d; mkdir -p $OUT; cd "$(dirname "$0")/../adv36"
for id in "$@"; do
  start=$(date +%s.%N)
  ADV=${ADV:-/tmp/adv37p2} timeout -s KILL 300 nice -n 10 bash cases/$id.sh > $OUT/adv36_$id.txt 2>&1; rc=$?
  echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> $OUT/adv36_$id.txt
done
