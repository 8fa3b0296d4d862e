#!/bin/bash
# x77: blast whose 0/T walls are fixedValue from the start ('".*" { type fixedValue; value uniform 300; }'), run to 2 ns; then only the VALUE changed to 320 (the condition itself: the record removes 'value' from what it digests?): restart to 3 ns refused naming 0/T, or continued at 300 K without a word?
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/^\(\s*\)".\*".*/\1".*" { type fixedValue; value uniform 300; }/' 0/T; grep -a '".\*"' 0/T; run 60 cellBlastFoam > log.first 2>&1; tail -1 log.first; fatal log.first 3
latest; blastEnd 3e-9 1e-9; cp 0/T ../T0; sed -i 's/value uniform 300;/value uniform 320;/' 0/T; try "fixedValue 300 -> 320" cellBlastFoam; rm -rf 3e-09
grep -a "fixedValue" 2e-09/T | head -2; grep -a -c "" 2e-09/T
