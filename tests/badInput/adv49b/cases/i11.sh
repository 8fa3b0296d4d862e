#!/bin/bash
# i11 (class 1/5, the extrapolated predictor's restart state in uniform/fsiState): xbd (extrapolated, 5e-9) restarted to 6e-9
# with 5e-09/uniform/fsiState (a) removed, (b) replaced by that of mbd's 5e-09 (a centralDifference run of the same times),
# (c) as (b) with -acceptEdited, (d) its last non-empty entry line deleted, with -acceptEdited, (e) one digit of a number in
# it changed, with -acceptEdited. (a) (b) refused naming the file (marker), nothing changed; (c)-(e): refused naming the
# file and what is missing or not of this predictor, or (an edit on purpose) continued - but never a restart that silently
# takes a missing predictor state as zero: compared with the clean restart (f) and named.
. "$(dirname "$0")/../lib.sh"
mbd; M=$PWD; xbd; rs6; S=5e-09/uniform/fsiState; echo "   fsiState: $(grep -av '^ *$\|^ *//' $S | sed -n '9,40p' | cut -c1-80 | tr '\n' '|' | cut -c1-600)"; cp $S ../fs; sums > ../s0
rm $S; tryt 300 "(a) fsiState removed" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"
cp $M/$S $S; tryt 300 "(b) fsiState of a centralDifference run" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"
tryt 300 "(c) (b) with -acceptEdited" cellBlastFoam -acceptEdited; cont; echo "   changed: $(changed ../s0)"; away c_c
xbd; rs6; L=$(grep -an ';' $S | tail -1 | cut -d: -f1); echo "   (d) deleted line $L: $(sed -n ${L}p $S | cut -c1-120)"; sed -i "${L}d" $S
tryt 300 "(d) last entry deleted, -acceptEdited" cellBlastFoam -acceptEdited; cont
away d_d; xbd; rs6; /usr/bin/python3 - $S <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); lines = t.split('\n')
for i in range(len(lines) - 1, -1, -1):
    m = re.search(r'[1-9]\.?\d*e', lines[i])
    if m and not lines[i].lstrip().startswith('//'):
        j = m.start(); d = lines[i][j]; lines[i] = lines[i][:j] + ('2' if d != '2' else '3') + lines[i][j+1:]; print("   (e) edited line %d: %s" % (i + 1, lines[i][:120])); break
open(p, 'w').write('\n'.join(lines))
P
tryt 300 "(e) one digit edited, -acceptEdited" cellBlastFoam -acceptEdited; cont
away e_e; xbd; rs6; tryt 300 "(f) clean restart" cellBlastFoam; cont; away ref
for c in c_c d_d e_e; do [ -d $W/$c/6e-09 ] && (cd $W/$c && echo "   ($c) $(cmp6 $W/ref)"); done
