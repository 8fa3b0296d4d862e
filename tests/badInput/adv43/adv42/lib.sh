# (adv43: a copy of adv42 74e63eb tests/badInput/adv42/lib.sh; its source of adv41/lib.sh goes one folder up more, ADV default /tmp/adv43-adv42)
# lib.sh (adv42): adv41's lib.sh (all helpers of adv35-adv41: ind/indDone, blast/blastDone, pblast/pblastDone, blastEnd,
# latest, sums, changed, nochange, kept, tryf, try, run, fatal, h5steps, xmfsteps, waitFor, lockOf, sameSeries, study, cal,
# wpDone, nul, forceOk, ...) with ADV defaulting to /tmp/adv42-B, plus:
#   flip FILE OFF       xor 0x01 into the byte at offset OFF of FILE (one damaged bit; OFF negative: from the end)
#   h5same A B          "same" if every dataset and attribute of the HDF5 files A and B is equal, else what differs
#   blastRef            $W/ref: blastDone, then its restart to 3e-09 (the clean continuation the damaged restarts are compared with)
#   cmpRef REF          this case against REF after a restart to 3e-09: the four logs (sameSeries), solid.h5 (h5same), 3e-09/p
#   killAt S CMD...     CMD in the background, SIGKILLed S s after its start (and its children); prints what it did
ADV=${ADV:-/tmp/adv43-adv42}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../../adv41/lib.sh"
flip() { /usr/bin/python3 - "$1" "$2" <<'P'
import sys
p, off = sys.argv[1], int(sys.argv[2]); b = bytearray(open(p, 'rb').read())
if off < 0: off += len(b)
b[off] ^= 1; open(p, 'wb').write(b)
P
}
h5same() { /usr/bin/python3 - "$1" "$2" <<'P' 2>&1 | tail -2
import sys, h5py, numpy as np
d = []
def items(f):
    out = {}
    def v(n, o):
        if isinstance(o, h5py.Dataset): out[n] = o[()]
        for k, a in o.attrs.items(): out[n + '@' + k] = a
    f.visititems(v)
    for k, a in f.attrs.items(): out['@' + k] = a
    return out
a, b = items(h5py.File(sys.argv[1], 'r')), items(h5py.File(sys.argv[2], 'r'))
for k in sorted(set(a) | set(b)):
    if k not in a or k not in b: d.append(k + ' (only in one)'); continue
    x, y = a[k], b[k]
    try: eq = np.array_equal(np.asarray(x), np.asarray(y))
    except Exception: eq = str(x) == str(y)
    if not eq: d.append(k)
print('same' if not d else 'DIFF: ' + ' '.join(d[:8]))
P
}
blastRef() { local here=$PWD; mkdir -p $W/r; cd $W/r; cp -r "$ADV/blastBase/axisymmetricPreview" ref; cd ref; rm -rf postProcessing solid [1-9]*
  cellBlastFoam > log.first 2>&1 || echo "blastRef first run failed"; cd ..; cp -r ref ref2; cd ref; latest; blastEnd 3e-9 1e-9; cellBlastFoam > log.second 2>&1 || echo "blastRef restart failed"; cd "$here"; }
cmpRef() { echo "   vs clean restart: $(sameSeries $1 | awk '{print $1, $2}' | tr '\n' ' ')| solid.h5 $(h5same solid/solid.h5 $1/solid/solid.h5) | 3e-09/p $(cmp -s 3e-09/p $1/3e-09/p && echo same || echo DIFF)"; }
killAt() { local s=$1; shift; "$@" > $W/killAt.log 2>&1 & local p=$!; sleep $s; pkill -KILL -P $p 2>/dev/null; kill -KILL $p 2>/dev/null; wait $p 2>/dev/null; echo "killed at $s s"; }
#   closeTo REF         the four logs joined over their segments here and in REF: rows and the largest difference relative to REF's largest |value| per log
closeTo() { PYTHONPATH=$ROOT/src/python /usr/bin/python3 - "$1" <<'P'
import sys, numpy as np
from neuronFsi.postProcessing import series
out = []
for log in ("fsi/coupling.dat", "solidProbes/solidProbes.dat", "solidInterfaces/interfaceMaxima.dat", "fluidProbes/p"):
    try:
        a, b = np.asarray(series(".", log), float), np.asarray(series(sys.argv[1], log), float)
        n = min(len(a), len(b)); d = np.nanmax(np.abs(a[:n, 1:] - b[:n, 1:])) / max(np.nanmax(np.abs(b[:n, 1:])), 1e-300) if n else float('nan')
        t = np.array_equal(a[:n, 0], b[:n, 0])
        out.append("%s %d/%d rows, times %s, max rel diff %.2g" % (log.split('/')[0], len(a), len(b), "same" if t else "DIFFER", d))
    except Exception as e:
        out.append("%s error %s" % (log.split('/')[0], str(e)[:80]))
print("   vs reference: " + "; ".join(out))
P
}
#   sete FILE KEY VALUE  the first line-anchored "KEY <anything>;" of FILE (also "KEY x;" inside a line after a ';') set to "KEY VALUE;"
#   dupe FILE KEY        the first "KEY ...;" of FILE written twice (the same value) on its line
sete() { /usr/bin/python3 - "$@" <<'P'
import re, sys
p, k, v = sys.argv[1:4]; t = open(p).read()
m = re.compile(r'(^|[;{]\s*|\n\s*)(%s)(\s+)([^;{}]*?);' % re.escape(k), re.M).search(t)
if not m: print('   sete: no %s in %s' % (k, p)); sys.exit(1)
open(p, 'w').write(t[:m.start(4)] + v + t[m.end(4):])
P
}
dupe() { /usr/bin/python3 - "$@" <<'P'
import re, sys
p, k = sys.argv[1:3]; t = open(p).read()
m = re.compile(r'(^|[;{]\s*|\n\s*)(%s\s+[^;{}]*?;)' % re.escape(k), re.M).search(t)
if not m: print('   dupe: no %s in %s' % (k, p)); sys.exit(1)
open(p, 'w').write(t[:m.end(2)] + ' ' + m.group(2) + t[m.end(2):])
P
}
#   badValues FILE "KEY..." -- CMD...  for each KEY and each of nan, inf, -1, 1e400 and a duplicate: the original FILE back, the edit, CMD (60 s); the results of an accepted run removed
badValues() { local f=$1 keys=$2; shift 3; cp "$f" $W/bv.orig; local k v
  for k in $keys; do for v in nan inf -1 1e400 DUP; do cp $W/bv.orig "$f"; if [ $v = DUP ]; then dupe "$f" $k || continue; else sete "$f" $k $v || continue; fi
    tryf "$f $k $v" "$@"; [ -d 1e-09 ] || [ -d postProcessing ] || [ -d solid ] && echo "      (ran: $(ls -d [1-9]* solid postProcessing 2>/dev/null | tr '\n' ' '))"; rm -rf [1-9]* solid postProcessing; done; done; cp $W/bv.orig "$f"; }
