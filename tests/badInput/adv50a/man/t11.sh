. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
mkdir -p $W/bind; bd; C=$PWD; latest; blastEnd 12e-9 1e-9; rm -f .runLock; cd $W
printf '%s\n' "mount --bind '$C' '$W/bind' || exit 9" "cd '$W/bind' || exit 9" 'cellBlastFoam > log.ns 2>&1; echo "ns solver rc $?" > /tmp/adv50a-man/t11.nsrc' > $W/ns.sh
unshare -rm bash $W/ns.sh & np=$!; sleep 6
echo "lock at 6 s: $(cat $C/.runLock 2>/dev/null | tr '\n' ' ')"
cd $C; cellBlastFoam > log.out 2>&1 & op=$!; sleep 8; echo "outside solver after 8 s: alive=$([ -e /proc/$op ] && echo yes || echo no) | $(grep -a -m2 'stale\|in use\|Removing' log.out | cut -c1-250 | tr '\n' '|')"
wait $op; echo "outside rc $?"; wait $np; cat /tmp/adv50a-man/t11.nsrc; echo "ns log tail: $(tail -3 $C/log.ns | tr '\n' '|' | cut -c1-300)"; echo "times: $(ls -d [0-9]* | tr '\n' ' ') | markers: $(ls [0-9]*/.writeCommitted | wc -l)"
rm -rf $W
