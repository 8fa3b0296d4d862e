#!/bin/bash
# CASETIMEOUT=900
# n03 (new, class 4/5: the solid probes of constant/solidProperties, docs/userGuide/fsi.md "Solid probes", and the balls of
# bench/blast/ballProbes.override): the short preview (sb) with constant/solidProperties.allrun holding: (a) a list probe
# outside the solid (1e-3 1e-3 0); (b) a named probe on the cytoplasm-nucleus interface without region (the Fig. 10 point
# of ballProbes.override, 3.852e-6 4.108e-6); (c) region cytoplasma (misspelt); (d) region nucleus for a point inside the
# cytoplasm; (e) balls of radius 1e-3 (beyond the cell), 1e-12 and 1e-300 (below any sub-cell: a volume of 0?), 1e-9;
# (f) a ball whose centre is outside its region but within R of it; (g) the same name twice, probes (), probes {};
# (h) interfaceProbe regions reversed, (cytoplasm cytoplasm), side middle, heightFraction 1e-9. Each: refused at the start
# naming the file, the entry and the point (the docs' rule), or run with finite values in solidProbes.dat; never a nan
# or inf written as a probe's value without a word, never a signal.
. "$(dirname "$0")/../lib.sh"
res() { local f=$(find postProcessing -name solidProbes.dat 2>/dev/null | head -1); echo "   sig: $(sig) | End: $(grep -a -c '^End' $W/try.log) | msg: $(msg 5 | cut -c1-380)"
  [ -n "$f" ] && echo "   solidProbes.dat: $(grep -c '^#' $f) header lines | nan/inf in rows: $(grep -v '^#' $f | grep -c -i 'nan\|inf') | last row: $(tail -1 $f | tr -s ' ' | cut -c1-160)" && grep -a '^#.*\(ball\|radius\|volume\)' $f | head -2 | cut -c1-200 | sed 's/^/   header: /'; }
sb; cp -a . ../b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
sp() { printf '%s\n' "$2" > constant/solidProperties.allrun; tryt 150 "$1" cellBlastFoam; res; back; }
sp "(a) probes ((1e-3 1e-3 0))" 'probes ((1e-3 1e-3 0));'
sp "(b) a named probe on the interface, no region" 'probes { f10 { point (3.852e-6 4.108e-6 0); } }'
sp "(c) region cytoplasma" 'probes { c { point (4.85e-6 4.108e-6 0); region cytoplasma; } }'
sp "(d) region nucleus for a cytoplasm point" 'probes { c { point (4.85e-6 4.108e-6 0); region nucleus; } }'
for r in 1e-3 1e-12 1e-300 1e-9; do sp "(e) a ball of radius $r in the cytoplasm" "probes { b { point (4.85e-6 4.108e-6 0); region cytoplasm; radius $r; } }"; done
sp "(f) a ball centred in the nucleus, region cytoplasm, radius 0.5e-6 (reaches the cytoplasm)" 'probes { b { point (3.6e-6 4.108e-6 0); region cytoplasm; radius 0.5e-6; } }'
sp "(g) the same name twice" 'probes { c { point (4.85e-6 4.108e-6 0); region cytoplasm; } c { point (4.6e-6 4.108e-6 0); region cytoplasm; } }'
sp "(g) probes ()" 'probes ();'
sp "(g) probes {}" 'probes { }'
sp "(h) interfaceProbe regions (nucleus cytoplasm)" 'interfaceProbe { regions (nucleus cytoplasm); heightFraction 0.75; side outer; }'
sp "(h) interfaceProbe regions (cytoplasm cytoplasm)" 'interfaceProbe { regions (cytoplasm cytoplasm); heightFraction 0.75; side outer; }'
sp "(h) interfaceProbe side middle" 'interfaceProbe { regions (cytoplasm nucleus); heightFraction 0.75; side middle; }'
sp "(h) interfaceProbe heightFraction 1e-9" 'interfaceProbe { regions (cytoplasm nucleus); heightFraction 1e-9; side outer; }'
sp "(h) interfaceProbe regions (membrane nucleus) (no shared interface)" 'interfaceProbe { regions (membrane nucleus); heightFraction 0.75; side outer; }'
