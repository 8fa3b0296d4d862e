#!/bin/bash
# f36 (environment, a UTF-8 case path under LANG=C): the smoke indentation in $W/café: (a) cellIndentationFoam -case with LC_ALL=C LANG=C, (b) with C.UTF-8: each runs in that folder (force.dat there) or refuses naming the path; never results written into another folder (a name with the é dropped or changed). (c) solidToFoam on it with LC_ALL=C.
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/café"; cp -r $ADV/indBase/{system,constant} "$W/café/"; cd $W
LC_ALL=C LANG=C tryt 200 "(a) LC_ALL=C" cellIndentationFoam -case "$W/café"; echo "   folders: $(ls $W | tr '\n' ' ') force.dat: $(find $W -name force.dat | tr '\n' ' ')"
rm -rf "$W/café/postProcessing"; LC_ALL=C.UTF-8 tryt 200 "(b) LC_ALL=C.UTF-8" cellIndentationFoam -case "$W/café"; echo "   folders: $(ls $W | tr '\n' ' ') force.dat: $(find $W -name force.dat | tr '\n' ' ')"
cd "$W/café"; LC_ALL=C tryt 60 "(c) solidToFoam LC_ALL=C" solidToFoam postProcessing/indentation/solid.h5; ls constant | tr '\n' ' '; echo
