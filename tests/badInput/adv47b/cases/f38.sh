#!/bin/bash
# f38 (environment, the disk fills during a blast write): bd copied onto a tmpfs whose size leaves about half a time directory free, restart to 4e-9: stops with an error naming what could not be written (rc != 0, no signal), the earlier times and solid.h5 intact; after the tmpfs is enlarged the restart continues and equals the restart on a normal disk (B) exactly.
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/B; cd $W/B; latest; blastEnd 4e-9 1e-9; tryt 240 "B on a normal disk" cellBlastFoam
bd; mv $W/blast $W/blast0; s=$(du -sk --apparent-size $W/blast0 | cut -f1); t=$(du -sk --apparent-size $W/blast0/2e-09 | cut -f1); tiny $((s + t / 2 + 200))k; cp -a $W/blast0 $W/fs/blast; cd $W/fs/blast; latest; blastEnd 4e-9 1e-9; df -k $W/fs | tail -1
tryt 240 "restart on the filling disk" cellBlastFoam; grep -a -c 'Segmentation\|sigFpe\|signal' $W/try.log; after; tail -3 $W/try.log | cut -c1-200
mount -o remount,size=200m $W/fs; tryt 240 "restart after the disk was enlarged" cellBlastFoam; cont; after; cmpRef $W/B
