#!/bin/bash
# b14 (class 4, pulseStudy nProcs odd values): nProcs 1.5, 0x1, 1e308, -0, 4.9e-324, 1e-400, 1.0, "$n" (a macro, n 1): each refused naming nProcs and its range [1, the grid's points] before anything runs, or (1.0, $n: a whole number 1) run; never a crash, a traceback or a hang?
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict ../dict.orig
for v in 1.5 0x1 1e308 -0 4.9e-324 1e-400 1.0 '$n'; do cp ../dict.orig system/pulseStudyDict; setStudy nProcs "$v"; [ "$v" = '$n' ] && sed -i 's/^nProcs /n 1;\nnProcs /' system/pulseStudyDict
  timeout -s KILL 150 pulseStudy -case . > ../log.s 2>&1; echo "nProcs $v: rc=$? | $(grep -a -m1 -i 'error\|refus\|done\|Traceback' ../log.s | cut -c1-220)"; rm -rf postProcessing; done
