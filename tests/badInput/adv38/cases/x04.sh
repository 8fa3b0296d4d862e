#!/bin/bash
# x04: a stale lock of ANOTHER host name (the container's host name changed after a reset; its process long gone) in a finished blast case: cellBlastFoam restart, planeWave, solidToFoam: each refused with the lock named and how to remove it, nothing written?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; printf 'pid 4242\nhost oldhost-7f3a\nexecutable cellBlastFoam\nstarted 2026-12-01T10:00:00\ncase %s\n' "$PWD" > .runLock
sums > ../s1
for c in "cellBlastFoam" "planeWave -Z 20e-6 -dz 50e-9" "solidToFoam solid/solid.h5"; do try "$c" $c; done
sums > ../s2; cmp -s ../s1 ../s2 && echo "files unchanged" || diff ../s1 ../s2 | head -5
grep -a -i "host\|remove" $W/try.log | head -3 | cut -c1-250
