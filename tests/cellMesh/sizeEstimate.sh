#!/bin/bash
# The water's cell count estimated from the sizes before meshing (issue
# 19, class 6; Foam::fluidBox::tetCells, wedgeCells) against the count
# gmsh then makes, on the cell of tests/badInput/cellMeshDict:
#   quarter3D tetrahedra: the estimate within a factor 2 of gmsh's count;
#   axisymmetric wedge: the estimate a lower bound.
# Prints the table of docs/reliability.md (class 6).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
mkdir system constant
fail=0
printf '%-13s %-8s %-8s %-8s %10s %8s %6s\n' mode nearSize farSize growth estimate gmsh ratio
run()
{
    local mode=$1 near=$2 far=$3 growth=$4
    cp "$root/tests/badInput/cellMeshDict" system/
    sed -i "s/^mode .*/mode $mode;/; s/^nearSize .*/nearSize $near;/; s/^farSize .*/farSize $far;/; s/^growthDistance .*/growthDistance $growth;/" system/cellMeshDict
    # the 3D cell without a contact zone (its size field is 2D only)
    [ "$mode" = axisymmetric ] \
        || sed -i 's/^contactRadius .*/contactRadius 0;/' system/cellMeshDict
    cellMesh > log.cellMesh 2>&1 || { tail -5 log.cellMesh; exit 1; }
    local est n
    est=$(sed -n 's/^Water: \(about\|at least\) \([0-9.e+]*\) .*/\2/p' log.cellMesh)
    n=$(sed -n 's/^ *water: \([0-9]*\) .*/\1/p' log.cellMesh)
    if [ "$mode" = axisymmetric ]
    then
        # hexahedra and the prisms on the axis
        n=$(sed -n 's/^ *water: \([0-9]*\) hexahedra \([0-9]*\) prisms.*/\1 \2/p' log.cellMesh | awk '{print $1 + $2}')
    fi
    local ratio
    ratio=$(awk -v n="$n" -v e="$est" 'BEGIN { printf "%.2f", n/e }')
    printf '%-13s %-8s %-8s %-8s %10s %8s %6s\n' "$mode" "$near" "$far" "$growth" "$est" "$n" "$ratio"
    if [ "$mode" = axisymmetric ]
    then
        awk -v r="$ratio" 'BEGIN { exit !(r >= 1) }' || { echo "FAIL: not a lower bound"; fail=1; }
    else
        awk -v r="$ratio" 'BEGIN { exit !(r >= 0.5 && r <= 2) }' || { echo "FAIL: not within a factor 2"; fail=1; }
    fi
}
for s in "2e-6 20e-6 30e-6" "1e-6 10e-6 30e-6" "0.5e-6 5e-6 20e-6" "1e-6 20e-6 10e-6" "0.3e-6 20e-6 30e-6"
do
    run quarter3D $s
done
for s in "2e-6 20e-6 30e-6" "0.5e-6 5e-6 20e-6" "0.2e-6 2e-6 10e-6"
do
    run axisymmetric $s
done
exit $fail
