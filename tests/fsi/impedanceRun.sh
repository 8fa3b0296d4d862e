#!/bin/bash
# One impedance-ratio run: the pulseLayer case (tests/fsi/pulseLayer, used
# as it is but for the entries below) in a scratch copy with a weak pulse
# (linear acoustics), a coupling scheme and a solid of acoustic impedance
# Z_s = ratio x Z_f (water: 1000 kg/m^3 x 1450 m/s), set by the solid's
# density (rho: rho0 = ratio x 1000, C0 = 1450) or by its sound speed
# (c: rho0 = 1000, C0 = ratio x 1450); prints the measures of
# impedanceAnalyse.py (last line), or "run failed" (exit 2) with the
# first fatal message or signal of the log.
# Usage: impedanceRun.sh <scheme> <ratio> [rho|c] [pI [Pa], default 1e6]
set -euo pipefail
scheme=$1; ratio=$2; by=${3:-rho}; pI=${4:-1e6}
dir=$(cd "$(dirname "$0")" && pwd)
. "$dir/../../etc/bashrc"
case $by in
    rho) rho0=$(awk "BEGIN { print $ratio*1000 }"); C0=1450 ;;
    c)   rho0=1000; C0=$(awk "BEGIN { print $ratio*1450 }") ;;
    *)   echo "impedanceRun.sh: third argument rho or c, not '$by'"; exit 1 ;;
esac
# until the reflected pulse has passed the fluid probe (25 um) and the
# transmitted one the solid probe (75 um): 1 ns after both centres
endTime=$(awk "BEGIN { e = 3.55e-9 + 50e-6/1450 + 25e-6/$C0; \
    f = 3.55e-9 + 75e-6/1450; printf \"%.4e\", (f > e ? f : e) }")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$dir/pulseLayer" "$work/case"
cd "$work/case"
sed -i "s/^\( *scheme *\)[A-Za-z]*;/\1$scheme;/" constant/fsiProperties
sed -i "s/^\( *rho0 *\)[0-9.e+-]*;/\1$rho0;/; s/\( C0 *\)[0-9.e+-]*;/\1$C0;/" \
    constant/solidProperties
sed -i "s/^\(endTime *\)[0-9.e+-]*;/\1$endTime;/" system/controlDict
sed -i "s/^\( *([0-9.e-]* *\)5e7)/\1$pI)/" 0/p
grep -q "^ *scheme *$scheme;" constant/fsiProperties
grep -q "^ *rho0 *$rho0;" constant/solidProperties
grep -q " C0 *$C0;" constant/solidProperties
[ "$(grep -c " $pI)" 0/p)" = 2 ]
blockMesh > log.blockMesh 2>&1
start=$(date +%s.%N)
if ! cellBlastFoam > log.cellBlastFoam 2>&1; then
    # (the banner "trapFpe: Floating point exception trapping enabled" is
    # not a failure)
    { grep -v "^trapFpe" log.cellBlastFoam \
        | grep -m1 -A3 "FOAM FATAL\|Floating point\|sigFpe\|Segmentation" \
        || tail -3 log.cellBlastFoam; } | tr '\n' ' '
    echo
    # The per-step logs end with complete rows (flushed per row: the stop
    # runs no destructor)
    for f in postProcessing/fsi/0/coupling.dat \
        postProcessing/solidProbes/0/solidProbes.dat
    do
        [ -f "$f" ] || continue
        awk -v f="$f" '!/^#/ { if (!n) n = NF; if (NF != n) bad++; rows++ }
            END { printf "%s: %d rows, %s\n", f, rows,
                  bad ? "rows cut: logs incomplete" : "logs complete" }' "$f"
    done
    echo "scheme=$scheme ratio=$ratio by=$by: run failed at" \
        "$(grep '^Time = ' log.cellBlastFoam | tail -1)"
    exit 2
fi
end=$(date +%s.%N)
grep "^FSI coupling" log.cellBlastFoam
echo "scheme=$scheme by=$by rho0=$rho0 C0=$C0" \
    "wallTime=$(awk "BEGIN { printf \"%.1f\", $end - $start }")s" \
    "$(/usr/bin/python3 "$dir/impedanceAnalyse.py" . "$rho0" "$C0" "$pI")"
