. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
mkdir -p $W/bind; bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; C=$PWD; latest; blastEnd 12e-9 1e-9; rm -f .runLock; cd $W
printf '%s\n' "mount --bind '$C' '$W/bind' || exit 9" "cd '$W/bind' || exit 9" 'cellBlastFoam > log.ns 2>&1; echo "ns solver rc $?" > /tmp/adv50a-man/t10.nsrc' > $W/ns.sh
unshare -rm bash $W/ns.sh & np=$!; sleep 6
echo "lock at 6 s: $(cat $C/.runLock 2>/dev/null | tr "\n" " ")"; echo "solvers: $(pgrep -u $(id -u) -f "^cellBlastFoam" | while read p; do echo -n "$p:$(readlink /proc/$p/cwd) "; done)"
cd /tmp; $C/Allclean; echo "Allclean (outside, real path) rc $?"; echo "after Allclean: $(cd $C; ls -a | tr '\n' ' ')"
wait $np; echo "ns exit $?"; cat /tmp/adv50a-man/t10.nsrc; echo "final: $(cd $C; ls -a | tr '\n' ' ')"
# (c): solver outside, Allclean inside the namespace
cd $W; rm -rf blast; bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; C=$PWD; latest; blastEnd 12e-9 1e-9; rm -f .runLock
(cellBlastFoam > log.bg 2>&1; echo "outside solver rc $?" > /tmp/adv50a-man/t10.bgrc) & bp=$!; sleep 6; echo "(c) lock at 5 s: $(cat $C/.runLock | tr '\n' ' ')"
printf '%s\n' "mount --bind '$C' '$W/bind' || exit 9" "cd '$W/bind' || exit 9" './Allclean; echo "Allclean in ns rc $?"' > $W/ns.sh; unshare -rm bash $W/ns.sh
echo "(c) after: $(cd $C; ls -a | tr '\n' ' ')"; wait $bp; cat /tmp/adv50a-man/t10.bgrc; echo "(c) final: $(cd $C; ls -a | tr '\n' ' ')"
rm -rf $W
