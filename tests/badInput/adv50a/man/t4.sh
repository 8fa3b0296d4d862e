. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 5e-10; (ulimit -v 8000000; cm "" 600); grep -a -m4 'maxElements\|memory\|FATAL\|what' $W/try.log | cut -c1-300; uptime
rm -rf $W
