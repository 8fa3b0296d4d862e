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
echo "solidToFoam: passed"
