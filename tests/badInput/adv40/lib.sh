# lib.sh (adv40): adv39's lib.sh (adv35-39's base cases and helpers: ind/indDone, blast/blastDone, pblast/pblastDone,
# sod/sodDone, prev/$PREV, study, cal, indAllrun, setd, blastEnd, latest, killAfter, indKilled, try, each, snap/gone,
# contents/lost, inDir/killIn, run, fatal, waitFor, lockOf, sameSeries, killedAllrun, again) with ADV defaulting to
# /tmp/adv40-B, plus:
#   nul FILE...       each FILE's bytes replaced by as many NUL bytes (what a power loss can leave of a file whose
#                     size reached the disk before its data: ext4/XFS delayed allocation)
#   changed BEFORE    the files whose md5 differs from the `sums` listing BEFORE, or that are gone or new (names)
#   h5steps FILE      the number of steps of a solid.h5 (h5py)
#   xmfsteps FILE     the number of <Grid ... Name= time grids in a solid.xmf
ADV=${ADV:-/tmp/adv40-B}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv39/lib.sh"
nul() { local f; for f in "$@"; do head -c "$(stat -c %s "$f")" /dev/zero > "$f.nul" && mv "$f.nul" "$f"; done; }
changed() { sums > $W/.sumsNow; diff "$1" $W/.sumsNow | grep '^[<>]' | awk '{print $3}' | sort -u | tr '\n' ' '; echo; }
h5steps() { /usr/bin/python3 -c "import h5py,sys; f=h5py.File(sys.argv[1],'r'); print(len(f['steps']))" "$1" 2>&1 | tail -1; }
xmfsteps() { grep -c '<Time ' "$1" 2>/dev/null || echo 0; }
#   tryf LABEL CMD... as try (60 s KILL timeout), but the message shown is the first FATAL/error block (3 lines), not the first line matching a word
tryf() { local l=$1; shift; timeout -s KILL 60 "$@" > $W/try.log 2>&1; local rc=$?; echo "$l: rc=$rc | $(grep -a -m1 -A3 'FATAL\|error:\|Error\|Traceback\|refused' $W/try.log | grep -av '^ *$\|^-->\|From function\|^\[.\] *$' | head -3 | tr '\n' ' ' | cut -c1-420)"; }
#   forceOk FILE    rows of a force.dat/peaks.dat-like file, NUL bytes, and whether its times (column 1) increase
forceOk() { /usr/bin/python3 - "$1" <<'P'
import sys
b = open(sys.argv[1], 'rb').read(); t = [float(l.split()[0]) for l in b.decode('latin-1').splitlines() if l.strip() and not l.startswith('#') and '\0' not in l]
print("%s: %d rows, %d NUL bytes, times increasing %s" % (sys.argv[1].split('/')[-1], len(t), b.count(b'\0'), all(x < y for x, y in zip(t, t[1:]))))
P
}
