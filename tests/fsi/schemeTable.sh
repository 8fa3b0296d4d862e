#!/bin/bash
# Stability table of the coupling schemes for impedance ratios
# Z_s/Z_f = 0.1, 1, 10 (solid rho0 = 100, 1000, 10000 kg/m^3, water's C0
# and s) on the pulseLayer case until the pulse has crossed the interface
# (45 ns). Not a CI test (about 1-2 min); results in docs/userGuide/fsi.md.
dir=$(cd "$(dirname "$0")" && pwd)
for rho0 in 100 1000 10000
do
    for scheme in explicitStaggered aitken IQNILS robin
    do
        bash "$dir/runPulseLayer.sh" $scheme $rho0 4.5e-8 2>&1 | tail -1
    done
done
