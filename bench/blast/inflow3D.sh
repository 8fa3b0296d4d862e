#!/bin/bash
# The 3D quarter (tutorials/blast/quarter3D) with its water column
# shortened by the planeWaveInflow top (Allrun -inflow; issue 17 item 2,
# issue 18 item 5); not a test. In a scratch copy of the tutorial (inputs
# only) Allrun -noRun prepares the case (meshes, 0/ with the inflow top,
# constant/inflowWave from planeWave -inflow; with -np N the decomposed
# case), then cellBlastFoam runs niced under /usr/bin/time -v, on one rank
# or on N (mpirun -np N --bind-to none cellBlastFoam -parallel), then
# planeWave as the tutorial's plots stage runs it (the full
# column's 1D answer, 50 nm cells) against the probes (on one rank or
# on N).
#
#   bench/blast/inflow3D.sh DIR NP [Allrun options...]
#       DIR   scratch folder (created; must not exist): the case is
#             DIR/quarter3D, kept for inspection
#       NP    MPI ranks (1: serial)
#     e.g. bench/blast/inflow3D.sh /tmp/in1 1 -lateral 2e-6 -far 10e-6 \
#              -inflow 20e-6
#   MAXCO=X in the environment: system/controlDict's maxCo of the copy
#   set to X (the tutorial's default 0.9; 0.5 before 2026-12-03)
#   NICENESS=N in the environment: cellBlastFoam runs at nice -n N
#   (default 10; 0 for a final measurement on a shared machine)
#   FITPROBES=1 in the environment: a second set of water probes,
#   fluidProbesFit, at fluidProbes' locations with interpolationScheme
#   cellLinearFit (the weighted linear fit of the cell values, evaluated
#   at the probe's point) appended to the copy's system/controlDict;
#   planeWave measures both sets. Until 2026-12-06 fluidProbes'
#   cellPoint did not sample at its point in these micrometre cells
#   (OpenFOAM's tetrahedron::pointToBarycentric takes every tetrahedron
#   with |det| < SMALL = 1e-15 m^3 as degenerate, so the probe read its
#   cell's first tetrahedron's centroid); movingMeshProbes now finds the
#   tetrahedron with a test relative to its size
#   (scaleFreeCellPointWeight; docs/results/blast3D.md, "Where the water
#   probes sample"), and the two sets should agree to the schemes'
#   difference
#   WATERVISCOSITY=MU in the environment: the water's Newtonian viscous
#   stress in the copy's system/fvSolution (riemann { viscous true; mu
#   MU; }, MU [Pa s] >= 0; the paper's water, its eq. 12, has 1e-3),
#   set before Allrun -noRun, so that planeWave's 1D columns (the inflow
#   wave and the reference, which copy the case's fvSolution) run the
#   same water (docs/results/blast3D.md, "The paper's water viscosity")
#   MEMBRANE=water in the environment: the transparent quarter, the
#   membrane's quadratic law replaced by water's Mie-Grueneisen law in
#   the prepared case's constant/solidProperties (neuronFsi.membraneLaw,
#   as bench/blast/restVariants3D.sh membrane=water): every region water
#   to its shear moduli, whose exact answer is planeWave's 1D column
#   everywhere (docs/results/blast3D.md, "The quarter with the interface
#   reading at 0.5 um, 0.25 um water")
#   LINEPROBES=1 in the environment: two z-lines of probes through the
#   cell and the water above it, on the axis (x = y = 0.1 um) and at
#   x = y = 5 um: solid probes (material points, every 0.25 um from
#   0.125 um; listed before the interfaceProbe, whose three probes then
#   come last in solidProbes.dat) and water probes (function object
#   echoLines, cellPoint, every 0.25 um from 8 um on the axis, from
#   4.5 um at x = y = 5 um, to 12 um); planeWave measures them all
#   (bench/blast/analysis/incidentWindow.py CASE --foot 51e6: the echo's
#   foot along the lines; docs/results/blast3D.md, "What spreads the
#   echo in the cell (branch echo49)"). Not with FITPROBES=1 (not tried:
#   two appended functions blocks)
#
# While cellBlastFoam runs, the load average is sampled every 15 s into
# DIR/quarter3D/log.load (printed as its range at the end).
#
# Prints: water cells (checkMesh), time steps, the time step before the
# arrival, coupling passes, cellBlastFoam's CPU split of the time loop
# (rank 0; on N ranks also the largest of each part over the ranks and
# every rank's split),
# wall time and peak resident memory of the run (/usr/bin/time -v: the
# largest of the processes it waited for, i.e. one rank), and
# planeWave's measures (postProcessing/planeWave/0/measures.dat,
# solidMeasures.dat; on N ranks too since branch q3dG: planeWave reads
# the master's probe files in the case, no reconstructPar needed).
set -euo pipefail
[ $# -ge 2 ] || { sed -n 2,50p "$0"; exit 1; }
dir=$1; np=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
[ ! -e "$dir" ] || { echo "inflow3D.sh: $dir exists" >&2; exit 1; }
case ${MEMBRANE:-} in
''|water) ;;
*) echo "inflow3D.sh: MEMBRANE=$MEMBRANE: the only value is water" >&2
   exit 1 ;;
