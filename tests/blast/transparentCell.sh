#!/bin/bash
# The transparent cell against the exact 1D plane wave (issue 17 item 1;
# docs/results/blastPlaneWave.md, "The transparent cell"): the preview at
# level x1 (-h 0.25e-6 -far 1e-6 -dz 0.25e-6 -cell 0.5e-6) with every
# region of the cell given water's Mie-Grueneisen law (bench/blast/
# transparentCell.sh ... water), the 10 ns pulse to 90 ns (the echo and
# its impulse window at every probe), water probes at z = 10 um, r = 0.1,
# 1, 2, 4, 8 um. The whole scene is then water to its shear moduli, and
# the water-only 1D column (planeWave) is its exact answer. Asserts every
# measure of planeWave -check within issue 17's bounds, except these,
# bounded by what x1 measured (2026-12-05; the water probes re-measured
# 2026-12-06 sampling at their points, docs/results/blastPlaneWave.md
# "The water probes at their points") rounded up; they fall at first
# order with the cell size (the ladder in the docs: the axis probe's
# 1-ns peak +8.1 / +5.6 / +4.0 / ... % at x1 / x0.7 / x0.5):
#   the 1-ns peak of the water at r = 0.1 um     9 %  (x1: +8.13 %)
#                                  at r = 1 um    6.5 % (+5.71 %)
#   the solid's incident 1-ns peak               13 %  (+12.2 / +10.4 %)
#   the solid's von Mises and strain 1-ns peaks  8 / 6 % (+7.46 / +5.36 %)
# A scene whose cell scatters (the membrane's quadratic law: +14 % on the
# axis) or whose numerics depart from the 1D wave by more fails. About
# 50 s wall on a quiet machine (217 s with it loaded 8-10 times over).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
bash "$here/../../bench/blast/transparentCell.sh" "$work/run" 1 water \
    -pulse 1e-8 -endTime 9e-8 > "$work/out" 2>&1 || status=$?
# the check's own exit: 1 for the measures outside the 5 % bounds (those
# excepted below included); anything else is a failed run
if [ "$status" -gt 1 ] || ! grep -q "^fluidProbes_4 " "$work/out"
then
    cat "$work/out"; echo "FAIL transparentCell: the run failed"; exit 1
fi
case=$work/run/axisymmetricPreview
grep -q "volumetric mieGruneisen; d0 0; C0 1450; rho0 1000; volumetric mieGruneisen; d0 0; C0 1450; rho0 1000; volumetric mieGruneisen" \
    <<< "$(head -1 "$work/out" | tr -s ' ')" \
    || { head -1 "$work/out"; echo "FAIL transparentCell: not water's law in every region"; exit 1; }
planeWave -case "$case" -reference "$case/postProcessing/planeWave/0/reference.dat" \
    -check -except fluid:peak1ns,solid:peakIncident,vonMises1ns,strain1ns \
    > "$work/check" 2>&1 \
    || { grep -v "^#" "$work/check"; echo "FAIL transparentCell: planeWave -check"; exit 1; }
/usr/bin/python3 - "$case/postProcessing/planeWave/0" <<'PY'
import sys
d = sys.argv[1]
fail = []
def rows(name):
    return [l.split() for l in open("%s/%s" % (d, name)) if not l.startswith("#")]
# measures.dat: probe z, 5 pairs, errArrival errPeak1ns errPeakIncident ...
bound = {"fluidProbes_0": 9.0, "fluidProbes_1": 6.5}
for r in rows("measures.dat"):
    name, peak, incident = r[0], float(r[13]), float(r[14])
    if name.startswith("fluidProbes"):
        b = bound.get(name, 5.0)
        if abs(peak) > b:
            fail.append("%s 1-ns peak %+.2f %% (bound %g %%)" % (name, peak, b))
    elif abs(incident) > 13.0:
        fail.append("%s incident 1-ns peak %+.2f %% (bound 13 %%)" % (name, incident))
# solidMeasures.dat: probe region z vM vMRef errVM strain strainRef errStrain ...
for r in rows("solidMeasures.dat"):
    for what, v, b in (("von Mises", float(r[5]), 8.0), ("strain", float(r[8]), 6.0)):
        if abs(v) > b:
            fail.append("%s %s 1-ns peak %+.2f %% (bound %g %%)" % (r[0], what, v, b))
for f in fail:
    print("FAIL transparentCell: " + f)
sys.exit(1 if fail else 0)
PY
echo "transparentCell: ok"
