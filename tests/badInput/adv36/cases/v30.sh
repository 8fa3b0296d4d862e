#!/bin/bash
# v30: blast: planeWave on a finished case whose fluidProbes p has zero bytes in its middle
. "$(dirname "$0")/../lib.sh"
blastDone; f=postProcessing/fluidProbes/0/p; s=$(stat -c%s $f); dd if=/dev/zero of=$f bs=1 seek=$((s/2)) count=20 conv=notrunc 2>/dev/null
planeWave -dz 50e-9 > log.pw 2>&1; echo "rc=$?"; grep -ai error log.pw | head -2 | cut -c1-300
