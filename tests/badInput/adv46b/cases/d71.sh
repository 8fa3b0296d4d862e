#!/bin/bash
# d71 (class 4, the preview Allrun options in other styles, -noRun, 25 s each): -endTime=2e-9, --endTime 2e-9, -endtime 2e-9, a stray word (extra), -noPlots yes (a flag with a value), -endTime given as the last word without a value: each refused naming the option (the closest valid one) before any step.
. "$(dirname "$0")/../lib.sh"
for o in "-endTime=2e-9" "--endTime 2e-9" "-endtime 2e-9" "extra" "-noPlots yes" "-endTime"; do cd $W; rm -rf c; prev
  timeout -s KILL 25 ./Allrun $PREV $o -noRun > $W/try.log 2>&1; rc=$?; [ "$o" = "-endTime" ] && { rm -rf $W/c; prev; timeout -s KILL 25 ./Allrun $PREV -noRun -endTime > $W/try.log 2>&1; rc=$?; }
  echo "[$o]: rc=$rc | $(grep -a -m1 -i "error\|invalid\|refus\|unknown\|not a\|range" $W/try.log | cut -c1-220) | steps run: $(ls log.* 2>/dev/null | tr "\n" " ")"; done
