#!/bin/bash
# solidToFoam on an axisymmetric and a 3D result file of the solid library:
# the region passes checkMesh, foamToVTK converts it, every step becomes a
# time directory with the fields, and the converted geometry is right:
# the wedge's volume is (wedge angle/2 pi) x the revolved volume pi R^2 H
# (chord-faced wedge: sin(angle)/angle of it), the box's volume exact.
set -euo pipefail
make=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$make" "$work"
for name in axisymmetric box
do
    c="$work/$name"
    mkdir -p "$c/system" "$c/constant"
    cat > "$c/system/controlDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application solidToFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime 1; deltaT 1; writeControl timeStep; writeInterval 1;
DICT
    for f in fvSchemes fvSolution; do
        echo "FoamFile { version 2.0; format ascii; class dictionary; object $f; }" > "$c/system/$f"
    done
    (cd "$c" && solidToFoam "../$name.h5" > log.solidToFoam)
    (cd "$c" && checkMesh -region solid > log.checkMesh 2>&1) || { tail -20 "$c/log.checkMesh"; exit 1; }
    grep -q "Mesh OK" "$c/log.checkMesh" || { grep -E "\*\*\*" "$c/log.checkMesh"; exit 1; }
    (cd "$c" && foamToVTK -region solid > log.foamToVTK 2>&1) || { tail -20 "$c/log.foamToVTK"; exit 1; }
    n=$(ls -d "$c"/VTK/* | wc -l)
    [ "$n" -ge 1 ] || { echo "no VTK output"; exit 1; }
    for t in 0.5 1; do
        for f in D sigma pressure vonMises J temperatureRise region; do
            [ -f "$c/$t/solid/$f" ] || { echo "missing $name/$t/solid/$f"; exit 1; }
        done
    done
    vol=$(grep -oE "Total volume = [0-9.e+-]+" "$c/log.checkMesh" | awk '{print $4}' | sed 's/\.$//')
    /usr/bin/python3 - "$name" "$vol" <<'PY'
import math, sys
name, vol = sys.argv[1], float(sys.argv[2])
if name == "axisymmetric":
    a = math.radians(5.0)
    exact = math.sin(a)/2*(2e-6)**2*3e-6       # chord-faced wedge of R, H
else:
    exact = 3e-6*2e-6*4e-6
err = abs(vol - exact)/exact
print(f"solidToFoam: {name}: volume {vol:.6e} m^3, expected {exact:.6e} m^3, relative error {err:.1e}")
sys.exit(0 if err < 2e-5 else 1)   # checkMesh prints 6 digits
PY
done
# A conversion over an earlier one (issue 19, adv35 t45): the earlier
# conversion's times this file has no step for are removed (only the region
# folders solidToFoam marked; a time directory keeps what else it holds),
# an unmarked region folder of such a time stops it with nothing written
c="$work/box"
for t in 8e-05 9e-05; do
    mkdir -p "$c/$t/solid"; cp "$c/1/solid/.solidToFoam" "$c/1/solid/D" "$c/$t/solid/"
done
echo "not solidToFoam's" > "$c/8e-05/p"
(cd "$c" && solidToFoam ../box.h5 > log.solidToFoam2)
[ ! -e "$c/9e-05" ] && [ ! -e "$c/8e-05/solid" ] && [ -f "$c/8e-05/p" ] \
    || { echo "the earlier conversion's times 8e-05, 9e-05 not removed as they should"; ls "$c" "$c/8e-05"; exit 1; }
grep -q "Removed 9e-05/solid: a time of an earlier conversion" "$c/log.solidToFoam2" \
    || { echo "the removal is not reported"; exit 1; }
mkdir -p "$c/7e-05/solid"; echo "a user's" > "$c/7e-05/solid/D"
if (cd "$c" && solidToFoam ../box.h5 > log.solidToFoam3 2>&1); then
    echo "an unmarked region folder of a time the file has not: converted over"; exit 1
fi
grep -q "the time directories 7e-05 of .* hold a folder 'solid'" "$c/log.solidToFoam3" \
    && [ -f "$c/7e-05/solid/D" ] || { echo "not refused as it should"; tail -5 "$c/log.solidToFoam3"; exit 1; }
# ... and a marked folder holding a file solidToFoam did not write (a
# user's notes: adv36 v32, removed with the folder, exit 0) stops it,
# naming the file, with nothing removed
rm -rf "$c/7e-05"
mkdir -p "$c/6e-05/solid"; cp "$c/1/solid/.solidToFoam" "$c/1/solid/D" "$c/6e-05/solid/"
echo "my notes" > "$c/6e-05/solid/notes.txt"
if (cd "$c" && solidToFoam ../box.h5 > log.solidToFoam4 2>&1); then
    echo "a marked region folder holding a user's file: removed"; exit 1
fi
grep -q "holds files solidToFoam did not write" "$c/log.solidToFoam4" \
    && grep -q "6e-05/solid/notes.txt" "$c/log.solidToFoam4" \
    && [ -f "$c/6e-05/solid/notes.txt" ] && [ -f "$c/6e-05/solid/D" ] \
    || { echo "not refused as it should"; tail -5 "$c/log.solidToFoam4"; exit 1; }
echo "solidToFoam: passed"
