#!/bin/bash
# f39 (environment, the disk fills during an indentation restart): ik copied onto a tmpfs with 150 KiB free, restart: an error naming the file that could not be written (rc != 0, no signal), restart.h5/force.dat/peaks.dat/solid.h5 consistent; after enlarging, the restart ends and force.dat equals that of the same restart on a normal disk (B).
. "$(dirname "$0")/../lib.sh"
ik; mv $W/ind $W/B; cd $W/B; tryt 240 "B on a normal disk" cellIndentationFoam
ik; mv $W/ind $W/ind0; s=$(du -sk --apparent-size $W/ind0 | cut -f1); tiny $((s + 150))k; cp -a $W/ind0 $W/fs/ind; cd $W/fs/ind; df -k $W/fs | tail -1
tryt 240 "restart on the filling disk" cellIndentationFoam; grep -a -c 'Segmentation\|sigFpe\|signal' $W/try.log; after; tail -3 $W/try.log | cut -c1-200
mount -o remount,size=200m $W/fs; tryt 240 "restart after enlarging" cellIndentationFoam; cont; after
cmp postProcessing/indentation/force.dat $W/B/postProcessing/indentation/force.dat && echo "   force.dat same as B"; cmp postProcessing/indentation/peaks.dat $W/B/postProcessing/indentation/peaks.dat && echo "   peaks.dat same as B"
