#!/bin/bash
# cellBlastFoam on 2 MPI ranks (issue 5: "the fluid in parallel giving the
# same probe results as serial"; issue 8: serial and parallel agree, a
# parallel run killed and continued ends as the uninterrupted one).
# The fluid is decomposed, the solid is whole on every rank
# (src/fsi/globalInterfacePatch.H).
#   1. The axisymmetric preview on the short column (shortColumn.sh, to
#      16 ns, a write every 25 steps: 9 of its 225 with maxCo 0.9),
#      decomposed by hand at y = 4 um so that the processor boundary
#      cuts the cell's interface (both ranks hold interface faces and
#      share interface points): 2 ranks against
#      serial, every step of the coupling log (time, dt, iterations exact),
#      the solid probes, the interface maxima and every dataset of
#      solid/solid.h5 within 1e-9 of each column's largest magnitude
#      (compareRestart.py; the logs carry 10 digits), and the water
#      probes' pressure (fluidProbes, cellPoint) too: a probe beside the
#      cell at the processor plane samples the same point on 1 and 2
#      ranks (scaleFreeCellPointWeight; OpenFOAM's cellPointWeight took
#      the cell's first tetrahedron's centroid, which depends on the
#      cell's face order, so on the decomposition).
#   2. The same decomposed case killed (SIGKILL of both ranks and mpirun)
#      after 3 committed writes, continued from the latest time, stopped by
#      SIGTERM after 5, continued to the end: logs and solid.h5 bitwise
#      equal to the uninterrupted 2-rank run, the last time's processor
#      fields byte-equal.
#   3. The 3D quarter with the tetrahedral water (Allrun -tet; the
#      earlier smoke case's meshes, 20 um box, to 9.5 ns, through the
#      pulse's arrival at the cell top),
#      simple decomposition (2 1 1) at x = 5 um through the cell: 2 ranks
#      against serial as in 1 (the water probes too).
#   4. The preview shortened by its characteristic inflow (Allrun -inflow
#      14e-6 on a 30 um column, to 24 ns: the pulse through the top at
#      14 um and onto the cell), decomposed at y = 4 um as in 1: the top
#      patch is on one rank only (the other holds none of its faces);
#      2 ranks against serial as in 1 (the water probes too).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib/restartTools.sh"
. "$here/../lib/splitAtPlane.sh"
compare=$here/compareRestart.py

# decompose DIR NAME: decomposePar in DIR; both ranks must hold faces of
# the FSI patch (printed)
decompose()
{
    local patch r n
    (cd "$1" && decomposePar > log.decompose 2>&1) \
        || { tail "$1/log.decompose"; exit 1; }
    patch=$(foamDictionary -entry interface/fluidPatch -value \
        "$1/constant/fsiProperties")
    echo -n "$2: interface faces per rank:"
    for r in 0 1
    do
        n=$(foamDictionary -entry entry0/$patch/nFaces -value \
            "$1/processor$r/constant/polyMesh/boundary")
        echo -n " $n"
        [ "$n" -gt 0 ] || { echo; echo "FAIL: rank $r has none"; exit 1; }
    done
    echo
}

# runParallel DIR LOG: cellBlastFoam on 2 ranks in DIR
runParallel()
{
    (cd "$1" && mpirun -np 2 cellBlastFoam -parallel > "$2" 2>&1) \
        || { tail -20 "$1/$2"; exit 1; }
}

# 1. Axisymmetric: serial against 2 ranks
bash "$here/shortColumn.sh" "$work/serial" writeControl timeStep \
    writeInterval 25
serial=$work/serial/axisymmetricPreview
# A water probe beside the cell next to the processor plane y = 4 um
# (its tetrahedron's points on the plane: movingMeshProbes' cellPoint
# from the ranks' sums there, localCellPoint::coupledValues), and the
# one 2.1 um above the cell
foamDictionary -entry functions/fluidProbes/probeLocations \
    -set "((12e-6 4.05e-6 0) (1e-7 10e-6 0))" \
    "$serial/system/controlDict" > /dev/null
cp -r "$work/serial" "$work/parallel"
par=$work/parallel/axisymmetricPreview
splitAtPlane "$par" y 4e-6
decompose "$par" axisymmetric
# Every cellPoint sample of the 2-rank run compared with OpenFOAM's
# whole-field interpolation in the same tetrahedra to the last bit (a
# difference stops the run)
printf 'DebugSwitches\n{\n    movingMeshProbes 1;\n}\n' \
    >> "$par/system/controlDict"
cp -r "$work/parallel" "$work/killed"
killed=$work/killed/axisymmetricPreview
(cd "$serial" && cellBlastFoam > log.cellBlastFoam 2>&1) \
    || { tail -20 "$serial/log.cellBlastFoam"; exit 1; }
runParallel "$par" log.cellBlastFoam
n=$(grep -c "processor points: yes), the same bits" "$par/log.cellBlastFoam" \
    || true)
