#!/bin/bash
# a23 (class 4+6, pulseStudy whose baseCase CONTAINS the study): (a) baseCase "." (the study's own case), (b) baseCase ".." (its parent folder, holding the study) : the study copies the base case into its own postProcessing/pulseStudy/base: refused naming the entry, or a copy of itself into itself (recursion, a traceback, a disk filled)? Sizes of what is left.
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict ../d.orig
for b in '"."' '".."' "\"$W/study/system/..\""; do cp ../d.orig system/pulseStudyDict; sed -i "s|^baseCase .*|baseCase        $b;|" system/pulseStudyDict
  timeout -s KILL 60 ./Allrun > ../log.s 2>&1; rc=$?; echo "baseCase $b: rc=$rc | $(grep -a -m2 -i 'error\|Traceback' ../log.s | cut -c1-300 | tr '\n' ' ')"; echo "   left: $(du -s -k $W | cut -f1) kB in \$W; deepest: $(find $W -type d | awk '{print length($0)}' | sort -n | tail -1) chars; postProcessing/pulseStudy: $(ls postProcessing/pulseStudy 2>/dev/null | tr '\n' ' ')"; rm -rf postProcessing; done
