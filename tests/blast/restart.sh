#!/bin/bash
# Restart of cellBlastFoam (issues 5 and 8): the preview on a short water
# column (20 um, coarse far field, to 16 ns, a write every 2 ns, the
# tutorial's adjustableRunTime) run once without interruption; a copy
# killed with SIGKILL once 6 ns is written, continued from its latest time
# (startFrom latestTime), stopped with SIGTERM once 12 ns is written (the
# pulse has reached the cell) and continued to the end. Asserted: every
# step of the coupling log, the solid probes and the interface maxima after
# each start equal to the uninterrupted run's bitwise (compareRestart.py;
# every log complete: each is flushed at every write time) and the fields of the last time (fluid, points,
# solid and coupling state) byte-equal. Kills inside writes:
# restartKilledWrites.sh.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib/restartTools.sh"

# Reference: uninterrupted, writes every 2 ns
bash "$here/shortColumn.sh" "$work/ref" writeInterval 2e-9
ref=$work/ref/axisymmetricPreview
cp -r "$ref" "$work/killed"
killed=$work/killed
(cd "$ref" && cellBlastFoam > log.cellBlastFoam 2>&1) \
    || { tail -20 "$ref/log.cellBlastFoam"; exit 1; }

# Killed: SIGKILL once 6e-09 is written, SIGTERM once 1.2e-08 is written,
# each time continued from the latest time
(
    cd "$killed"
    foamDictionary -entry startFrom -set latestTime system/controlDict \
        > /dev/null
    runUntil KILL "[ -f 6e-09/.writeCommitted ]" log.first cellBlastFoam
    echo "SIGKILL after t = $(foamListTimes -latestTime | tail -1) s was written"
    runUntil TERM "[ -f 1.2e-08/.writeCommitted ]" log.second cellBlastFoam
    grep -q "Solid: restarted from" log.second
    echo "SIGTERM after t = $(foamListTimes -latestTime | tail -1) s was written"
    cellBlastFoam > log.restart 2>&1 || { tail -20 log.restart; exit 1; }
    grep -q "Solid: restarted from" log.restart
)
/usr/bin/python3 "$here/compareRestart.py" "$ref" "$killed" --bitwise \
    --pulse 25e6
sameFiles "$ref/1.6e-08" "$killed/1.6e-08" p U T rho rhoU rhoE \
    polyMesh/points uniform/solidState uniform/fsiState
echo "blast restart: SIGKILL and SIGTERM, logs and last fields bitwise equal"
