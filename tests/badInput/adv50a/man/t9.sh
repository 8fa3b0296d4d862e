. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
idn; cp postProcessing/indentation/force.dat ../force.orig; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
for k in 1 2; do cellIndentationFoam -overwrite > log.new$k 2>&1 & p=$!; waitFor 60 test -f postProcessing/indentation/.force.dat.overwritten$([ $k = 2 ] && echo 1) ; sleep 0.3; kill -9 $p; wait $p; echo "kill $k: $(ls -a postProcessing/indentation | tr '\n' ' ')"; done
for f in postProcessing/indentation/.force.dat.overwritten*; do echo "$f: $(cmp -s $f ../force.orig && echo 'the original' || echo "other ($(wc -l < $f) lines)")"; done
cellIndentationFoam > log.plain 2>&1; echo "plain start rc $?"; grep -a -A12 FATAL log.plain | grep -a -v "^ *$" | head -14
rm -rf $W
