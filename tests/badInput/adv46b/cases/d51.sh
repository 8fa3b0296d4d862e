#!/bin/bash
# d51 (class 6, cellMeshDict sizes asking for too much, indentation, each 60 s, max RSS): membraneLayers 100000; contactSize 1e-9; nucleusSize 1e-9; membraneThickness 1e-12 with membraneLayers 1; contactRadius 1 (a bead zone larger than the cell): each refused before meshing naming the entry and the estimate, in seconds, little memory.
. "$(dirname "$0")/../lib.sh"
ind; cp system/cellMeshDict ../d; md5sum constant/cell.msh > ../m
for e in "membraneLayers 100000" "contactSize 1e-9" "nucleusSize 1e-9" "membraneThickness 1e-12" "contactRadius 1"; do cp ../d system/cellMeshDict; sete system/cellMeshDict $e
  /usr/bin/time -f "%M" -o ../rss timeout -s KILL 60 cellMesh > $W/try.log 2>&1; rc=$?; echo "$e: rc=$rc maxRSS $(tail -1 ../rss) kB | $(grep -a -m1 -A2 "FATAL\|Error\|error" $W/try.log | grep -v "^ *$" | head -2 | tr "\n" " " | cut -c1-300)"; done; echo "   cell.msh: $(md5sum -c ../m 2>&1 | awk "{print \$2}")"
