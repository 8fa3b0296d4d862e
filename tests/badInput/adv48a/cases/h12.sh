#!/bin/bash
# CASETIMEOUT=900
# h12 (class 6, adv47b f55 varied: sweepCase -maxRuns at its edge; sod's maxCo, -run rhoRiemannFoam): 3 values with
# -maxRuns 2 (refused before anything is copied), 2 values with -maxRuns 2 (run), the same value 3 times with -maxRuns 2,
# -maxRuns 0, -1, 1.5, 0x10, 2abc, empty, given twice (2 then 5), 1001 values with the default (refused). Each refusal
# names -maxRuns (or -values), the count and the valid range; 'Nothing was copied'; no Traceback; no run folders left
# after a refusal.
. "$(dirname "$0")/../lib.sh"
sod; O='t=0.007/uniform/time:/value +([0-9.e+-]+);/'
sw() { local l=$1; shift; timeout -s KILL 90 sweepCase -entry system/controlDict/maxCo -run rhoRiemannFoam -output "$O" -name "s$RANDOM" "$@" > $W/try.log 2>&1; local rc=$?
  echo "$l: rc=$rc traceback=$(grep -a -c Traceback $W/try.log) | $(grep -a -m1 -A1 '[Ee]rror\|refused\|more than\|not a\|invalid\|must' $W/try.log | head -2 | tr '\n' ' ' | tr -s ' ' | cut -c1-300)"; echo "   rows: $(grep -a -c '^|' $W/try.log) | folders: $(ls -d $W/*s[0-9]* 2>/dev/null | wc -l)"; }
sw "3 values, -maxRuns 2" -values "0.4 0.5 0.6" -maxRuns 2
sw "2 values, -maxRuns 2" -values "0.4 0.5" -maxRuns 2
sw "0.4 three times, -maxRuns 2" -values "0.4 0.4 0.4" -maxRuns 2
for m in 0 -1 1.5 0x10 2abc ""; do sw "-maxRuns [$m]" -values "0.4 0.5" -maxRuns "$m"; done
sw "-maxRuns 2 then 5, 3 values" -values "0.4 0.5 0.6" -maxRuns 2 -maxRuns 5
v=$(/usr/bin/python3 -c "print(' '.join('%.6g' % (0.1 + 0.8 * i / 1001) for i in range(1001)))"); sw "1001 values, default" -values "$v"
ls $W | tr '\n' ' '; echo
