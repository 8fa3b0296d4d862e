#!/bin/bash
# CASETIMEOUT=900
# m10 (fix19g's scan ranges, src/fsi/fsiRanges, varied over every row of its table): the short preview (sb) with one entry
# of constant/fsiProperties or constant/solidProperties set (through a .allrun file for coupling{}/interface{} entries
# it does not hold) to: 1e400 and 1e-320 (the scan: the entry's own range and unit), the value just beyond the range's
# edge (1 ulp past an open bound; the edge itself for an open one), a whole number beyond the label (2147483648,
# 9223372036854775808) for the counts (maxIter, reuse, solidSubcycles, pressureQuadrature, motionNearest). Each refused
# rc 1 naming the file, the entry, the value as written, the range and unit of fsiRanges.C's table (printed first);
# never a signal, never a wrapped count.
. "$(dirname "$0")/../lib.sh"
sed -n '/rows$/,/^    };/p' "$ROOT/src/fsi/fsiRanges/fsiRanges.C" | grep -o '{"[a-zA-Z/]*", "[a-zA-Z]*"}, {[^}]*}' | sed 's/^/   table: /'
sb; cp -a . ../b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
res() { echo "   sig: $(sig) | End: $(grep -a -c '^End' $W/try.log) | msg: $(msg 5 | cut -c1-420)"; }
fsi() { local sub=$1 k=$2 v=$3; printf '%s\n{\n    %s %s;\n}\n' $sub $k "$v" > constant/fsiProperties.allrun; tryt 90 "fsiProperties $sub/$k $v" cellBlastFoam; res; back; }
for kv in "maxIter 1e400 1e-320 0 0.5 2147483648 9223372036854775808" "tolerance 1e400 1e-320 0 0.10000000000000001 0.10000000000000002" "velocityScale 1e400 1e-320 0 -1e-300" \
  "initialRelaxation 1e400 1e-320 0 1.0000000000000002" "reuse 1e400 -1 2147483648" "solidSubcycles 1e400 0 1001 2147483648"; do set -- $kv; k=$1; shift; for v in "$@"; do fsi coupling $k $v; done; done
for kv in "mapTolerance 1e400 1e-320 0" "pressureQuadrature 1e400 0 17 2147483648" "motionDistance 1e400 1e-320 0" "motionNearest 1e400 0 2147483648 9223372036854775808"; do set -- $kv; k=$1; shift; for v in "$@"; do fsi interface $k $v; done; done
sol() { local k=$1 v=$2; hdr0 constant/solidProperties; sete constant/solidProperties $k "$v" > /dev/null || echo "$k $v;" >> constant/solidProperties; hdr constant/solidProperties | grep CHANGED; tryt 90 "solidProperties $k $v" cellBlastFoam; res; back; }
for kv in "explicitSafety 1e400 1e-320 0 1" "hourglassViscosity 1e400 1e-320 -1e-300 1" "shearViscosity 1e400 1 -0.1" "interfacePatchLength 1e400 1e-320 0"; do set -- $kv; k=$1; shift; for v in "$@"; do sol $k $v; done; done
for v in 1e400 1e-320 0 1; do sete constant/solidProperties heightFraction $v > /dev/null; tryt 90 "solidProperties interfaceProbe/heightFraction $v" cellBlastFoam; res; back; done
for v in 1e400 1e-320 1; do printf 'hourglassViscosityRegions\n{\n    nucleus %s;\n}\n' $v > constant/solidProperties.allrun; tryt 90 "solidProperties hourglassViscosityRegions/nucleus $v" cellBlastFoam; res; back; done
for v in 1e400 1e-320 -1e-9; do printf 'probes\n{\n    p1 { point (2e-6 7e-6 0); radius %s; }\n}\n' $v > constant/solidProperties.allrun; tryt 90 "solidProperties probes/p1/radius $v" cellBlastFoam; res; back; done
