#!/bin/bash
# longRun.sh PULSE: the axisymmetric preview at its default meshes to 150 ns
# (the paper's end time) for a pulse of PULSE s (5, 10, 15 ns), then
# checkLongRun.py (completion, coupling, no drift, sound elements) and
# planeWave -check: the Fig. 10 probe and the water probes on the axis
# against the 1D plane wave (50 nm cells, within 0.3 % of the 25 nm
# answer; arrival 0.3 ns, 1-ns peaks and plateau 5 %, impulse 3 %: issue
# 17), and the solid probes' von Mises and strain against the uniaxial-
# strain answer (1-ns peaks within 5 %; after 140 ns |strain_z| below 1e-3
# and von Mises below 10 % of its peak). Not checked, the known failures
# of docs/results/blastPlaneWave.md ("The default at x0.7"), for the 10 and
# 15 ns pulses only: the echo from the substrate near the cell (the water
# probe's whole-history 1-ns peak at 10 um, +14.6 / -6.1 %: a wave that
# converges on the axis after the echo, fading with the distance from it,
# +14.3 / +9.3 / +3.9 / +2.0 / +0.2 % at r = 0.1 / 1 / 2 / 4 / 16 um for the
# 10 ns pulse; with water's law in the membrane +5.6 %), the solid probe's
# 1-ns peak before the 1D echo (+7 to +8 %: the scene's echo front, about
# 1 ns wide in the solid, enters the window that ends at the sharp 1D
# echo's arrival), and for the 10 ns pulse the rest strain (1.03e-3
# against 1e-3: a slow isochoric drift after the pulse). They are printed
# (measures.dat, solidMeasures.dat). The same check is made a second time
# against planeWave -layered (20 nm cells): the posed model's 1D answer on
# the axis, the membrane with its own quadratic law and the solid probes
# at their material points (docs/results/blastPlaneWave.md "The layered
# reference"); the layers move the references by at most 0.3 %, so the
# same exceptions hold.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
pulse=$1
work=${TMPDIR:-/tmp}/blastLong.$$
trap 'rm -rf "$work"' EXIT
bash "$here/runPreview.sh" "$work" -pulse "$pulse" -endTime 1.5e-7 \
    -noPlots > "$work.log" 2>&1 || { tail -30 "$work.log"; rm -f "$work.log"; exit 1; }
rm -f "$work.log"
# the time loop's CPU and its split (docs/benchmarks.md's preview row)
grep "^CPU time of the time loop" "$work/axisymmetricPreview/log.cellBlastFoam" || true
status=0
/usr/bin/python3 "$here/checkLongRun.py" "$work/axisymmetricPreview" 1.5e-7 \
    || status=1
case "$pulse" in
    5e-9) except=() ;;
    10e-9|1e-8) except=(-except fluid:peak1ns,solid:peakIncident,solid:restStrain) ;;
    *) except=(-except fluid:peak1ns,solid:peakIncident) ;;
esac
planeWave -case "$work/axisymmetricPreview" -dz 50e-9 -check "${except[@]}" \
    || status=1
planeWave -case "$work/axisymmetricPreview" -layered -dz 20e-9 -check \
    "${except[@]}" || status=1
exit $status
