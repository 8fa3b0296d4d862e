#!/bin/bash
# i24 (class 3, a lock written by another host): bd restarted (rs; the preview's Allclean copied in) with a .runLock naming
# host node17 (pid 1, alive here, and pid 999999, alive nowhere here), then host "vm " (this host's name with a trailing
# space), "VM" and "vm.cluster" with pid 4000000 (below Linux's largest pid_max, 4194304)
# (names of this host written otherwise, as an NFS client may): each refused by cellBlastFoam, cellMesh, solidToFoam,
# planeWave -check and the preview's Allclean, naming the lock, its host, its pid and that it is removed by hand (never
# taken over: the documented rule), nothing changed (the lock kept as it was).
. "$(dirname "$0")/../lib.sh"
bd; rs; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; H=$(hostname); echo "   this host: $H"
for hp in "node17|1" "node17|999999" "$H |4000000" "${H^^}|4000000" "$H.cluster|4000000"; do h=${hp%|*}; p=${hp##*|}
  printf 'pid %s\nhost %s\nexecutable cellBlastFoam\nstarted 2026-12-05T01:00:00\ncase %s\n' "$p" "$h" "$PWD" > .runLock; md5sum .runLock > ../l0; sums > ../s0
  echo "[host '$h' pid $p]"; for c in cellBlastFoam cellMesh solidToFoam "planeWave -check" ./Allclean; do tryt 120 "   $c" $c; echo "      $(grep -a -m1 -i 'lock\|in use\|host' $W/try.log | cut -c1-250)"; done
  echo "   lock kept: $(md5sum -c ../l0 2>&1 | tail -1) | changed: $(changed ../s0)"; done
