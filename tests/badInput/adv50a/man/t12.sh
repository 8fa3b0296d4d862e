. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
for v in 1e-15 1e-200 4.9e-324; do mdir quarter3D; mset azimuthSize $v; (ulimit -v 3000000; cm "" 60); done
for v in 1e-12 1e-200; do mdir; mset meshType structured; mset membraneSize $v; (ulimit -v 3000000; cm "" 60); done
for v in 1e-12; do mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize $v; mset maxElements 1000000000; (ulimit -v 3000000; cm "" 120); done
rm -rf $W
