#!/bin/bash
# CASETIMEOUT=900
# m05 (fix19g's k58 warning, adv50b k58, varied: restarts from each write format): the prepared preview (blast), run to
# 1e-9 with controlDict's writeFormat/writePrecision/writeCompression set, then restarted (startFrom latestTime) to 2e-9;
# the restarted 2e-09/p, rho, rhoU against the uninterrupted run's (bd: binary, 17 digits; the state in memory does not
# depend on how it is written) as the largest difference. (a) ascii 17 (no warning, exact), (b) ascii 16 (warning),
# (c) binary 6 (warning: uniform/time's deltaT at 6 digits), (d) ascii 17 writeCompression on (.gz: restart exact?),
# (e) ascii 3 written, controlDict's writePrecision put back to 17 before the restart (fix19g's documented limit: no
# warning), (f) binary 17 written, ascii 17 at the restart (exact), (g) the sod tube (rhoRiemannFoam, ascii 12, its
# tutorial's value) stopped at half its endTime and restarted (warning). Never a silent inexact continuation.
. "$(dirname "$0")/../lib.sh"
fdiff() { /usr/bin/python3 - "$@" <<'P'
import gzip, re, struct, sys, os
def read(p):
    if not os.path.exists(p) and os.path.exists(p + '.gz'): p += '.gz'
    b = gzip.open(p).read() if p.endswith('.gz') else open(p, 'rb').read()
    k = b.index(b'internalField'); m = re.compile(rb'nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(').search(b, k)
    n, w, s = int(m.group(2)), 3 if m.group(1) == b'vector' else 1, m.end()
    if b'format      binary' in b[:800] or b'format binary' in b[:800]:
        return list(struct.unpack_from('<%dd' % (n * w), b, s))
    e = b.index(b'\n)', s); return [float(x) for x in re.findall(rb'[-+0-9.eE]+', b[s:e])]
a, r = read(sys.argv[1]), read(sys.argv[2])
if len(a) != len(r): print('sizes differ %d %d' % (len(a), len(r))); sys.exit()
d = max(abs(x - y) for x, y in zip(a, r)); sc = max(abs(y) for y in r)
print('max |diff| %.3e (of max %.3e, rel %.2e)' % (d, sc, d / sc if sc else 0))
P
}
bd; REF=$PWD; cd $W
ctl() { sed -i "s/^writeFormat .*/writeFormat $1;/; s/^writePrecision .*/writePrecision $2;/; s/^writeCompression .*/writeCompression $3;/" system/controlDict; }
one() { local l=$1 f=$2 p=$3 c=$4 f2=${5:-$2} p2=${6:-$3} c2=${7:-$4}; cd $W; rm -rf m; cp -r $ADV/blastBase/axisymmetricPreview m; cd m; rm -rf postProcessing solid [1-9]*
  hdr0 system/controlDict; ctl $f $p $c; hdr system/controlDict; blastEnd 1e-9 1e-9; timeout -s KILL 300 cellBlastFoam > log.first 2>&1; echo "$l: first run rc $? | 1e-09: $(ls 1e-09 | tr '\n' ' ' | cut -c1-120)"
  ctl $f2 $p2 $c2; latest; blastEnd 2e-9 1e-9; tryt 300 "$l: restart to 2e-9 ($f2 $p2 compression $c2)" cellBlastFoam
  echo "   warning lines: $(grep -a -c -i 'writePrecision' $W/try.log) | $(grep -a -m1 -i -A1 'writePrecision' $W/try.log | tr '\n' ' ' | cut -c1-330)"; echo "   End: $(grep -a -c '^End' $W/try.log) | 2e-09: $(ls 2e-09 2>/dev/null | tr '\n' ' ' | cut -c1-100)"
  for fld in p rho rhoU; do echo "   2e-09/$fld vs uninterrupted: $(fdiff 2e-09/$fld $REF/2e-09/$fld 2>&1 | tail -1)"; done; }
one "(a) ascii 17" ascii 17 off
one "(b) ascii 16" ascii 16 off
one "(c) binary 6" binary 6 off
one "(d) ascii 17 compressed" ascii 17 on
one "(e) ascii 3 written, 17 at the restart" ascii 3 off ascii 17 off
one "(f) binary 17 written, ascii 17 at the restart" binary 17 off ascii 17 off
cd $W; sod; sed -n '/^endTime/p;/^writeInterval/p;/^writePrecision/p' system/controlDict | tr '\n' ' '; echo; E=$(sed -n 's/^endTime *\([^;]*\);.*/\1/p' system/controlDict)
H=$(/usr/bin/python3 -c "print(repr($E/2))"); sed -i "s/^endTime .*/endTime $H;/" system/controlDict; timeout -s KILL 300 rhoRiemannFoam > log.first 2>&1; echo "(g) sod to $H: rc $? | times: $(ls -d [0-9]* | tr '\n' ' ')"
sed -i "s/^endTime .*/endTime $E;/" system/controlDict; latest; tryt 300 "(g) sod restart to $E" rhoRiemannFoam; echo "   warning lines: $(grep -a -c -i 'writePrecision' $W/try.log) | $(grep -a -m1 -i 'writePrecision' $W/try.log | cut -c1-250)"
