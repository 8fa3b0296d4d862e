#!/bin/bash
# x21: blast 0/T: an explicit 'top { type zeroGradient; }' beside the ".*" pattern (OpenFOAM: a name beats a pattern) accepted; the pattern "(top|bottom)" given twice refused; a "(top|bottom)" pattern and a "(bottom|outer)" pattern overlapping on bottom (two different conditions: OpenFOAM takes the last pattern) ?
. "$(dirname "$0")/../lib.sh"
blast; cp 0/T ../T0
sed -i 's/^\(\s*\)".\*".*/&\n    top { type zeroGradient; }/' 0/T; try "explicit top beside .*" cellBlastFoam; rm -rf [1-9]* solid postProcessing; cp ../T0 0/T
sed -i 's/^\(\s*\)".\*".*/&\n    "(top|bottom)" { type zeroGradient; }\n    "(top|bottom)" { type fixedValue; value uniform 300; }/' 0/T; try "(top|bottom) twice" cellBlastFoam; rm -rf [1-9]* solid postProcessing; cp ../T0 0/T
sed -i 's/^\(\s*\)".\*".*/&\n    "(top|bottom)" { type zeroGradient; }\n    "(bottom|outer)" { type fixedValue; value uniform 310; }/' 0/T; try "overlapping patterns" cellBlastFoam; grep -a -A4 "^    bottom" 1e-09/T 2>/dev/null | tr -s ' \n' ' ' | cut -c1-120; echo
