#!/bin/bash
# runOne.sh [-o DIR] PASS ID: adv45's runOne.sh for adv46b, with its own out/ folder and base-case prefix (/tmp/adv46b-),
# without setsid: `timeout` (no --foreground) puts itself and the case in a process group of their own, whatever the case
# leaves running is SIGKILLed by that group id after it. Runs tests/badInput/PASS/cases/ID.sh unchanged from its own
# folder (PASS adv46b: this folder), this worktree's build, ADV=${ADVPREFIX:-/tmp/adv46b-}PASS, nice -n 10, a 300 s KILL
# timeout; output tests/badInput/adv46b/out/DIR/PASS_ID.txt
here=$(cd "$(dirname "$0")" && pwd); d=A; [ "$1" = -o ] && { d=$2; shift 2; }
pass=$1 id=$2; OUT=$here/out/$d; mkdir -p $OUT; f=$OUT/${pass}_$id.txt
if [ $pass = adv46b ]; then cd $here; elif [ -d $here/$pass/cases ]; then cd $here/$pass; else cd $here/../$pass || exit 1; fi
start=$(date +%s.%N)
ADV=${ADVPREFIX:-/tmp/adv46b-}$pass nice -n 10 timeout -s KILL ${CASETIMEOUT:-300} bash "cases/$id.sh" > $f 2>&1 < /dev/null & g=$!
wait $g; rc=$?
left=$(pgrep -g $g | tr '\n' ' '); [ -n "$left" ] && { kill -KILL -- -$g 2>/dev/null; echo "[left running after the case, SIGKILLed: $left]" >> $f; }
echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> $f
echo "$(date +%H:%M:%S) $pass $id rc=$rc"
