#!/bin/bash
# w39: ind: the case on a full disk (tmpfs sized 300 kB above the smoke case's mesh), a run from the start: clear error when a write fails, nothing half-written left as good, restart after space is freed?
. "$(dirname "$0")/../lib.sh"
ind; rm -f log.*; m=$W/mnt; mkdir -p $m; s=$(du -sk . | cut -f1); mount -t tmpfs -o size=$((s+300))k tmpfs $m; cp -a . $m/case; cd $m/case; df -k . | tail -1
run 120 cellIndentationFoam > $W/log.full 2>&1; fatal $W/log.full 6; tail -1 $W/log.full | cut -c1-200; ls -la postProcessing/indentation 2>/dev/null | tail -6
cd $W; mount -o remount,size=50m $m; cd $m/case; latest; run 120 cellIndentationFoam > $W/log.after 2>&1; fatal $W/log.after 6; tail -1 $W/log.after; cd $W; umount $m
