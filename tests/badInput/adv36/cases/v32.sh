#!/bin/bash
# v32: ind: a user's file put into a converted <time>/solid/, then a re-conversion after -overwrite with the last row removed (that time gone from solid.h5): the user's file removed?
. "$(dirname "$0")/../lib.sh"
indDone; solidToFoam postProcessing/indentation/solid.h5 > log.s1 2>&1; ls -d [0-9]* | tr '\n' ' '; echo; last=$(ls -d [0-9]* | sort -g | tail -1); echo "my notes" > $last/solid/notes.txt; echo "user file in $last/solid"
sed -i '/(C1  unload/d' constant/indenterProperties; cellIndentationFoam -overwrite > log.2 2>&1; echo "second run rc=$?"
solidToFoam postProcessing/indentation/solid.h5 > log.s2 2>&1; echo "conversion rc=$?"; grep -a -A4 "FATAL\|Removed" log.s2 | head -6 | cut -c1-300; ls -d [0-9]* | tr '\n' ' '; echo; ls $last/solid/notes.txt 2>&1
