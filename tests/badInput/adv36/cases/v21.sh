#!/bin/bash
# v21: blast: the only written time (1e-9 s) without its .writeCommitted and 64 zero bytes in its p, then a restart
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 1e-9 1e-9; cellBlastFoam > log.first 2>&1; ls -a 1e-09 | tr '\n' ' '; echo; rm 1e-09/.writeCommitted; dd if=/dev/zero of=1e-09/p bs=1 seek=2000 count=64 conv=notrunc 2>/dev/null; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A8 FATAL log.r | head -10
