. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; C=$PWD; ln -s $C $W/lnk; latest; blastEnd 12e-9 1e-9; rm -f .runLock
(cellBlastFoam > log.bg 2>&1; echo "bg rc $?" > $W/bgrc) & sleep 4; echo "lock: $(cat .runLock 2>/dev/null | tr '\n' ' ')"; cd /tmp
$W/lnk/Allclean; echo "(g) Allclean via linked folder rc $?; case: $(ls $C | tr '\n' ' ')"
$C/Allclean; echo "(h') Allclean by real path rc $?"; wait; cat $W/bgrc; echo "case now: $(ls $C | tr '\n' ' ')"
rm -rf $W
