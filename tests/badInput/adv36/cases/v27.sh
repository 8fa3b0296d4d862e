#!/bin/bash
# v27: blast: planeWave -partial on a finished case, and planeWave (no -partial) with a stale lock of a dead process
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -partial -dz 50e-9 > log.pw1 2>&1; echo "-partial on finished rc=$?"; head -3 log.pw1 | cut -c1-250
sh -c 'exit 0' & dp=$!; wait $dp; printf 'pid %s\nhost %s\nexecutable cellBlastFoam\nstarted 2026-12-04T16:00:00\ncase %s\n' $dp $(hostname) "$PWD" > .runLock
planeWave -dz 50e-9 > log.pw2 2>&1; echo "stale lock rc=$?"; grep -ai "lock\|error" log.pw2 | head -3 | cut -c1-250; ls -a | grep -c runLock
