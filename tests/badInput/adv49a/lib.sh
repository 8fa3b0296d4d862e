# lib.sh (adv49a): adv48a's lib.sh (tests/badInput/adv48a: adv47b's helpers of adv35-adv47b plus dmgf, setv, setb, cutf,
# sig) with ADV mapped to PREFIXadv47b, where adv48a's and adv48b's prebuild.sh (called with this pass's prefix) put every
# base (indBase, blastBase, bdBase, idBase, ikBase, bd2Base, qBase, pbdBase, ibdBase); runOne.sh's ADV=<prefix>adv49a is
# mapped there as adv48b's lib.sh does. Plus (mine):
#   pbd, short     adv48b's pbd and short (copied, one line each: sourcing adv48b's lib.sh would source the whole chain
#                  again): the finished 2-rank blast preview (processor0/1 hold 1e-09, 2e-09), cd there; endTime 2e-11
#   msg [N]        the first N (8) lines of the last tryt's error block, unwrapped (the whole message, not tryt's 420 chars)
#   subset FILE SUB KEY VALUE   KEY's value in the sub-dictionary SUB of FILE set to VALUE (added at its top if absent)
#   setbb FILE PATCH INDEX VALUE   the INDEX-th double of PATCH's binary value list in FILE's boundaryField set to VALUE
ADV=${ADV:-/tmp/adv49a-adv49a}; ADV=${ADV%adv49a}adv47b
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv48a/lib.sh"
short() { blastEnd 2e-11 1e-11; }
pbd() { mkBase_ pbdBase pblastDone blast; cp -a $ADV/pbdBase $W/pblast; cd $W/pblast; }
msg() { grep -a -m1 -A${1:-8} 'FATAL\|Traceback\|error:' $W/try.log | grep -av '^ *$\|^-->\|From function\|in file\|^\[.\] *$' | head -${1:-8} | tr -s ' ' | tr '\n' ' ' | cut -c1-900; echo; }
subset() { /usr/bin/python3 - "$@" <<'P'
import re, sys
p, sub, k, v = sys.argv[1:5]; t = open(p).read()
m = re.search(r'(?m)^\s*%s\s*\n\s*\{' % re.escape(sub), t)
if not m: print('   subset: no %s in %s' % (sub, p)); sys.exit(1)
depth, i = 1, m.end()
while depth:
    depth += {'{': 1, '}': -1}.get(t[i], 0); i += 1
body = t[m.end():i - 1]
e = re.search(r'(?m)^(\s*)%s(\s+)([^;]*);' % re.escape(k), body)
body = body[:e.start(3)] + v + body[e.end(3):] if e else '\n    %s %s;' % (k, v) + body
open(p, 'w').write(t[:m.end()] + body + t[i - 1:]); print('   %s: %s/%s %s' % (p, sub, k, v))
P
}
setbb() { /usr/bin/python3 - "$@" <<'P'
import struct, sys
f, patch, i, v = sys.argv[1], sys.argv[2].encode(), int(sys.argv[3]), float(sys.argv[4]); s = bytearray(open(f, 'rb').read())
k = s.find(b'boundaryField'); k = s.find(patch, k); k = s.find(b'value', k); k = s.find(b'(', k) + 1 + 8 * i
old = struct.unpack('<d', bytes(s[k:k+8]))[0]; s[k:k+8] = struct.pack('<d', v); open(f, 'wb').write(s)
print('   %s: %s value %d %r -> %r' % (f, patch.decode(), i, old, v))
P
}
