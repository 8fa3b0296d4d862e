#!/bin/bash
# f21 (class 4, a range's bound and one ulp beyond): pulseStudy with overpressure (1e9 1.0000000000000002e9) (1 GPa is the bound of (0, 1e9] Pa): refused before anything runs naming overpressure, the value beyond and the range; no points/ folder. (b) (1e9) alone with nProcs 2 (above the grid's 1 point): refused naming nProcs - the 1e9 itself accepted.
. "$(dirname "$0")/../lib.sh"
study; setStudy overpressure "(1e9 1.0000000000000002e9)"
tryt 60 "(a) 1e9 and one ulp beyond" pulseStudy; ls postProcessing/pulseStudy 2>/dev/null | tr '\n' ' '; echo
setStudy overpressure "(1e9)"; setStudy nProcs 2; tryt 60 "(b) 1e9 with nProcs 2" pulseStudy; ls postProcessing/pulseStudy 2>/dev/null | tr '\n' ' '; echo
