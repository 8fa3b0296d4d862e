#!/bin/bash
# x55: planeWave on a finished blast on a full disk (a tmpfs with just the case and 4 kB free): a message naming the full disk, exit non-zero, no partial table left as if complete? and sweepCase's base copy on a full disk
. "$(dirname "$0")/../lib.sh"
blastDone; mkdir -p $W/fs; s=$(du -sk . | cut -f1); mount -t tmpfs -o size=$((s+600))k tmpfs $W/fs || exit 0; cp -r . $W/fs/blast; cd $W/fs/blast; head -c $(( $(stat -f -c '%a*%S' .) - 4096 )) /dev/zero > ../dummy 2>/dev/null; df -k . | tail -1
run 100 planeWave -Z 20e-6 -dz 50e-9 > ../log.pw 2>&1; echo "planeWave rc above"; grep -a -i "space\|error\|Traceback" ../log.pw | head -3 | cut -c1-300; ls -la postProcessing/planeWave 2>/dev/null | awk '{print $5, $9}' | tr '\n' ' '; echo
run 100 sweepCase -case . -entry constant/fsiProperties/coupling/maxIter -values "20 25" -run cellBlastFoam -name m -nProcs 1 -output "F=postProcessing/fsi/0/coupling.dat:-1:1" > ../log.sw 2>&1; tail -3 ../log.sw | cut -c1-300; ls ..; cd $W; umount $W/fs
