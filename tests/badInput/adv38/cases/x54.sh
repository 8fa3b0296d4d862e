#!/bin/bash
# x54: cellIndentationFoam FRESH on a full file system (a 2.5 MB tmpfs holding the smoke case, filled with a dummy file to 4 kB free): the first write fails: a message naming the full disk, non-zero exit, nothing half-written left as good? then space freed: the run starts (or -overwrite needed and said)?
. "$(dirname "$0")/../lib.sh"
ind; mkdir -p $W/fs; mount -t tmpfs -o size=3m tmpfs $W/fs || { echo "no tmpfs"; exit 0; }; cp -r . $W/fs/ind; cd $W/fs/ind; fill=$(( $(stat -f -c '%a*%S' . ) - 8192 )); head -c $(( fill )) /dev/zero > ../dummy 2>/dev/null; df -k . | tail -1
run 100 cellIndentationFoam > ../log.r 2>&1; grep -a -i -m3 "space\|FATAL\|error\|cannot" ../log.r | cut -c1-300; ls -la postProcessing/indentation 2>/dev/null | awk '{print $5, $9}' | tr '\n' ' '; echo
rm -f ../dummy; run 100 cellIndentationFoam > ../log.r2 2>&1; tail -1 ../log.r2; fatal ../log.r2 4; cd $W; umount $W/fs
