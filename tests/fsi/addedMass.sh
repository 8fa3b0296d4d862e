#!/bin/bash
# Added-mass-prone implicit case: the pulseLayer problem with a light solid
# (rho0 = 100 kg/m^3, Z_s/Z_f = 0.1). The explicit staggered scheme must
# diverge there (step amplification 1 - 2 gamma, gamma = (Z_f/Z_s) c dt/h
# ~ 4.7), which shows the case is added-mass prone; IQN-ILS must converge
# in every step and transmit the exact interface pressure (transmitted
# shock against the water's reflected rarefaction) within 2 %.
set -euo pipefail
dir=$(cd "$(dirname "$0")" && pwd)
if bash "$dir/runPulseLayer.sh" explicitStaggered 100 4.5e-8 > /dev/null 2>&1
then
    echo "FAIL explicitStaggered did not diverge: the case is not added-mass prone"
    exit 1
fi
echo "explicitStaggered diverged, as expected"
out=$(bash "$dir/runPulseLayer.sh" IQNILS 100 4.5e-8)
echo "$out"
echo "$out" | tail -1 | tr ' ' '\n' | awk -F= '
    { gsub(/[a-zA-Z%]+$/, "", $2); v[$1] = $2 }
    END {
        ok = 1
        if (v["nonConverged"] != 0) { print "FAIL " v["nonConverged"] " steps not converged"; ok = 0 }
        if ((v["interface"] - v["interfaceExact"])^2 > (0.02*v["interfaceExact"])^2) { print "FAIL interface " v["interface"] " MPa vs " v["interfaceExact"]; ok = 0 }
        if (ok) print "addedMass: IQNILS converged, mean " v["meanIter"] " max " v["maxIter"] " iterations: passed"
        exit !ok
    }'
