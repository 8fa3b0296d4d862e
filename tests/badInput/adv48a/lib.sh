# lib.sh (adv48a): adv47b's lib.sh (adv46b's helpers of adv35-adv46b plus bd2, q, qEnd, qrun, lk) with ADV defaulting to
# /tmp/adv48a-adv48a; for adv48a's variants of earlier cases (cases/h*.sh). Bases copied there by prebuild.sh.
ADV=${ADV:-/tmp/adv48a-adv48a}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv47b/lib.sh"
# dmgf FILE [OFFSET N]: N (64) bytes zeroed at OFFSET (200) bytes after the '(' of FILE's internalField (f07's damage)
dmgf() { /usr/bin/python3 - "$1" "${2:-200}" "${3:-64}" <<'P'
import sys; f, o, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]); s = bytearray(open(f, 'rb').read()); k = s.find(b'internalField'); k = s.find(b'(', k) + o; s[k:k+n] = b'\0' * n; open(f, 'wb').write(s)
P
}
# setv FILE INDEX TEXT: the INDEX-th number of FILE's internalField list replaced by TEXT (parse-valid damage)
setv() { /usr/bin/python3 - "$@" <<'P'
import re, sys; f, i, t = sys.argv[1], int(sys.argv[2]), sys.argv[3]; s = open(f, 'rb').read().decode('latin-1')
k = s.find('internalField'); k = s.find('(', k) + 1; m = list(re.finditer(r'[-+0-9.eE]+', s[k:k+200000]))[i]
a, b = k + m.start(), k + m.end(); print('   %s: value %d %s -> %s' % (f, i, s[a:b], t)); open(f, 'wb').write((s[:a] + t + s[b:]).encode('latin-1'))
P
}
# sig: what killed the last tryt (signal handler / stack trace lines)
sig() { grep -a -c "sigHandler\|sigFpe\|printStack\|Aborted\|signal [0-9]" $W/try.log; }
# setb FILE INDEX VALUE: the INDEX-th double of FILE's binary internalField list set to VALUE (python float text: nan, inf,
# -1e3 ...), a parse-valid damage of a binary field (the preview writes binary)
setb() { /usr/bin/python3 - "$@" <<'P'
import struct, sys; f, i, v = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]); s = bytearray(open(f, 'rb').read())
k = s.find(b'internalField'); k = s.find(b'(', k) + 1 + 8 * i; old = struct.unpack('<d', bytes(s[k:k+8]))[0]
s[k:k+8] = struct.pack('<d', v); open(f, 'wb').write(s); print('   %s: double %d %r -> %r' % (f, i, old, v))
P
}
# cutf FILE FRACTION: FILE cut to FRACTION of its size
cutf() { truncate -s $(( $(stat -c %s "$1") * $2 / 100 )) "$1"; echo "   $1 cut to $(stat -c %s "$1") B"; }
