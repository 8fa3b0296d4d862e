. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; C=$PWD; ln -s $C $W/lnk; rs; rm -f .runLock
(cellBlastFoam > log.bg 2>&1 &); sleep 3; cd /tmp; $W/lnk/Allclean; echo "rc $?"; $C/Allclean; echo "rc $?"; sleep 1; while pgrep -f "cellBlastFoam" -u $(id -u) -P 1 >/dev/null 2>&1 && [ ! -e $C/3e-09 ]; do sleep 2; done; sleep 5; rm -rf $W
