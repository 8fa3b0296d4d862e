#!/bin/bash
# checkQuarterRun.sh CASE: issue 17 item 1 on a finished 150 ns run of the
# 3D quarter (tutorials/blast/quarter3D) at the setting the main job runs
# (tutorials/Allrun: ./Allrun -np 2 -cell 0.7e-6 -lateral 2e-6 -far 10e-6
# -inflow 14e-6, with -pulse 5e-9, 1e-8 or 1.5e-8), e.g. the case
# bench/blast/inflow3D.sh DIR 2 ... leaves in DIR/quarter3D. Not run by
# ctest: a 3D run to 150 ns is 2.6 min wall on 2 idle cores and 10-30 min
# on the shared machine, three of them too long for the Alltest; CI covers
# the quarter through the pulse's arrival only (blast.quarter3DSmoke), and
# the 150 ns bounds on the preview (blast.preview150ns.pulse*).
#
# Asserts:
#   - checkLongRun.py CASE endTime (the run reached the controlDict's
#     endTime, every coupling step converged, the pulse reached the probe,
#     no node above 10 % of the pulse's particle velocity from 110 ns on,
#     every element's J within [0.9, 1.1])
#   - planeWave -case CASE -dz 50e-9 -check (50 nm cells, as the
#     tutorial's plots stage): arrival within 0.3 ns, 1-ns peak, incident
#     1-ns peak and plateau within 5 %, impulse within 3 % at every water
#     probe and at the solid probes (the Fig. 10 point, cytoplasm and
#     nucleus side) against the 1D plane wave; and item 6's rest strain
#     (|strain_z| after 140 ns below 1e-3). Left out of the check (printed
#     by planeWave, in CASE/postProcessing/planeWave/0/solidMeasures.dat):
#     the solid probes' von Mises and strain 1-ns peaks (item 4) and their
#     von Mises after 140 ns (item 6: 0.15-0.16 of the peak in 3D, not
#     met; docs/results/blast3D.md, "What keeps the 3D cell flowing after
#     the pulse")
# Exit status 0 when every assertion holds. planeWave writes its files
# into CASE/postProcessing/planeWave/0/ (the same as the run's own plots
# stage computes).
set -euo pipefail
[ $# -eq 1 ] || { sed -n 2,30p "$0"; exit 1; }
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
case=$(cd "$1" && pwd)
[ -f "$case/system/controlDict" ] || {
    echo "checkQuarterRun.sh: $case/system/controlDict not found" \
        "(not a case)" >&2; exit 1; }
# a path OpenFOAM cannot hold (a space, a quote): foamDictionary reads
# nothing there, and the mode was said to be '' (adv50b k17 (e))
problem=$(PYTHONPATH="$PROJECT_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}" \
    /usr/bin/python3 -c 'import sys; from neuronFsi import options
print(options.casePathProblem(sys.argv[1]))' "$case")
[ -z "$problem" ] || {
    echo "checkQuarterRun.sh: $problem" >&2; exit 1; }
mode=$(foamDictionary -entry mode -value "$case/system/cellMeshDict" \
    2> /dev/null || true)
[ "$mode" = quarter3D ] || {
    echo "checkQuarterRun.sh: $case is not a quarter3D case" \
        "(system/cellMeshDict mode '$mode')" >&2; exit 1; }
endTime=$(foamDictionary -case "$case" -entry endTime -value \
    "$case/system/controlDict")
status=0
/usr/bin/python3 "$here/checkLongRun.py" "$case" "$endTime" || status=1
planeWave -case "$case" -dz 50e-9 -check \
    -except solid:vonMises1ns,solid:strain1ns,solid:restVonMises \
    || status=1
exit $status
