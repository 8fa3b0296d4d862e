#!/bin/bash
# g27 (class 4, pulseStudyDict): a one-point study; sampleInterval, strainRateWindow, overpressure, duration and a threshold's value set in turn to nan, inf, -1, 1e400 or given twice; ./Allrun: refused naming the entry and range before any point runs (a point that starts: killed at 12 s and reported)?
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict $W/sd.orig
for k in sampleInterval strainRateWindow overpressure duration value; do for v in nan inf -1 1e400 DUP; do cp $W/sd.orig system/pulseStudyDict
  case $k in overpressure|duration) [ $v = DUP ] && { dupe system/pulseStudyDict $k; true; } || sete system/pulseStudyDict $k "($v)";; *) [ $v = DUP ] && dupe system/pulseStudyDict $k || sete system/pulseStudyDict $k $v;; esac
  setsid ./Allrun > $W/st.log 2>&1 & p=$!; waitFor 12 bash -c "! kill -0 $p"; kill -KILL -- -$p 2>/dev/null; wait $p; rc=$?; echo "$k $v: rc $rc | $(grep -a -m1 -A1 -i 'error\|refus' $W/st.log | tr '\n' ' ' | cut -c1-240) $([ -d postProcessing/pulseStudy/points ] && echo "[a point started: $(ls postProcessing/pulseStudy/points | tr '\n' ' ')]")"
  rm -rf postProcessing log.pulseStudy; done; done
cp $W/sd.orig system/pulseStudyDict
