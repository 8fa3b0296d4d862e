#!/bin/bash
# i20 (class 5/4, the restart state at the law's edges, -acceptEdited): bd's 2e-09 with one cell's (cell 5) conservative
# state edited, each from a fresh copy, restarted with -acceptEdited to 3e-9: rho 0.95, 0.85, 0.75, 0.6 and 0.3 x rho0 with
# rhoE scaled likewise (e kept) (the water stretched towards and beyond the tension where its Mie-Grueneisen sound speed vanishes,
# -264 MPa), rho 1e300, rho 4.9e-324 (a denormal), rhoE -1e12 (e far below the law's domain), rhoE = 0.5 rho |U|^2 exactly
# (e = 0). Each: refused naming the time, the cell, rho/rhoU/rhoE and why (outside the law's domain), or run (exit 0) with
# finite logs; never a floating-point exception (exit 136), a NaN in a log, or a hang.
. "$(dirname "$0")/../lib.sh"
bd; echo "   2e-09 holds: $(ls 2e-09 | tr '\n' ' ')"; cd $W; mv blast b0
one() { rm -rf $W/blast; cp -a $W/b0 $W/blast; cd $W/blast; rs; }
nanLogs() { echo "   NaN/inf rows: $(grep -a -l -i -w 'nan\|inf\|-nan\|-inf' postProcessing/*/*/*.dat postProcessing/*/*/* 2>/dev/null | tr '\n' ' ')"; }
for f in 0.95 0.85 0.75 0.6 0.3; do one; fset 2e-09/rho internal 5 x$f; fset 2e-09/rhoE internal 5 x$f > /dev/null; tryt 300 "rho x$f" cellBlastFoam -acceptEdited; nanLogs; done
one; fset 2e-09/rho internal 5 1e300; tryt 300 "rho 1e300" cellBlastFoam -acceptEdited; nanLogs
one; fset 2e-09/rho internal 5 4.9e-324; tryt 300 "rho 4.9e-324" cellBlastFoam -acceptEdited; nanLogs
one; fset 2e-09/rhoE internal 5 -1e12; tryt 300 "rhoE -1e12" cellBlastFoam -acceptEdited; nanLogs
one; fset 2e-09/rhoU internal 5 0 0 0; fset 2e-09/rhoE internal 5 0; tryt 300 "rhoU 0, rhoE 0 (e = 0)" cellBlastFoam -acceptEdited; nanLogs
