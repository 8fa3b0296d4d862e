#!/bin/bash
# k35 (class 4, pulseStudyDict ranges, integers as reals, units): the one-point study (study): nProcs 0, 2.0, 1e9; sampleInterval 0, 3e-9 (above the 2 ns run), strainRateWindow 0; overpressure (30e6 30e6) (a point twice); duration (1e-300); a threshold's value "0.21 [m]" (a strain in metres) and "0.21 [%]". Expected: each refused before anything runs, naming system/pulseStudyDict, the entry, the value and the valid range/unit; no point folder created.
. "$(dirname "$0")/../lib.sh"
study; F=system/pulseStudyDict; cp $F $W/p0
pst() { tryt 200 "$1" pulseStudy; echo "      folders: $(ls -d points 2>/dev/null) $(ls points 2>/dev/null | head -3 | tr '\n' ' ')"; rm -rf points postProcessing; cp $W/p0 $F; }
for e in "nProcs 0" "nProcs 2.0" "nProcs 1e9" "sampleInterval 0" "sampleInterval 3e-9" "strainRateWindow 0" "overpressure (30e6 30e6)" "duration (1e-300)"; do setStudy ${e%% *} "${e#* }"; pst "$e"; done
sed -i '0,/value *0.21 \[-\];/s//value 0.21 [m];/' $F; pst "threshold value 0.21 [m]"
sed -i '0,/value *0.21 \[-\];/s//value 21 [%];/' $F; pst "threshold value 21 [%]"
