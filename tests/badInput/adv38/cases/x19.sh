#!/bin/bash
# x19: indentation finished: a user's notes.txt in postProcessing/indentation/ and a user's plot folder postProcessing/myPlots/: then cellIndentationFoam -overwrite (full run): the user's files kept?
. "$(dirname "$0")/../lib.sh"
indDone; echo "my notes" > postProcessing/indentation/notes.txt; mkdir -p postProcessing/myPlots; echo plot > postProcessing/myPlots/a.txt
run 120 cellIndentationFoam -overwrite > log.o 2>&1; tail -1 log.o; fatal log.o 3; ls postProcessing/indentation postProcessing/myPlots | tr '\n' ' '; echo; find . -name '.*overwritten*'