esac
c=$dir/quarter3D
python3 -m neuronFsi.scratch "$root/tutorials/blast/quarter3D" "$c" \
    0.orig constant system Allrun --ignore polyMesh '*.msh' inflowWave cellDecomposition
cd "$c"
if [ -n "${MAXCO:-}" ]
then
    foamDictionary -entry maxCo -set "$MAXCO" system/controlDict > /dev/null
    echo "== maxCo $(foamDictionary -entry maxCo -value system/controlDict)"
fi
if [ -n "${WATERVISCOSITY:-}" ]
then
    python3 -c "import math, sys
try:
    mu = float(sys.argv[1])
except ValueError:
    mu = float('nan')
sys.exit(0 if math.isfinite(mu) and mu >= 0 else 1)" "$WATERVISCOSITY" || {
        echo "inflow3D.sh: WATERVISCOSITY=$WATERVISCOSITY is outside the" \
            "valid range [0, inf) Pa s (a finite number)" >&2; exit 1; }
    foamDictionary -entry riemann/viscous -set true system/fvSolution > /dev/null
    foamDictionary -entry riemann/mu -set "$WATERVISCOSITY" system/fvSolution > /dev/null
    echo "== WATERVISCOSITY: riemann { viscous $(foamDictionary -entry riemann/viscous -value system/fvSolution); mu $(foamDictionary -entry riemann/mu -value system/fvSolution); } in system/fvSolution"
fi
npOpt=()
[ "$np" -le 1 ] || npOpt=(-np "$np")
echo "== $(date -u '+%F %H:%M UTC'), commit $(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet HEAD -- src applications tutorials/blast bench/blast || echo ' (with uncommitted changes)'), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "== ./Allrun -noRun -noPlots ${npOpt[*]} $*"
PROJECT_DIR=$root ./Allrun -noRun -noPlots "${npOpt[@]}" "$@" > log.prepare 2>&1 \
    || { tail -20 log.prepare; exit 1; }
grep '^Pulse' log.prepare || true
if [ "${MEMBRANE:-}" = water ]
then
    python3 -m neuronFsi.membraneLaw water constant/solidProperties
    echo "== MEMBRANE=water: the membrane's law in constant/solidProperties:" \
        "$(grep -A2 '^    membrane' constant/solidProperties | tail -1 | tr -s ' ')"
fi
if [ "${FITPROBES:-0}" = 1 ]
then
    locations=$(foamDictionary -entry functions/fluidProbes/probeLocations \
        -value system/controlDict)
    cat >> system/controlDict <<EOF

// inflow3D.sh FITPROBES=1: fluidProbes' locations sampled by the linear fit
functions
{
    fluidProbesFit
    {
        type            movingMeshProbes;
        libs            ("libfsi.so");
        writeControl    timeStep;
        writeInterval   1;
        fields          (p);
        interpolationScheme cellLinearFit;
        probeLocations  $locations;
    }
}
EOF
    echo "== fluidProbesFit (cellLinearFit) at $locations"
fi
if [ "${LINEPROBES:-0}" = 1 ]
then
    # two z-lines through the cell and the water above it: the axis
    # (x = y = 0.1 um, as the axis water probe) and x = y = 5 um; solid
    # probes (material points, listed first: the interfaceProbe's three
    # come after them) every 0.25 um inside the cell, water probes
    # (movingMeshProbes, cellPoint) every 0.25 um above it
    /usr/bin/python3 - >> constant/solidProperties <<'PY'
