#!/bin/bash
# b04 (class 2+4, sweepCase -case through a symbolic link to the case folder): $W/lnk -> $W/real/ind; sweepCase -case $W/lnk -values "0.1e-6 0.05e-6" (maxDepthIncrement): where the run folders go (next to the link or the real case), the table correct, nothing left, the real case and the link unchanged?
. "$(dirname "$0")/../lib.sh"
ind; mkdir -p $W/real; mv $W/ind $W/real/ind; ln -s $W/real/ind $W/lnk; cd $W; md5sum real/ind/constant/* > m
tryf "sweep through a linked case" sweepCase -case $W/lnk -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6 0.05e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a '^|' $W/try.log | head -4
echo "   link: $(readlink lnk); real case's dictionaries: $(md5sum -c m 2>&1 | awk '{print $2}' | sort | uniq -c | tr '\n' ' ')"; echo "   W: $(ls -a $W | tr '\n' ' '); real/: $(ls -a real | tr '\n' ' ')"; echo "   report: $(ls real/ind/postProcessing/sweep 2>/dev/null | tr '\n' ' ')"
