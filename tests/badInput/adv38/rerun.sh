#!/bin/bash
# rerun.sh [-o DIR] SET:ID...: reproducers of earlier passes (SET adv36 or adv37: tests/badInput/SET/cases/ID.sh) with this
# worktree's build, each under nice -n 10 and a 300 s KILL timeout; output in out/DIR/SET_ID.txt (DIR: p2). ADV (default
# /tmp/adv38p2) holds the base cases they build (remove it to rebuild them with another build).
d=p2; [ "$1" = -o ] && { d=$2; shift 2; }
here=$(cd "$(dirname "$0")" && pwd); OUT=$here/out/$d; mkdir -p $OUT
for k in "$@"; do
  set=${k%%:*}; id=${k#*:}; start=$(date +%s.%N)
  (cd $here/../$set && ADV=${ADV:-/tmp/adv38p2} timeout -s KILL 300 nice -n 10 bash cases/$id.sh) > $OUT/${set}_$id.txt 2>&1; rc=$?
  echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> $OUT/${set}_$id.txt
done
