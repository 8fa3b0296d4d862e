#!/bin/bash
# CASETIMEOUT=900
# h11 (class 4, adv47b f42/f46/f50 varied: a value one ulp outside the valid range that a refusal names, in other entries
# and tools): for each entry, 1e308 (or -1) gives the valid range in the refusal; then the bound itself (if closed:
# accepted, cut at 30 s) and the next double outside it: refused, printed with the digits that put it outside (never as
# the bound). Entries: sod controlDict maxCo and maxDeltaT; the preview's fsiProperties tolerance, mapTolerance,
# velocityScale, motionDistance; the smoke indentation's indenterProperties tolerance (with maxDepthIncrement 0.3e-6: is
# its tenth 3e-8 accepted?); cellMesh's membraneThickness. Then cellMesh maxElements at its estimate with cytoplasmSize 0.5e-6.
. "$(dirname "$0")/../lib.sh"
msg() { grep -a -m1 -A2 'FATAL\|[Ee]rror\|refused\|outside\|range' $W/try.log | grep -av '^ *$\|^-->\|From function\|^\[.\] *$' | head -2 | tr '\n' ' ' | tr -s ' ' | cut -c1-300; }
bound() { local file=$1 key=$2 cmd=$3; cp $file $W/orig; echo "== $key in $file ($cmd)"
  local r="" v; for v in 1e308 -1; do cp $W/orig $file; sete $file $key $v; timeout -s KILL 30 $cmd > $W/try.log 2>&1; r=$(grep -a -o "range [[(][^])]*[])]" $W/try.log | head -1); [ -n "$r" ] && break; done
  echo "   range from '$v': ${r:-none found} | $(msg)"; [ -z "$r" ] && { cp $W/orig $file; return; }
  for v in $(/usr/bin/python3 - "$r" <<'P'
import math, re, sys
r = sys.argv[1]; m = re.match(r"range ([[(])\s*([^,]+),\s*([^])]+)([])])", r); lo, hi = m.group(2).strip(), m.group(3).strip()
out = []
for b, o, d in ((hi, m.group(4), math.inf), (lo, m.group(1), -math.inf)):
    try: x = float(b)
    except ValueError: continue
    if not math.isfinite(x): continue
    out += [repr(x), repr(math.nextafter(x, d))]
print(' '.join(out))
P
); do cp $W/orig $file; sete $file $key $v; timeout -s KILL 30 $cmd > $W/try.log 2>&1; echo "   [$v] rc=$? sig=$(sig) | $(msg)"; rm -rf [1-9]* 0.[0-9]* postProcessing solid; done; cp $W/orig $file; }
sod; bound system/controlDict maxCo rhoRiemannFoam; bound system/controlDict maxDeltaT rhoRiemannFoam
cd $W; blast; for k in tolerance mapTolerance velocityScale motionDistance; do bound constant/fsiProperties $k cellBlastFoam; done
cd $W; ind; sete constant/indenterProperties maxDepthIncrement 0.3e-6; /usr/bin/python3 -c "print('   0.3e-6/10 == 3e-8:', 0.3e-6/10 == 3e-8, repr(0.3e-6/10))"
for v in 3e-8 3.0000000000000004e-8 2.9999999999999997e-8; do sete constant/indenterProperties tolerance $v; timeout -s KILL 40 cellIndentationFoam > $W/try.log 2>&1; echo "   [tolerance $v, maxDepthIncrement 0.3e-6] rc=$? | $(msg)"; rm -rf postProcessing; done
cd $W; rm -rf ind; ind; bound system/cellMeshDict membraneThickness cellMesh
sete system/cellMeshDict cytoplasmSize 0.5e-6; cp system/cellMeshDict ../m0; echo "maxElements 1;" >> system/cellMeshDict; timeout -s KILL 60 cellMesh > $W/try.log 2>&1; echo "   [maxElements 1] rc=$? | $(msg)"
N=$(grep -a -o 'at least [0-9]\+' $W/try.log | grep -o '[0-9]\+' | head -1); echo "   N=$N"
for m in $N $((N - 1)) 0 -1 1.5 1e308; do cp ../m0 system/cellMeshDict; echo "maxElements $m;" >> system/cellMeshDict; rm -f constant/cell.msh; timeout -s KILL 60 cellMesh > $W/try.log 2>&1; echo "   [maxElements $m] rc=$? sig=$(sig) | $(msg) | cell.msh: $(ls constant/cell.msh 2>/dev/null)"; done
