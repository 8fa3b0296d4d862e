#!/bin/bash
# membraneWaterLaw.sh DIR [PULSE] [Allrun options]: the axisymmetric preview
# (a copy in DIR, tests/blast/runPreview.sh) with the membrane given water's
# Mie-Grueneisen law instead of its quadratic law (paper eq. 2), run to
# 150 ns, then planeWave -check (DIR/axisymmetricPreview/log.planeWaveCheck).
# Measures how much of the echo near the cell's top the membrane's law
# makes (docs/results/blastPlaneWave.md, "The default at x0.7"). Not a test.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
dir=$1; pulse=${2:-1e-8}; shift; [ $# -gt 0 ] && shift
bash "$here/../../tests/blast/runPreview.sh" "$dir" -pulse "$pulse" \
    -noPlots -noVTK -noRun "$@" > "$dir.log" 2>&1
cd "$dir/axisymmetricPreview"
/usr/bin/python3 - <<'PY'
s = open("constant/solidProperties").read()
old = """volumetric  quadratic;  // Psi_vol = (J - 1)^2/d0 (paper eq. 2)
        d0          9.5125e-10; // 2/K [1/Pa], K = 1000 x 1450^2 Pa"""
if old not in s:
    raise SystemExit("membraneWaterLaw.sh: the membrane's quadratic law "
                     "not found in constant/solidProperties")
s = s.replace(old, "volumetric  mieGruneisen;\n"
              "        C0 1450; s 1.99; Gamma0 0.1; Cv 4184; T0 293.15;")
open("constant/solidProperties", "w").write(s)
PY
cellBlastFoam > log.cellBlastFoam 2>&1
status=0
planeWave -case . -check > log.planeWaveCheck 2>&1 || status=$?
grep -v "^#" log.planeWaveCheck
exit $status
