. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
for v in 1e-200 1e-160 1e-155 1e-100; do mdir quarter3D; mset azimuthSize $v; cm "" 60; grep -a -A12 "printStack" $W/try.log | grep -a "#[0-9]" | head -8 | cut -c1-150; done
mdir quarter3D; mset membraneSize 1e-200; cm "" 60
mdir quarter3D; mset nucleusSize 1e-200; cm "" 60
mdir; mset nucleusSize 1e-200; cm "" 60
rm -rf $W
