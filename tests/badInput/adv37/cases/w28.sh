#!/bin/bash
# w28: blast: restart of a finished case mounted read-only (bind mount, ro): a clear error, exit non-zero, no crash?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; mkdir -p ../ro; mount --bind . ../ro && mount -o remount,bind,ro ../ro; cd ../ro
run 120 cellBlastFoam > /tmp/adv37.w28.log 2>&1; fatal /tmp/adv37.w28.log 6; tail -2 /tmp/adv37.w28.log; cd ..; umount ro
