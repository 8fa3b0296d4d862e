#!/bin/bash
# d53 (class 6, a blast restart on a full disk: the finished preview copied onto a tmpfs 300 KiB larger than it, restarted to 3 ns; then moved to a roomy disk and restarted again): the first fails naming the file it could not write, exit non-zero, no crash; the second continues from 2e-09 (nothing of 1e-09/2e-09 lost, solid.h5 consistent).
. "$(dirname "$0")/../lib.sh"
bd; rs; s=$(du -sk . | cut -f1); cd $W; tiny $((s + 300))k; cp -a blast fs/blast; cd fs/blast; tryt 240 "restart on a full disk" cellBlastFoam; cont; after; df -k . | tail -1
cd $W; rm -rf b2; cp -a fs/blast b2; cd b2; tryt 240 "restart on a roomy disk" cellBlastFoam; cont; after
