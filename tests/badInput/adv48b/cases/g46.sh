#!/bin/bash
# g46 (class 4, numberText: a pulse a few ulps off the grid's point) the one-point study (study: 30 MPa, 2 ns) with an uncertainty block whose pulse is (30000000.000000004 2e-9) (one ulp above 3e7: another double): refused before anything runs, naming uncertainty/pulses, the value printed with the digits that show it differs from the grid's 3e7 (never "30000000 is not a point of the grid (30000000)") and the grid's points; (b) (3e7 2.0000000000000004e-9) the same for the duration.
. "$(dirname "$0")/../lib.sh"
uncBlock() { cat >> system/pulseStudyDict <<U
uncertainty
{
    pulses      ($1);
    variants    { table { materials table; } }
    about       base;
    parameters
    {
        cytoplasm.C10 { interval (0.131 0.245) [Pa]; log yes; }
        nucleus.C10   { interval (1.58 4.08) [Pa]; log yes; }
    }
    correlation ($2);
    difference  central;
    step        ${3:-0.2};
    checkStep   ${4:-0.1};
}
U
}
study; cp system/pulseStudyDict ../d0
uncBlock "(30000000.000000004 2e-9)" "(cytoplasm.C10 nucleus.C10 -0.60)"; tryt 60 "(a) pulse 30000000.000000004" pulseStudy; grep -a -i -m2 'pulse\|grid' $W/try.log | cut -c1-300; killIn $W; ls -d points 2>/dev/null
cp ../d0 system/pulseStudyDict; uncBlock "(3e7 2.0000000000000004e-9)" "(cytoplasm.C10 nucleus.C10 -0.60)"; tryt 60 "(b) duration 2.0000000000000004e-9" pulseStudy; grep -a -i -m2 'pulse\|grid' $W/try.log | cut -c1-300; killIn $W; ls -d points 2>/dev/null
