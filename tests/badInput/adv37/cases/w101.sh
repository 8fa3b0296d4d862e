#!/bin/bash
# w101: blast: solid/solid.h5 made immutable (chattr +i: root cannot write it either, as an unwritable file), restart to 3 ns: a clear error naming the file and the reason, no crash, nothing lost?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; chattr +i solid/solid.h5 || echo "chattr not supported here"; snap ../before
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 5; tail -1 log.r; chattr -i solid/solid.h5; echo "gone: $(gone ../before | tr '\n' ' ')"
