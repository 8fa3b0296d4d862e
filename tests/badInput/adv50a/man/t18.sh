. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
bd; rs; rm -f .runLock; s=$(date +%s.%N); cellBlastFoam > log.x 2>&1; echo "restart rc $? in $(echo "$(date +%s.%N) - $s" | bc | cut -c1-5) s; times $(ls -d [0-9]* | tr '\n' ' ')"; grep -a -m3 "FATAL\|Warning" -A3 log.x | head -8 | cut -c1-200
rm -rf $W
