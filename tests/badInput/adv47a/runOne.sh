#!/bin/bash
# runOne.sh [-o DIR] PASS ID: adv46b's runOne.sh (adv45's without setsid) for adv47a, plus adv46a's bin/ first in PATH (its
# perl setsid stands in for setsid(1) inside the earlier cases: a process group of its own, the same session). Runs
# tests/badInput/PASS/cases/ID.sh unchanged from its own folder tests/badInput/PASS (PASS adv47a: this folder), this
# worktree's build, ADV=${ADVPREFIX:-/tmp/adv47a-}PASS (base cases), nice -n 10, a ${CASETIMEOUT:-300} s KILL timeout:
# `timeout` (no --foreground) puts itself and the case in a process group of their own, whatever the case leaves running
# in it is SIGKILLed by that group id after it. Output tests/badInput/adv47a/out/DIR/PASS_ID.txt; one log line per case
# with the 1-minute load average at its end. A case's line "# CASETIMEOUT=N" sets its own timeout (f03: the 3D quarter's mesh).
here=$(cd "$(dirname "$0")" && pwd); d=A; [ "$1" = -o ] && { d=$2; shift 2; }
pass=$1 id=$2; OUT=$here/out/$d; mkdir -p $OUT; f=$OUT/${pass}_$id.txt
cd $here/../$pass || exit 1
ct=$(grep -m1 -o "^# CASETIMEOUT=[0-9]*" cases/$id.sh 2>/dev/null | cut -d= -f2); CASETIMEOUT=${ct:-${CASETIMEOUT:-300}}   # a case may ask for more
start=$(date +%s.%N)
PATH=$here/../adv46a/bin:$PATH ADV=${ADVPREFIX:-/tmp/adv47a-}$pass nice -n 10 timeout -s KILL ${CASETIMEOUT:-300} bash "cases/$id.sh" > $f 2>&1 < /dev/null & g=$!
wait $g; rc=$?
left=$(pgrep -g $g | tr '\n' ' '); [ -n "$left" ] && { kill -KILL -- -$g 2>/dev/null; echo "[left running after the case, SIGKILLed: $left]" >> $f; }
echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> $f
echo "$(date +%H:%M:%S) $pass $id rc=$rc load=$(cut -d' ' -f1 /proc/loadavg)"
