#!/bin/bash
# i56 (class 4, pulseStudy's entries at the edges of their printed ranges and together): the small study with (a) overpressure
# (1.0000000000000002e9), (b) (0), (c) duration (0), (d) sampleInterval 0.3e-9 with strainRateWindow 1e-9 (not a whole number
# of samples: valid alone, not together), (e) strainRateWindow 0.5e-9 below... = sampleInterval (one sample), (f) duration
# (2e-9 2e-9) (a value twice), (g) overpressure (30e6 3.00000001e7) (two values that print alike at 6 digits): each refused
# before anything runs naming the entry, the value and the range/what does not fit, or (e) (g) accepted with distinct labels;
# nothing written by a refusal. Accepted ones are stopped after 20 s.
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict ../d0
for e in "overpressure (1.0000000000000002e9)" "overpressure (0)" "duration (0)" "sampleInterval 0.3e-9" "strainRateWindow 0.5e-9|sampleInterval 0.5e-9" "duration (2e-9 2e-9)" "overpressure (30e6 3.00000001e7)"; do
  cp ../d0 system/pulseStudyDict; IFS='|' read -ra kv <<< "$e"; for x in "${kv[@]}"; do setStudy ${x%% *} "${x#* }"; done
  tryt 20 "[$e]" pulseStudy; echo "   written: $(ls postProcessing/pulseStudy/points 2>/dev/null | tr '\n' ' ')"; killIn $W/study; sleep 0.5; rm -rf postProcessing; done
