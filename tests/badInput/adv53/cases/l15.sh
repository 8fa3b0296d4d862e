#!/bin/bash
# CASETIMEOUT=600
# l15 (new, class 5: what a power loss leaves in the text results - zeroed blocks and a row cut mid-number - read by the
# plot scripts, not by a restart): (a) the finished indentation idn: force.dat's middle 512 bytes zeroed, then
# tutorials/indentation/plotIndentation.py; (b) peaks.dat cut in the middle of its last number; (c) bd: postProcessing/
# solidProbes/0/solidProbes.dat's middle 256 bytes zeroed: tutorials/blast/plotBlast.py; (d) fluidProbes/0/p cut
# mid-row: plotBlast.py and planeWave -check. Expected: the damage named (file and line) rc != 0; a plot or a table made
# from the damaged rows without a word = SILENT; a traceback = CRASH (low).
. "$(dirname "$0")/../lib.sh"
z() { /usr/bin/python3 - "$1" "$2" <<'P'
import sys
p, n = sys.argv[1], int(sys.argv[2]); b = bytearray(open(p, 'rb').read()); k = len(b) // 2; b[k:k+n] = b'\0' * n; open(p, 'wb').write(b); print('   %s: %d bytes zeroed at %d of %d' % (p, n, k, len(b)))
P
}
py() { tryt 120 "$1" /usr/bin/python3 "${@:2}"; echo "   tracebacks $(grep -a -c Traceback $W/try.log) | said: $(grep -a -i -m2 'error\|damag\|zero\|cut\|Traceback' $W/try.log | tr '\n' '|' | cut -c1-250) | last: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-150)"; }
idn; I=postProcessing/indentation; cp -a . $W/i0; py "(0) plotIndentation.py (control)" $ROOT/tutorials/indentation/plotIndentation.py .
z $I/force.dat 512; py "(a) force.dat's middle 512 bytes zeroed" $ROOT/tutorials/indentation/plotIndentation.py .
cd $W; rm -rf ind; cp -a i0 ind; cd ind; truncate -s -3 $I/peaks.dat; tail -c 60 $I/peaks.dat | sed 's/^/   peaks.dat ends: /'; py "(b) peaks.dat cut mid-number" $ROOT/tutorials/indentation/plotIndentation.py .
cd $W; bd; cp -a . $W/b0; S=$(ls postProcessing/solidProbes/*/solidProbes.dat | head -1); z $S 256; py "(c) solidProbes.dat's middle 256 bytes zeroed: plotBlast.py" $ROOT/tutorials/blast/plotBlast.py .
cd $W; rm -rf blast; cp -a b0 blast; cd blast; P=$(ls postProcessing/fluidProbes/*/p | head -1); n=$(wc -l < $P); head -n $((n/2)) $P > $W/p2; sed -n "$((n/2+1))p" $P | cut -c1-12 | tr -d '\n' >> $W/p2; cp $W/p2 $P; tail -c 40 $P | sed 's/^/   p ends: /'; echo
py "(d) fluidProbes p cut mid-row: plotBlast.py" $ROOT/tutorials/blast/plotBlast.py .
tryt 300 "(d2) planeWave -check on it" planeWave -case . -check; echo "   said: $(say 2 | cut -c1-250) | last: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-150)"
