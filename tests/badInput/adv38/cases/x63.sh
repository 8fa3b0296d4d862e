#!/bin/bash
# x63: thermophysicalProperties (the water) at edges never tried in a fresh blast run: s 0 (no Hugoniot slope), Gamma0 0, Gamma0 3 (large), Cv 1 (1 J/kg/K), p0/T0 at the bound: accepted and sensible, or refused naming entry and range?
. "$(dirname "$0")/../lib.sh"
blast; grep -a -v "^\s*//" constant/thermophysicalProperties | grep -a "C0\|s \|Gamma0\|Cv\|T0\|rho0\|p0" | head -8
each constant/thermophysicalProperties "s 0" "Gamma0 0" "Gamma0 3" "Cv 1" -- cellBlastFoam
