#!/bin/bash
# solidVariant.sh DIR INTEGRATION KAPPA [Allrun options]: the blast preview
# (tests/blast/runPreview.sh, to its 150 ns) with the solid's
# volumetricIntegration (element | gaussPoints) and hourglassViscosity
# KAPPA, then planeWave -check against the exact answer (pressure and
# the uniaxial-strain von Mises, strain and rest; its table is
# DIR/axisymmetricPreview/postProcessing/planeWave/0/solidMeasures.dat).
# Prints cellBlastFoam's CPU time and peak memory and the failed bounds.
# SOLID_PROBES (environment, optional): a probes { } dictionary appended to
# constant/solidProperties (extra Lagrangian probes, docs/userGuide/fsi.md).
# SHEAR_VISCOSITY (environment, default 0): solidProperties shearViscosity
# (the deviatoric numerical viscosity beta, solid::ExplicitSolver).
# SHEAR_VISCOSITY_FILTER (environment, default no): solidProperties
# shearViscosityFilter (yes: its filtered form). These defaults are the
# solid without the viscosity (the tutorial's default before 2026-12-03),
# so that the commands documented before then reproduce; Allrun options
# (-shearViscosity, -shearViscosityFilter) override them.
# Not a test (issue 17: docs/results/blastPlaneWave.md, "The solid's
# formulation and the cell's mesh"). Example:
#   bench/blast/solidVariant.sh /tmp/gp2 gaussPoints 0 -cell 0.25e-6 -h 0.125e-6
set -u
[ $# -ge 3 ] || { sed -n 2,17p "$0"; exit 1; }
dir=$1; integ=$2; kappa=$3; shift 3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
"$here/../../tests/blast/runPreview.sh" "$dir" -noRun "$@" > /dev/null \
    2>&1 || { echo "runPreview.sh $dir -noRun $* failed"; exit 1; }
cd "$dir/axisymmetricPreview"
foamDictionary constant/solidProperties -entry hourglassViscosity \
    -set "$kappa" > /dev/null
foamDictionary constant/solidProperties -entry volumetricIntegration \
    -set "$integ" > /dev/null
foamDictionary constant/solidProperties -entry shearViscosity \
    -set "${SHEAR_VISCOSITY:-0}" > /dev/null
foamDictionary constant/solidProperties -entry shearViscosityFilter \
    -set "${SHEAR_VISCOSITY_FILTER:-no}" > /dev/null
[ -z "${SOLID_PROBES:-}" ] \
    || printf '\nprobes\n{\n%s\n}\n' "$SOLID_PROBES" >> constant/solidProperties
grep -E "^(hourglassViscosity|volumetricIntegration|shearViscosity)" \
    constant/solidProperties
Z=$(grep -o -- "-Z [^ ]*" <<<"$*" | cut -d' ' -f2)
/usr/bin/time -f "cellBlastFoam: %U s CPU, %M KB peak" cellBlastFoam \
    > log.cellBlastFoam 2> time.log \
    || { tail -5 log.cellBlastFoam; cat time.log; exit 1; }
cat time.log
planeWave -Z "${Z:-100e-6}" -dz 50e-9 -check > log.planeWave 2>&1
echo "planeWave -check: exit $?"
grep -E "FAIL" log.planeWave
grep -v "^#" postProcessing/planeWave/0/solidMeasures.dat
# The solid's residual nodal speed at the last write, by radius
/usr/bin/python3 - <<'PY'
import numpy as np
from neuronFsi.solidResults import SolidResults
with SolidResults("solid/solid.h5") as s:
    X = s.mesh("coordinates")
    step = s.steps()[-1]
    v = np.linalg.norm(s.field(step, "velocity"), axis=1)
    r = X[:, 0]*1e6
    bands = [(0, 0.01), (0.01, 1), (1, 3), (3, 6), (6, 1e9)]
    print("nodal speed at %.4g ns, mean / largest [m/s] for r [um] in %s"
          % (s.time(step)*1e9, ", ".join(
              "[%g, %g): %.2g / %.2g" % (lo, min(hi, r.max()),
                                         v[(r >= lo) & (r < hi)].mean(),
                                         v[(r >= lo) & (r < hi)].max())
              for lo, hi in bands)))
PY