[ "$n" -gt 0 ] || { echo "FAIL: no probe sampled at processor points"; exit 1; }
echo "movingMeshProbes on 2 ranks: $n samples with processor points," \
    "the same bits as the whole-field interpolation"
/usr/bin/python3 "$compare" "$serial" "$par" --tol 1e-9 --h5 --fluid

# 2. The 2-rank run killed and continued
committed()
{
    ls -d "$killed"/processor1/*/.writeCommitted 2> /dev/null | wc -l
}
foamDictionary -entry startFrom -set latestTime \
    "$killed/system/controlDict" > /dev/null
(
    cd "$killed"
    mpirun -np 2 cellBlastFoam -parallel > log.first 2>&1 &
    pid=$!
    until [ "$(committed)" -ge 3 ]
    do
        kill -0 $pid 2> /dev/null \
            || { echo "FAIL: ended before 3 writes"; tail log.first; exit 1; }
        sleep 0.01
    done
    pkill -KILL -P $pid || true
    kill -KILL $pid 2> /dev/null || true
    wait $pid 2> /dev/null || true
    echo "SIGKILL of the ranks after $(committed) committed writes"
    runUntil TERM "[ \$(committed) -ge 5 ]" log.second \
        mpirun -np 2 cellBlastFoam -parallel
    grep -q "Solid: restarted from" log.second
    echo "SIGTERM after $(committed) committed writes"
    mpirun -np 2 cellBlastFoam -parallel > log.restart 2>&1 \
        || { tail -20 log.restart; exit 1; }
    grep -q "Solid: restarted from" log.restart
)
/usr/bin/python3 "$compare" "$par" "$killed" --bitwise --h5
last=$(foamListTimes -case "$par" -processor -latestTime | tail -1)
for r in 0 1
do
    sameFiles "$par/processor$r/$last" "$killed/processor$r/$last" \
        p U T rho rhoU rhoE polyMesh/points uniform/solidState \
        uniform/fsiState
done
echo "parallel restart: logs, solid.h5 and the fields of t = $last s bitwise"

# 3. The 3D quarter: serial against 2 ranks
q=$work/q3D/quarter3D
python3 -m neuronFsi.scratch "$root/tutorials/blast/quarter3D" "$q" \
    0.orig constant system Allrun --ignore polyMesh '*.msh'
cp "$root/tutorials/blast/plotBlast.py" "$work/q3D/"
# to 12 ns: the pulse reaches the probe (the scaled nucleus's interface
# point, z = 4.1 um) at about 10.8 ns in the 20 um box
(cd "$q" && PROJECT_DIR=$root ./Allrun -tet -box 20e-6 -h 0.6e-6 -far 2e-6 \
    -growth 5e-6 -cell 1.4e-6 -endTime 1.2e-8 -noPlots -noRun \
    > log.prepare 2>&1) || { tail -20 "$q/log.prepare"; exit 1; }
for e in writeControl:timeStep writeInterval:200
do
    foamDictionary -entry "${e%%:*}" -set "${e#*:}" \
        "$q/system/controlDict" > /dev/null
done
cp -r "$work/q3D" "$work/q3Dpar"
qpar=$work/q3Dpar/quarter3D
decompose "$qpar" "3D quarter"
(cd "$q" && cellBlastFoam > log.cellBlastFoam 2>&1) \
    || { tail -20 "$q/log.cellBlastFoam"; exit 1; }
runParallel "$qpar" log.cellBlastFoam
/usr/bin/python3 "$compare" "$q" "$qpar" --tol 1e-9 --h5 --pulse 1e6 \
    --fluid
# 4. The shortened preview (planeWaveInflow top): serial against 2 ranks
bash "$here/runPreview.sh" "$work/inflow" -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 \
    -Z 30e-6 -inflow 14e-6 -endTime 2.4e-8 -noPlots -noRun \
    > "$work/inflow.log" 2>&1 || { cat "$work/inflow.log"; exit 1; }
inS=$work/inflow/axisymmetricPreview
for e in writeControl:timeStep writeInterval:25
do
    foamDictionary -entry "${e%%:*}" -set "${e#*:}" \
        "$inS/system/controlDict" > /dev/null
done
cp -r "$work/inflow" "$work/inflowPar"
inP=$work/inflowPar/axisymmetricPreview
splitAtPlane "$inP" y 4e-6
decompose "$inP" "inflow preview"
(cd "$inS" && cellBlastFoam > log.cellBlastFoam 2>&1) \
    || { tail -20 "$inS/log.cellBlastFoam"; exit 1; }
runParallel "$inP" log.cellBlastFoam
/usr/bin/python3 "$compare" "$inS" "$inP" --tol 1e-9 --h5 --fluid
echo "cellBlastFoam: 2 ranks equal serial (axisymmetric, 3D quarter, and" \
    "the preview shortened by planeWaveInflow)"
