#!/bin/bash
# CASETIMEOUT=600
# p10 (new, class 4/6: the exactRiemann sampler's inputs; no earlier pass ran it): the sod problem as key=value arguments
# (law=idealGas gamma=1.4 Cv=718 rhoL=1 uL=0 pL=1e5 rhoR=0.125 uR=0 pR=1e4 x0=0.5 t=5e-4 xMin=0 xMax=1 n=11) with:
# (a) n=1 (the range printed is [2, 1e7]; x = xMin + (xMax-xMin)*i/(n-1)), (b) n=10000001, (c) rhoL given twice
# (rhoL=1 rhoL=0.125), (d) t=0, (e) x0=5 (outside [xMin, xMax]), (f) a case file that is a folder, (g) /dev/zero as case
# file, (h) a FIFO with no writer as case file, (i) gamma=1, gamma=0.5, Cv=-1, (j) pL=-1, (k) rhoL=1e-320, (l) t= (empty),
# (m) n=10000000 to /dev/null (time and memory: the resource row). Each: refused rc 1 naming the entry and its range, or a
# right answer; a row of nan printed rc 0 = SILENT; a hang = HANG (60 s).
. "$(dirname "$0")/../lib.sh"
ER=$ROOT/build/bin/exactRiemann
S="law=idealGas gamma=1.4 Cv=718 rhoL=1 uL=0 pL=1e5 rhoR=0.125 uR=0 pR=1e4 x0=0.5 t=5e-4 xMin=0 xMax=1"
er() { local l=$1; shift; tryt 60 "$l" "$@"; echo "   out: $(grep -a -v '^#' $W/try.log | head -3 | tr -s ' ' | tr '\n' '|' | cut -c1-250) | nan rows: $(grep -a -v '^#' $W/try.log | grep -ci nan) | rows: $(grep -a -vc '^#' $W/try.log)"; }
er "(0) sod n=11 (control)" $ER $S n=11
er "(a) n=1" $ER $S n=1
tryt 120 "(b) n=10000001 (to a file)" bash -c "$ER $S n=10000001 > $W/b.out"; echo "   rows $(grep -vc '^#' $W/b.out)"; rm -f $W/b.out
er "(c) rhoL=1 rhoL=0.125" $ER $S rhoL=0.125 n=11
er "(d) t=0" $ER ${S/t=5e-4/t=0} n=11
er "(e) x0=5" $ER ${S/x0=0.5/x0=5} n=11
mkdir -p $W/cf; er "(f) a case file that is a folder" $ER $W/cf n=11
er "(g) /dev/zero as case file" $ER /dev/zero n=11
mkfifo $W/ff; er "(h) a FIFO as case file" $ER $W/ff n=11
for g in gamma=1 gamma=0.5 Cv=-1; do er "(i) $g" $ER $S $g n=11; done
er "(j) pL=-1" $ER ${S/pL=1e5/pL=-1} n=11
er "(k) rhoL=1e-320" $ER ${S/rhoL=1 /rhoL=1e-320 } n=11
er "(l) t= (empty)" $ER ${S/t=5e-4/t=} n=11
s=$(date +%s.%N); tryt 300 "(m) n=10000000 to /dev/null" bash -c "/usr/bin/time -f 'maxRSS %M KB, %e s' $ER $S n=10000000 > /dev/null"; echo "   $(tail -1 $W/try.log)"
