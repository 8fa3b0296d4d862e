#!/bin/bash
# d50 (class 5, constant/inflowWave cut: the prepared -inflow preview (iblast) with its last 3 lines removed, then with one byte of its header comment changed): (a) refused naming the file (rows digest, or an incomplete file); (b) a comment edit accepted or refused clearly.
. "$(dirname "$0")/../lib.sh"
iblast; ls constant; cp constant/inflowWave ../iw; head -n -3 ../iw > constant/inflowWave; tryt 60 "(a) inflowWave last 3 lines cut" cellBlastFoam; rm -rf [1-9]* solid postProcessing
cp ../iw constant/inflowWave; sed -i "0,/^\/\//s//\/\/X/" constant/inflowWave; tryt 60 "(b) a comment changed" cellBlastFoam; ls -d [1-9]* 2>/dev/null | tr "\n" " "
