#!/bin/bash
# x27: blast finished to 2 ns: the user APPENDS a note line to postProcessing/fsi/0/coupling.dat (after the last row), then a restart to 3 ns: accepted? where does the note end up (inside the log between rows, kept, dropped)? the log's rows bitwise those of an uninterrupted 3-ns run?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 3e-9 1e-9; cellBlastFoam > log.ref 2>&1; cp postProcessing/fsi/0/coupling.dat ../ref.dat; rm -rf [1-9]* solid postProcessing
blastEnd 2e-9 1e-9; cellBlastFoam > log.first 2>&1; echo "# my note: looked fine at 2 ns" >> postProcessing/fsi/0/coupling.dat
latest; blastEnd 3e-9 1e-9; run 120 cellBlastFoam > log.r 2>&1; tail -1 log.r; fatal log.r 4
grep -a -n "my note" postProcessing/fsi/0/coupling.dat | cut -c1-80; grep -a -v "my note" postProcessing/fsi/0/coupling.dat | cmp - ../ref.dat && echo "rows (note aside) equal to the uninterrupted run"
