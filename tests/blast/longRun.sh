#!/bin/bash
# longRun.sh PULSE: the axisymmetric preview at its default meshes to 150 ns
# (the paper's end time) for a pulse of PULSE s (5, 10, 15 ns), then
# checkLongRun.py (completion, coupling, no drift, sound elements) and
# planeWave -check: the Fig. 10 probe and the water probes on the axis
# against the 1D plane wave (50 nm cells; arrival 0.3 ns, 1-ns peaks and
# plateau 5 %, impulse 3 %: issue 17), and the solid probes' von Mises and
# strain against the uniaxial-strain answer at their material points
# (1-ns peaks within 5 %; after 140 ns |strain_z| below 1e-3 and von Mises
# below 10 % of its peak). The 50 nm column is within 0.3 % of the 25 nm
# one on the pressure measures; on the 5 ns pulse's von Mises peak at the
# Fig. 10 point it is 0.9 % below it (the echo's front in the 1-ns mean,
# first order in the cell size: docs/results/blastPlaneWave.md, "The 5 ns
# von Mises"), which makes the scene's error look about a point larger.
# Not checked, for the 10 ns pulse only: the water probe's whole-history
# 1-ns peak 2.1 um above the cell on the axis (+13.4 % at the default
# sizes): the posed model's departure from 1D, a ring wave scattered by
# the membrane's quadratic law on the cell's curved top converging on the
# axis (docs/results/blastPlaneWave.md, "The transparent cell": with
# water's law in every region the same error goes to 0 at first order,
# with the posed membrane it converges to +12-14 %). It is printed
# (measures.dat). The same check is made a second time against planeWave
# -layered (20 nm cells): the posed model's 1D answer on the axis, the
# membrane with its own quadratic law (docs/results/blastPlaneWave.md
# "The layered reference"); the layers move the references by at most
# 0.3 %, so the same exception holds.
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
    10e-9|1e-8) except=(-except fluid:peak1ns) ;;
    *) except=() ;;
esac
planeWave -case "$work/axisymmetricPreview" -dz 50e-9 -check "${except[@]}" \
    || status=1
planeWave -case "$work/axisymmetricPreview" -layered -dz 20e-9 -check \
    "${except[@]}" || status=1
exit $status
