#!/bin/bash
# d46 (class 5, junk after the committed bytes of a log: the finished preview with a line "9e-09 1 2 3" appended to postProcessing/fsi/0/coupling.dat, and a partial line appended to solidProbes.dat, then a restart): refused naming the file, or the junk cut (the joined series without the 9e-09 row); SILENT if the series holds it after the restart.
. "$(dirname "$0")/../lib.sh"
bd; rs; ls postProcessing postProcessing/*/0 | tr "\n" " "; echo; f=$(ls postProcessing/fsi/0/coupling.dat 2>/dev/null); echo "9e-09 1 2 3" >> $f; printf "2.5e-09 7" >> $(ls postProcessing/solidProbes/0/*.dat | head -1)
tryt 240 "restart with junk after the logs" cellBlastFoam; cont; after; echo "   9e-09 row: $(grep -rl "^9e-09 1 2 3" postProcessing | tr "\n" " ") | partial: $(grep -rl "^2.5e-09 7$" postProcessing | tr "\n" " ")"; sameSeries . 2>&1 | head -0