import numpy as np
pts = [(1e-7, 1e-7, z) for z in np.arange(0.125e-6, 7.9e-6, 0.25e-6)]
pts += [(5e-6, 5e-6, z) for z in np.arange(0.125e-6, 4.0e-6, 0.25e-6)]
print("\n// inflow3D.sh LINEPROBES=1: the axis and x = y = 5 um in the cell")
print("probes (%s);" % " ".join("(%.6g %.6g %.6g)" % p for p in pts))
PY
    lines=$(/usr/bin/python3 -c '
import numpy as np
pts = [(1e-7, 1e-7, z) for z in np.arange(8.0e-6, 12.01e-6, 0.25e-6)]
pts += [(5e-6, 5e-6, z) for z in np.arange(4.5e-6, 12.01e-6, 0.25e-6)]
print("(%s)" % " ".join("(%.6g %.6g %.6g)" % p for p in pts))')
    cat >> system/controlDict <<EOF

// inflow3D.sh LINEPROBES=1: the axis and x = y = 5 um in the water above
functions
{
    echoLines
    {
        type            movingMeshProbes;
        libs            ("libfsi.so");
        writeControl    timeStep;
        writeInterval   1;
        fields          (p);
        probeLocations  $lines;
    }
}
EOF
    echo "== LINEPROBES=1: solid probes on the two lines (constant/solidProperties), water probes echoLines"
fi
niceness=${NICENESS:-10}
(
    while true
    do
        echo "$(date -u +%T) $(cut -d' ' -f1-3 /proc/loadavg)" >> log.load
        sleep 15
    done
) &
sampler=$!
trap 'kill $sampler 2> /dev/null || true' EXIT
if [ "$np" -le 1 ]
then
    echo "== nice -n $niceness /usr/bin/time -v cellBlastFoam"
    nice -n "$niceness" /usr/bin/time -v -o log.time cellBlastFoam \
        > log.cellBlastFoam 2>&1
else
    echo "== nice -n $niceness /usr/bin/time -v mpirun -np $np --bind-to none cellBlastFoam -parallel"
    nice -n "$niceness" /usr/bin/time -v -o log.time mpirun -np "$np" \
        --bind-to none cellBlastFoam -parallel > log.cellBlastFoam 2>&1
fi
kill $sampler 2> /dev/null || true
echo "load average (1 min) during the run, every 15 s: $(awk '{print $2}' log.load | sort -g | sed -n '1p;$p' | paste -sd- ), mean $(awk '{s += $2} END {printf "%.1f", s/NR}' log.load)"
echo "water cells: $(awk '/^ *cells:/ {print $2}' log.checkMesh)"
echo "time steps: $(grep -c '^Time =' log.cellBlastFoam)," \
    "first steps' deltaT: $(awk '/^deltaT/ {print $3}' log.cellBlastFoam | sed -n 200p) s (step 200)"
grep -E "^(CPU time of the time loop|    largest over|    rank [0-9]+: time loop|FSI interface energy|FSI coupling [A-Za-z]+:)" \
    log.cellBlastFoam | tail -$((4 + (np > 1 ? np : 0)))
echo "wall (time -v): $(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' log.time)," \
    "peak RSS $(awk -F': ' '/Maximum resident/ {printf "%.0f MB", $2/1024}' log.time)," \
    "load at the end $(cut -d' ' -f1-3 /proc/loadavg)"
echo "ExecutionTime/ClockTime: $(grep '^ExecutionTime' log.cellBlastFoam | tail -1)"
# On N ranks too: the probes' files are the master's, in the case's own
# postProcessing/ (no reconstructPar needed), 0/p is the undecomposed one
Z=$(foamDictionary -entry boundaryField/top/columnHeight -value 0/p 2>/dev/null \
    || foamDictionary -entry fluid/boxSize -value system/cellMeshDict)
echo "== planeWave -Z $Z -dz 50e-9 (the tutorial's plots stage)"
/usr/bin/time -v -o log.time.planeWave planeWave -Z "$Z" -dz 50e-9 \
    > log.planeWave 2>&1 || { tail -5 log.planeWave; exit 1; }
cat postProcessing/planeWave/0/measures.dat \
    postProcessing/planeWave/0/solidMeasures.dat
echo "case: $c"
