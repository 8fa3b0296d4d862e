#!/bin/bash
# Stability and accuracy table of the coupling schemes over impedance
# ratios Z_s/Z_f = 0.1, 0.3, 1, 3, 10 (issue 5, "which schemes stay
# stable"; issue 8, "coupling with impedance ratios from 0.1 to 10"):
#  1. weak pulse (1 MPa, linear acoustics), the ratio set by the solid's
#     density, then by its sound speed (impedanceRun.sh);
#  2. the 50 MPa pulse of pulseLayer (nonlinear; interface pressure
#     against the exact Riemann value of analysePulseLayer.py), the ratio
#     set by the density (runPulseLayer.sh, until 45 ns).
# One result line per run on stdout. Not a CI test (36 + 20 runs, about
# 10 min on one core); results in docs/results/blastCoupling.md.
dir=$(cd "$(dirname "$0")" && pwd)
for by in rho c
do
    ratios="0.1 0.3 1 3 10"
    [ $by = c ] && ratios="0.1 0.3 3 10"    # c at ratio 1 is the rho run
    for ratio in $ratios
    do
        for scheme in explicitStaggered aitken IQNILS robin
        do
            bash "$dir/impedanceRun.sh" $scheme $ratio $by 2>&1 | tail -1
        done
    done
done
for rho0 in 100 300 1000 3000 10000
do
    for scheme in explicitStaggered aitken IQNILS robin
    do
        bash "$dir/runPulseLayer.sh" $scheme $rho0 4.5e-8 2>&1 | tail -1
    done
done
