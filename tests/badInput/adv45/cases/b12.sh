#!/bin/bash
# b12 (class 4, pulseStudyDict odd numbers): overpressure, duration, sampleInterval, strainRateWindow each set to 1e308, 1e-400, -0, a hex number, 4.9e-324 (a denormal), 1e400: each refused before anything runs naming the file, the entry and the valid range; nothing written under postProcessing/pulseStudy?
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict ../dict.orig
for k in overpressure duration sampleInterval strainRateWindow; do for v in 1e308 1e-400 -0 0x1p-29 4.9e-324 1e400; do cp ../dict.orig system/pulseStudyDict
  case $k in overpressure|duration) setStudy $k "($v)";; *) setStudy $k "$v";; esac
  timeout -s KILL 60 pulseStudy -case . > ../log.s 2>&1; echo "$k $v: rc=$? | $(grep -a -m1 -i 'error\|refus\|running' ../log.s | cut -c1-200) | written: $(ls postProcessing/pulseStudy 2>/dev/null | tr '\n' ' ')"; rm -rf postProcessing; done; done
