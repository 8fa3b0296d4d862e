#!/bin/bash
# (corrected after its first run: my parse of the estimate failed, N was empty)
# f47 (class 6, planeWave -maxSteps at the estimate): planeWave on the finished preview with -maxSteps 1: refused naming the estimate N; -maxSteps N: accepted (the 1D column runs); -maxSteps N-1: refused; -maxSteps 1.5, 0 and 4.9e-324: refused naming -maxSteps and its range.
. "$(dirname "$0")/../lib.sh"
bd; tryt 60 "-maxSteps 1" planeWave -maxSteps 1; N=$(grep -a -o 'about [0-9]\+' $W/try.log | grep -o '[0-9]\+' | head -1); echo "   N=$N (the estimate the message gives)"
for m in $N $((N - 1)) 1.5 0 4.9e-324; do tryt 200 "-maxSteps $m" planeWave -maxSteps $m; done
