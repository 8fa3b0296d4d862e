. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
for m in 13000000 13100000 13200000; do mdir; mset meshType structured; mset nucleusSize 2e-9; mset cytoplasmSize 2e-9; mset membraneSize 2e-9; mset maxElements $m; (ulimit -v 3000000; cm "" 60); done
rm -rf $W
