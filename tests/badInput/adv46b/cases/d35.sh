#!/bin/bash
# d35 (class 4, the preview Allrun -endTime with odd spellings, -noRun, 25 s each): "1e-9 " and " 1e-9" (spaces), "" (empty), "+1e-9", "1E-9", "01e-9" (plain numbers: accepted), Arabic-Indic digits, a unicode minus, "0x1p-30", "1e-9;ls", "1_0e-9", "4.9e-324", "-0": each refused naming -endTime, the value and the range before any step, or accepted only if it is the plain number.
. "$(dirname "$0")/../lib.sh"
for v in "1e-9 " " 1e-9" "" "+1e-9" "1E-9" "01e-9" "١e-٩" "−1e-9" "0x1p-30" "1e-9;ls" "1_0e-9" "4.9e-324" "-0"; do cd $W; rm -rf c; prev
  timeout -s KILL 25 ./Allrun $PREV -endTime "$v" -noRun > $W/try.log 2>&1; rc=$?; echo "[$v]: rc=$rc | $(grep -a -m1 -i "error\|invalid\|refus\|not a\|range" $W/try.log | cut -c1-220) | steps run: $(ls log.* 2>/dev/null | tr "\n" " ")"; done
