#!/bin/bash
# g24 (class 2+4, the indentation's -overwrite on a full disk and a read-only folder): a finished smoke indentation; (a) on a tmpfs with 0 kB free, -overwrite: a clear error, the earlier results kept? then space freed, -overwrite: equal to the original's? (b) postProcessing/indentation read-only (bind mount), -overwrite: the same questions
. "$(dirname "$0")/../lib.sh"
indDone; cd ..; mv ind orig; mkdir -p fs; sz=$(( $(du -sk orig | cut -f1) * 3 + 8000 )); mount -t tmpfs -o size=${sz}k tmpfs $W/fs || { echo "no tmpfs"; exit 0; }
cd fs; cp -r ../orig c; cd c; contents > ../before; free=$(stat -f -c '%a*%S' .); head -c $((free)) /dev/zero > ../fill 2>/dev/null; echo "   free: $(df -k . | tail -1 | awk '{print $4}') kB"
tryf "(a) -overwrite on a full disk" cellIndentationFoam -overwrite; echo "   earlier contents lost: $(lost ../before | wc -l); postProcessing: $(ls -a postProcessing postProcessing/indentation 2>/dev/null | tr '\n' ' ' | cut -c1-200)"
rm -f ../fill; tryf "(a) space freed, -overwrite" cellIndentationFoam -overwrite; for f in force.dat peaks.dat; do cmp -s postProcessing/indentation/$f $W/orig/postProcessing/indentation/$f && echo -n "   $f same" || echo -n "   $f DIFF"; done; echo
cd $W; umount $W/fs; cp -r orig b; cd b; sums > ../s.b; mount --bind postProcessing/indentation postProcessing/indentation && mount -o remount,ro,bind postProcessing/indentation
tryf "(b) -overwrite, postProcessing/indentation read-only" cellIndentationFoam -overwrite; umount postProcessing/indentation; nochange ../s.b; echo "   postProcessing: $(ls -a postProcessing | tr '\n' ' ')"
tryf "(b) writable again, -overwrite" cellIndentationFoam -overwrite; for f in force.dat peaks.dat; do cmp -s postProcessing/indentation/$f $W/orig/postProcessing/indentation/$f && echo -n "   $f same" || echo -n "   $f DIFF"; done; echo
