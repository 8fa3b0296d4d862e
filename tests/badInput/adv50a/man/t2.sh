. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 2e-10; (ulimit -v 8000000; cm "" 400); grep -a -m3 'maxElements\|memory\|FATAL' $W/try.log | cut -c1-300
rm -rf $W
