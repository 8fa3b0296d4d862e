#!/bin/bash
# v11: blast: SIGKILL at 5 random moments of a 2e-8 s run, each followed by a restart (latestTime): each restart must run
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 2e-8 1e-9; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict
for d in 0.7 1.9 1.3 2.9 0.45; do cellBlastFoam > log.a 2>&1 & p=$!; sleep $d; kill -KILL $p 2>/dev/null; wait $p 2>/dev/null; echo "killed at $d s, latest $(ls -d [0-9]* | sort -g | tail -1)"; done
cellBlastFoam > log.r 2>&1; echo "final restart rc=$?"; grep -a -A8 FATAL log.r | head -10; ls -d [0-9]* | sort -g | tail -1
