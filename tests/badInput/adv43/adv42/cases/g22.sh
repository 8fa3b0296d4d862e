#!/bin/bash
# g22 (class 2+4, disk full at each write of a restart): finished blast to 2 ns on a tmpfs; the file system filled to leave k kB free (0, 16, 128, 512, 2048), restart to 3 ns: a clear error naming the full disk, nothing of the earlier results lost or changed? then space freed, the same restart: equal to a clean restart's?
. "$(dirname "$0")/../lib.sh"
blastRef; mkdir -p $W/fs; sz=$(( $(du -sk $W/r/ref2 | cut -f1) * 3 + 20000 )); mount -t tmpfs -o size=${sz}k tmpfs $W/fs || { echo "no tmpfs"; exit 0; }
for k in 0 16 128 512 2048; do
  cd $W/fs; rm -rf c fill; cp -r $W/r/ref2 c; cd c; latest; blastEnd 3e-9 1e-9; sums > ../s; contents > ../before; free=$(stat -f -c '%a*%S' . ); head -c $(( free - k*1024 )) /dev/zero > ../fill 2>/dev/null
  timeout -s KILL 100 cellBlastFoam > $W/log.r 2>&1; rc=$?; echo "k=$k kB free ($(df -k . | tail -1 | awk '{print $4}') kB): rc $rc | $( (grep -a -m1 -A3 -i 'FATAL\|rror\|space\|cannot' $W/log.r || tail -4 $W/log.r) | grep -av '^ *$' | tr '\n' ' ' | cut -c1-420)"
  echo "   earlier contents lost: $(lost ../before | wc -l); left: $(ls -d [1-9]* .[0-9]* 2>/dev/null | tr '\n' ' ') $(find . -name '*.tmp' -o -name '*.incomplete' | tr '\n' ' ')"
  rm -f ../fill; timeout -s KILL 100 cellBlastFoam > $W/log.r2 2>&1; echo "   space freed, restart again: rc $? $(grep -a -m1 -A1 'FATAL' $W/log.r2 | tr '\n' ' ' | cut -c1-200)"; [ -d 3e-09 ] && cmpRef $W/r/ref
done
cd $W; umount $W/fs
