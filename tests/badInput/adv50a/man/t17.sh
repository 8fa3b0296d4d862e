. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 1e-10
(ulimit -v 3000000; exec cellMesh > $W/try.log 2>&1) & p=$!
for i in $(seq 12); do sleep 10; [ -e /proc/$p ] || break; echo "$(ps -o rss=,vsz=,time=,etime= -p $p) | log lines $(wc -l < $W/try.log)"; done
[ -e /proc/$p ] && kill $p; wait $p; echo "rc $?"; tail -4 $W/try.log | cut -c1-250
rm -rf $W
