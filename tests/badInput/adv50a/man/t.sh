. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 0.1e-6; mset maxElements 1; cm "" 60; grep -a -A6 FATAL $W/try.log | head -12
mdir quarter3D; mset maxElements 1; cm "" 60; grep -a -A6 FATAL $W/try.log | head -12
rm -rf $W
