#!/bin/bash
# CASETIMEOUT=300
# u07 (fix19i's small rows varied: fluidWedgeMesh.py's -maxCells a whole number, with other odd values and its other
# numbers): in a folder with system/: -maxCells nan, inf, 1e3 (a whole number written as a float: taken), 1e9, -R nan,
# -Z inf, -wedge nan, -o /dev/stdout. Expected: each refused in one line naming the option and its range (1e3 and 1e9
# accepted, writing system/blockMeshDict); a traceback = CRASH; a mesh written from nan/inf = SILENT.
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/f/system; cd $W/f; FW="/usr/bin/python3 $ROOT/tutorials/blast/fluidWedgeMesh.py -h 1e-6 -Z 20e-6 -R 20e-6"
for o in "-maxCells nan" "-maxCells inf" "-maxCells 1e3" "-maxCells 1e9" "-maxCells 1e9+1" "-R nan" "-Z inf" "-wedge nan" "-o /dev/stdout"; do rm -f system/blockMeshDict
  tryt 60 "$o" $FW $o; echo "   said: $(tail -1 $W/try.log | cut -c1-250) | tracebacks $(grep -a -c Traceback $W/try.log) | blockMeshDict: $([ -f system/blockMeshDict ] && echo "written, nan/inf lines $(grep -c -i 'nan\|inf' system/blockMeshDict)" || echo none)"; done
