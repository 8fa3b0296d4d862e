#!/bin/bash
# CASETIMEOUT=900
# k09 (adv49b i11 / fix19f's predictor history varied): the extrapolated-predictor run xbd (5e-9), restarted to 6e-9 with
# -acceptEdited after editing 5e-09/uniform/fsiState: (a) previousDeltaT 0, (b) previousDeltaT -1e-12, (c) previousDeltaT
# nan, (d) previousDeltaT 1e300, (e) `predictor centralDifference;` written in the state (the run's predictor is
# extrapolated), (f) `predictor extrapolatedd;` (a misspelt word), (g) previousAcceleration given as a word. Each refused
# rc 1 naming the file and entry, or run with a warning that says what it does; never a signal, never silently another
# history.
. "$(dirname "$0")/../lib.sh"
xbd; rs6; rm -f .runLock; F=5e-09/uniform/fsiState; grep -a -n 'predictor\|previous' $F | cut -c1-120 | tr '\n' ' '; echo; cp -a . ../keep
again() { cd $W; rm -rf xblast; cp -a keep xblast; cd xblast; }
one() { tryt 200 "$1" cellBlastFoam -acceptEdited; echo "   sig: $(sig) | times: $(ls -d [0-9]* | tr '\n' ' ') | warnings: $(grep -a -A2 'Warning' $W/try.log | grep -a -v '^ *$\|From\|in file' | head -3 | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"; echo "   msg: $(msg 4 | cut -c1-500)"; again; }
for v in 0 -1e-12 nan 1e300; do sete $F previousDeltaT $v > /dev/null; one "(x) previousDeltaT $v"; done
sete $F predictor centralDifference > /dev/null; one "(e) predictor centralDifference in the state"
sete $F predictor extrapolatedd > /dev/null; one "(f) predictor extrapolatedd in the state"
/usr/bin/python3 - $F <<'P'
import re, sys
f = sys.argv[1]; s = open(f).read(); s2 = re.sub(r'(previousAcceleration\s+)[^;]*;', r'\1none;', s, count=1); open(f, 'w').write(s2); print('   previousAcceleration -> none: %s' % (s != s2))
P
one "(g) previousAcceleration none"
