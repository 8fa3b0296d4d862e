#!/bin/bash
# Run the pulseLayer case in a scratch copy with a coupling scheme, a solid
# density (impedance ratio Z_s/Z_f = rho0/1000 with water's C0) and an end
# time; print the measures of analysePulseLayer.py, or "run failed".
# Usage: runPulseLayer.sh <scheme> <rho0 [kg/m^3]> <endTime [s]> [maxIter]
set -euo pipefail
scheme=$1; rho0=$2; endTime=$3; maxIter=${4:-30}
dir=$(cd "$(dirname "$0")" && pwd)
. "$dir/../../etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$dir/pulseLayer" "$work/case"
cd "$work/case"
sed -i "s/^\( *scheme *\)[A-Za-z]*;/\1$scheme;/; s/^\( *maxIter *\)[0-9]*;/\1$maxIter;/" \
    constant/fsiProperties
sed -i "s/^\( *rho0 *\)[0-9.e+-]*;/\1$rho0;/" constant/solidProperties
sed -i "s/^\(endTime *\)[0-9.e+-]*;/\1$endTime;/" system/controlDict
blockMesh > log.blockMesh 2>&1
start=$(date +%s.%N)
if ! cellBlastFoam > log.cellBlastFoam 2>&1; then
    grep -m1 -A3 "FOAM FATAL" log.cellBlastFoam | tr '\n' ' ' || true
    echo
    echo "scheme=$scheme rho0=$rho0: run failed"
    exit 2
fi
end=$(date +%s.%N)
grep "^FSI coupling" log.cellBlastFoam
echo "scheme=$scheme rho0=$rho0 wallTime=$(echo "$end - $start" | bc)s" \
    "$(/usr/bin/python3 "$dir/analysePulseLayer.py" . "$rho0")"
