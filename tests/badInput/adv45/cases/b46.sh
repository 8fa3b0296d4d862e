#!/bin/bash
# b46 (class 4+2, sweepCase on a nearly full disk): the smoke indentation in a tmpfs with room for the case and little more; sweepCase -values "0.1e-6 0.05e-6" -nProcs 2: an error naming the full disk (copying its base or a run folder, or a run's write), exit non-zero, no table; the case unchanged; what is left named?
. "$(dirname "$0")/../lib.sh"
ind; s=$(du -sk $W/ind | awk '{print $1}'); tiny $((s + 300))k; cp -r $W/ind $W/fs/ind; cd $W/fs/ind; md5sum constant/* system/* > $W/m; df -k . | tail -1 | awk '{print "   tmpfs: " $4 " kB free"}'
tryf "sweep on a full disk" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6 0.05e-6" -nProcs 2 -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a '^|' $W/try.log | head -3; for l in $W/fs/ind.sweep_*/log.sweepCase; do [ -f "$l" ] && echo "   $(basename $(dirname $l)): $(grep -a -m1 -A3 'FATAL\|rror' $l | grep -av '^ *$\|^-->' | tr '\n' ' ' | cut -c1-300)"; done
echo "   the case: $(md5sum -c $W/m 2>&1 | awk '{print $2}' | sort | uniq -c | tr '\n' ' '); left: $(ls -a $W/fs | tr '\n' ' '); report: $(ls postProcessing/sweep 2>/dev/null)"; cd $W
