#!/bin/bash
# The fluid of tutorials/blast/quarter3D alone (rhoRiemannFoam, the cell a
# rigid wall) on 2 MPI ranks gives the serial probe values: cellMesh's
# tetrahedral quarter water box (type tetrahedra, coarse: 1.5 um at the
# cell, 5 um far), 50 MPa on the top face, to 15 ns; the processor
# boundary is the plane z = 80 um (manual decomposition), which the pulse
# crosses at about 13 ns.
# Asserts max |p_2ranks - p_serial|/max|p| <= 1e-12 over every probe and
# time step (probes: the quarter3D fluid probes + one at z = 78 um, below
# the plane, reached at 14.6 ns) and
# over the pressure field at the end time.
# fluid3DParallel.sh [SCHEME [USCHEME]]: reconstruct(rho), reconstruct(U)
# and reconstruct(p) set to SCHEME (a multidimensional limiter of
# MUSCLReconstruction, BarthJespersen or venkatakrishnan: its min/max takes
# the processor neighbours' values); default: the tutorial's MUSCL/MUSCLV.
# USCHEME, if given, replaces SCHEME for reconstruct(U) (e.g.
# "normalTangential MUSCL upwind": the face frame on the processor faces).
set -euo pipefail
scheme=${1:-}
uScheme=${2:-$scheme}
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../..
. "$root/etc/bashrc"
. "$here/../lib/splitAtPlane.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
src=$root/tutorials/blast/quarter3D
mkdir "$work/serial"
cp -r "$src"/{0.orig,constant,system} "$work/serial/"
cd "$work/serial"
rm -rf constant/polyMesh constant/*.msh constant/dynamicMeshDict \
    constant/fsiProperties constant/solidProperties
for e in fluid/type:tetrahedra fluid/nearSize:1.5e-6 fluid/farSize:5e-6 \
    nucleusSize:1e-6 cytoplasmSize:1e-6 membraneSize:0.8e-6 application:rhoRiemannFoam \
    endTime:1.5e-8 writeInterval:1.5e-8 writeFormat:ascii \
    writePrecision:17
do
    f=system/cellMeshDict
    case ${e%%:*} in application|endTime|writeInterval|writeFormat|writePrecision) f=system/controlDict ;; esac
    foamDictionary -entry "${e%%:*}" -set "${e#*:}" $f > /dev/null
done
foamDictionary -entry functions/fluidProbes/probeLocations \
    -set "((25e-6 25e-6 90e-6) (25e-6 25e-6 50e-6) (25e-6 25e-6 10e-6) (5e-6 5e-6 78e-6))" \
    system/controlDict > /dev/null
cellMesh > log.cellMesh 2>&1 || { tail log.cellMesh; exit 1; }
gmshToFoam constant/fluid.msh > log.gmshToFoam 2>&1
for p in symmetryX symmetryY; do
    foamDictionary -entry entry0/$p/type -set symmetryPlane constant/polyMesh/boundary > /dev/null
done
for p in cellInterface bottom sides; do
    foamDictionary -entry entry0/$p/type -set wall constant/polyMesh/boundary > /dev/null
done
# pointDisplacement belongs to the FSI run; the rigid wall U: slip
rm -f 0.orig/pointDisplacement
sed -i 's/cellInterface *{ type movingWallVelocity; value uniform (0 0 0); }/cellInterface   { type slip; }/' 0.orig/U
grep -q "cellInterface   { type slip; }" 0.orig/U
if [ -n "$scheme" ]
then
    for v in rho U p
    do
        s=$scheme
        [ $v = U ] && s=$uScheme
        foamDictionary -entry "interpolationSchemes/reconstruct($v)" \
            -set "$s" system/fvSchemes > /dev/null
    done
    grep -q "reconstruct(U) *$uScheme;" system/fvSchemes
fi
cp -r 0.orig 0
# processor 1: cells above z = 80 um
splitAtPlane . z 80e-6
cp -r "$work/serial" "$work/parallel"
rhoRiemannFoam > log.solver 2>&1 || { tail log.solver; exit 1; }
cd "$work/parallel"
decomposePar > log.decompose 2>&1 || { tail log.decompose; exit 1; }
mpirun -np 2 rhoRiemannFoam -parallel > log.solver 2>&1 || { tail log.solver; exit 1; }
reconstructPar -latestTime > log.reconstruct 2>&1
cd "$work"
/usr/bin/python3 - serial parallel "${scheme:-MUSCL}, U ${uScheme:-MUSCLV}" <<'PY'
import sys
import numpy as np
from neuronFsi.foamField import internalField
def probes(case):
    return np.loadtxt(f"{case}/postProcessing/fluidProbes/0/p", comments="#")
a, b = probes(sys.argv[1]), probes(sys.argv[2])
ok = a.shape == b.shape and np.allclose(a[:, 0], b[:, 0], rtol=1e-12, atol=0)
dp = np.max(np.abs(a[:, 1:] - b[:, 1:]))/np.max(np.abs(a[:, 1:])) if ok else np.inf
fa, fb = (internalField(f"{c}/1.5e-08/p") for c in sys.argv[1:3])
df = np.max(np.abs(fa - fb))/np.max(np.abs(fa))
peak = np.max(a[:, 1:], axis=0)/1e6
print(f"fluid3DParallel {sys.argv[3]}: {fa.size} cells, {len(a)} probe samples, probe peaks "
      f"{np.round(peak, 3)} MPa; max |p_2ranks - p_serial|/max|p|: probes "
      f"{dp:.3e} (<= 1e-12 required), field {df:.3e} (<= 1e-9 required)")
sys.exit(0 if ok and dp <= 1e-12 and df <= 1e-9 else 1)
PY
