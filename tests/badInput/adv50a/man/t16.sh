. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
for m in 2679 2680; do mdir quarter3D; mset maxElements $m; timeout 60 /work/main/platforms/linux64GccDPInt32Opt/bin/cellMesh > $W/try.log 2>&1; echo "main's cellMesh, maxElements $m: rc $? | $(grep -a -m1 'at least' $W/try.log | cut -c1-160)"; done
rm -rf $W
