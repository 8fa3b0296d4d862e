. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
blast; short; rm -f .runLock; ls system | tr '\n' ' '; echo
s=$(date +%s); timeout -s KILL 40 mpirun -np 2 cellBlastFoam -parallel > try.log 2>&1; echo "rc $? after $(( $(date +%s) - s )) s"; tail -5 try.log | cut -c1-200
pgrep -u $(id -u) -f "cellBlastFoam -parallel" | while read p; do [ "$(readlink /proc/$p/cwd)" = "$PWD" ] && { echo "left: $p"; kill -9 $p; }; done
rm -rf $W
