#!/bin/bash
#------------------------------------------------------------------------------
# restartDigits.sh OUT [P ...] : how far a restart of rhoRiemannFoam from a
# time written with P digits (writePrecision P, ascii) is from the
# uninterrupted run (issue 19, adv50b k58). tutorials/verification/
# waterPulseWall (80 ns, writes every 20 ns) is run
#   a  uninterrupted to its end time,
#   b  the same run with the times after 40 ns removed, then continued from
#      40 ns (startFrom latestTime) to the end time,
# once with the tutorial's writeControl (adjustableRunTime: the step before
# a write time is shortened) and once with writeControl timeStep (every 200
# steps: no step is shortened, as tests/verification/restartExact.sh).
# Prints per P and control the largest |b - a| of p [Pa], rho [kg/m^3],
# U [m/s] at the end time, relative to the largest |a|, and "bitwise" when
# the files are equal. Default P: 3 6 10 12 17. Outputs under OUT.
#------------------------------------------------------------------------------
set -euo pipefail
[ "$#" -ge 1 ] || { sed -n 3,15p "$0" >&2; exit 1; }
root=$(cd "$(dirname "$0")/../.." && pwd)
out=$1; shift
precisions=("$@")
[ "${#precisions[@]}" -gt 0 ] || precisions=(3 6 10 12 17)
. "$root/etc/scratchFolder"
mkdir -p "$out"
out=$(cd "$out" && pwd)
tut="$root/tutorials/verification/waterPulseWall"

prepare() { # dir P control
    scratchFolder restartDigits.sh "$1"
    cp -r "$tut"/{0.orig,system,constant} "$1"/
    rm -rf "$1/constant/polyMesh"
    sed -i "s/^writePrecision .*/writePrecision  $2;/" "$1/system/controlDict"
    if [ "$3" = timeStep ]
    then
        # timePrecision 17: the restart time is read from the directory name
        sed -i 's/^writeControl .*/writeControl    timeStep;/; s/^writeInterval .*/writeInterval   200;/; s/^timePrecision .*/timePrecision   17;/' "$1/system/controlDict"
    fi
    ( cd "$1" && cp -r 0.orig 0 && blockMesh > log.blockMesh 2>&1 )
}

for control in adjustableRunTime timeStep
do
    for p in "${precisions[@]}"
    do
        d="$out/$control/$p"
        prepare "$d/a" "$p" "$control"
        ( cd "$d/a" && rhoRiemannFoam > log.1 2>&1 )
        scratchFolder restartDigits.sh "$d/b"; cp -r "$d/a/." "$d/b/"
        times=($(foamListTimes -case "$d/a"))
        last=${times[-1]}
        from=${times[$(( ${#times[@]} / 2 - 1 ))]}
        for t in "${times[@]}"
        do
            if awk -v t="$t" -v f="$from" 'BEGIN{exit !(t > f)}'
            then
                rm -rf "$d/b/$t"
            fi
        done
        # -acceptEdited: a restart from fewer than 17 digits is refused
        # without it (writeGuard::checkRestartDigits)
        if ! ( cd "$d/b" && rhoRiemannFoam -acceptEdited > log.2 2>&1 )
        then
            echo "writePrecision $p, $control, restart from $from s: the" \
                "restart stopped: $(grep -m1 -A1 'FOAM FATAL' "$d/b/log.2" | tail -1 | cut -c1-160)"
            continue
        fi
        lastB=$(foamListTimes -case "$d/b" -latestTime | tail -1)
        if [ "$lastB" != "$last" ]
        then
            echo "writePrecision $p, $control, restart from $from s: the" \
                "time line differs: the restarted run's last write is at" \
                "$lastB s, the uninterrupted run's at $last s"
            continue
        fi
        PYTHONPATH="$root/src/python" /usr/bin/python3 - "$d/a/$last" "$d/b/$last" "$p" "$control" "$from" <<'PY'
import filecmp, sys
import numpy as np
from neuronFsi import foamField
a, b, p, control, start = sys.argv[1:6]
parts = []
for f, unit in (("p", "Pa"), ("rho", "kg/m^3"), ("U", "m/s")):
    if filecmp.cmp(f"{a}/{f}", f"{b}/{f}", shallow=False):
        parts.append(f"{f} bitwise")
        continue
    va = foamField.internalField(f"{a}/{f}")
    vb = foamField.internalField(f"{b}/{f}")
    d = np.max(np.abs(vb - va))
    parts.append(f"{f} {d:.3g} {unit} ({d/np.max(np.abs(va)):.3g})")
print(f"writePrecision {p:>2}, {control}, restart from {start} s, at "
      f"{a.rsplit('/', 1)[1]} s: " + "; ".join(parts))
PY
    done
done
