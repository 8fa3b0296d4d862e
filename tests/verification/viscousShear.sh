#!/bin/bash
# The optional Newtonian viscous stress: a shear wave U_y = U0 sin(k x) in a
# periodic water column (tests/verification/viscousShearWave) decays as
# exp(-mu k^2 t / rho). After one e-folding time on 32 and 64 cells:
#  - the amplitude within 1 % of U0/e on 64 cells, the error falling at
#    least 3x from 32 to 64 cells (second order: 4x);
#  - total energy (internal + kinetic) conserved to 1e-6 of the initial
#    kinetic energy: the viscous work heats the water (energy equation).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for n in 32 64
do
    c="$work/n$n"
    cp -r "$(dirname "$0")/viscousShearWave" "$c"
    sed -i "s/^nCells .*/nCells  $n;/" "$c/system/blockMeshDict"
    /usr/bin/python3 - "$c" "$n" <<'PY'
import math, sys
case, n = sys.argv[1], int(sys.argv[2])
L, U0 = 10e-6, 1.0
k = 2*math.pi/L
vals = "\n".join(f"(0 {U0*math.sin(k*(i + 0.5)*L/n):.17g} 0)" for i in range(n))
t = open(f"{case}/0/U.template").read()
t = t.replace("internalField   uniform (0 0 0);    // replaced by the shear wave",
              f"internalField   nonuniform List<vector>\n{n}\n(\n{vals}\n)\n;")
open(f"{case}/0/U", "w").write(t)
PY
    ( cd "$c" && blockMesh > log.blockMesh && rhoRiemannFoam > log.solver )
done
/usr/bin/python3 - "$work" <<'PY'
import math, os, re, sys
import numpy as np
from neuronFsi.foamField import internalField
work = sys.argv[1]
L, U0, rho0, Cv, T0, mu = 10e-6, 1.0, 1000.0, 4184.0, 293.15, 1.0
k = 2*math.pi/L
errors = {}
ok = True
for n in (32, 64):
    c = os.path.join(work, f"n{n}")
    t = max((d for d in os.listdir(c) if re.fullmatch(r"[0-9.e+-]+", d) and float(d) > 0), key=float)
    U = internalField(f"{c}/{t}/U"); rho = internalField(f"{c}/{t}/rho"); T = internalField(f"{c}/{t}/T")
    x = (np.arange(n) + 0.5)*L/n
    A = 2/n*np.sum(U[:, 1]*np.sin(k*x))
    exact = U0*math.exp(-mu*k*k*float(t)/rho0)
    errors[n] = abs(A/exact - 1)
    E1 = np.sum(rho*(Cv*(T - T0) + 0.5*np.sum(U**2, axis=1)))*L/n
    # initial: rho0 at p = 0, e = 0, kinetic only
    x0 = (np.arange(n) + 0.5)*L/n
    E0 = np.sum(rho0*0.5*(U0*np.sin(k*x0))**2)*L/n
    dE = abs(E1 - E0)/E0
    print(f"viscousShear: {n} cells, t = {t} s: amplitude {A:.6f} m/s, exact {exact:.6f} m/s, relative error {errors[n]:.2e}; energy change {dE:.2e} of the initial kinetic energy")
    ok &= dE <= 1e-6
ratio = errors[32]/errors[64]
print(f"viscousShear: error ratio 32 -> 64 cells {ratio:.2f} (>= 3)")
ok &= errors[64] <= 0.01 and ratio >= 3
print("viscousShear: " + ("passed" if ok else "FAILED"))
sys.exit(0 if ok else 1)
PY
