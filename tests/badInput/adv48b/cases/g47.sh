#!/bin/bash
# g47 (class 4, the uncertainty's correlation and steps at their edges) the one-point study with an uncertainty block (a) correlation 1.0000000000000002, (b) a parameter correlated with itself (cytoplasm.C10 cytoplasm.C10 0.5), (c) nan, (d) -1 (valid edge), (e) step 1e400, (f) checkStep -0, (g) step 0.2 and checkStep 0.20000000000000001 (the same double as step): each invalid one refused before any run naming uncertainty's entry, the value with its digits and the range; (d) accepted (killed after 40 s).
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
for c in "(a)|(cytoplasm.C10 nucleus.C10 1.0000000000000002)" "(b)|(cytoplasm.C10 cytoplasm.C10 0.5)" "(c)|(cytoplasm.C10 nucleus.C10 nan)" "(e)|(cytoplasm.C10 nucleus.C10 -0.6)|1e400" "(f)|(cytoplasm.C10 nucleus.C10 -0.6)|0.2|-0" "(g)|(cytoplasm.C10 nucleus.C10 -0.6)|0.2|0.20000000000000001" "(d)|(cytoplasm.C10 nucleus.C10 -1)"; do IFS='|' read -r l co st cs <<< "$c"
  cp ../d0 system/pulseStudyDict; uncBlock "(3e7 2e-9)" "$co" "$st" "$cs"; tryt 40 "$l correlation $co step ${st:-0.2} checkStep ${cs:-0.1}" pulseStudy; killIn $W; echo "   points: $(ls points 2>/dev/null | tr '\n' ' ')"; rm -rf points postProcessing; done
