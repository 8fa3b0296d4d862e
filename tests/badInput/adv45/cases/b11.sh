#!/bin/bash
# b11 (class 4+1, pulseStudy: one grid value written two ways): overpressure (30e6 3e7); duration (2e-9 2.0e-9); overpressure (30e6 30000000.000000001) (equal as doubles): each refused as a value given twice, naming the entry, before anything runs; never two points of one pulse?
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict ../dict.orig
for e in "overpressure (30e6 3e7)" "duration (2e-9 2.0e-9)" "overpressure (30e6 30000000.000000001)"; do cp ../dict.orig system/pulseStudyDict; setStudy ${e%% *} "${e#* }"
  timeout -s KILL 100 pulseStudy -case . > ../log.s 2>&1; echo "[$e]: rc=$? | $(grep -a -m2 -i 'error\|twice\|refus\|running\|done' ../log.s | cut -c1-220 | tr '\n' '|')"; echo "   points: $(ls postProcessing/pulseStudy/points 2>/dev/null | tr '\n' ' ')"; rm -rf postProcessing; done
