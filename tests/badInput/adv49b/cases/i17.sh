#!/bin/bash
# i17 (class 4, the preview Allrun's newest options): -solidSubcycles 0, 1001, 2.5, 1e9, 4294967297, -1; -predictor
# Extrapolated, none, '' ; -motionDistance 0, -5e-6, nan, 1e-301, 4294967297 (a length: accepted?), 5e-6x; each refused
# before anything is done, naming the option, the value and its range/valid values, exit non-zero, the folder unchanged.
. "$(dirname "$0")/../lib.sh"
prev; sums > ../s0
for a in "-solidSubcycles 0" "-solidSubcycles 1001" "-solidSubcycles 2.5" "-solidSubcycles 1e9" "-solidSubcycles 4294967297" "-solidSubcycles -1" \
         "-predictor Extrapolated" "-predictor none" "-predictor ''" "-motionDistance 0" "-motionDistance -5e-6" "-motionDistance nan" "-motionDistance 1e-301" "-motionDistance 5e-6x"; do
  eval "tryt 120 \"Allrun $a\" ./Allrun $PREV -noRun $a"; echo "   changed: $(changed ../s0)"; [ -n "$(changed ../s0 | tr -d ' ')" ] && { ./Allclean > /dev/null 2>&1; sums > ../s0; }; done
