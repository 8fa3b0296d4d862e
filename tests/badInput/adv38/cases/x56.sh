#!/bin/bash
# x56: the blast preview Allrun in a read-only case folder (bind mount remounted ro) and with only postProcessing/ immutable (chattr +i) at a restart: clear messages naming the folder and the reason, exit non-zero, nothing lost?
. "$(dirname "$0")/../lib.sh"
prev; mkdir -p $W/ro; mount --bind $W/c $W/ro && mount -o remount,ro,bind $W/ro || { echo "no bind mount"; }; run 60 $W/ro/Allrun $PREV -endTime 2e-9 > ../log.ro 2>&1; head -3 ../log.ro | cut -c1-300; umount $W/ro
blastDone; latest; blastEnd 3e-9 1e-9; chattr +i postProcessing/fsi/0 || echo "no chattr"; run 100 cellBlastFoam > log.r 2>&1; fatal log.r 5; chattr -i postProcessing/fsi/0; ls -d [1-9]* | tr '\n' ' '
