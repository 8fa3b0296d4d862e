#!/bin/bash
# CASETIMEOUT=600
# n08 (new, class 2/4: the other bench scripts the docs name, n01 continued): a user's folder (notes.txt, data/run1.csv) at
# the output path each script would use: (a) bench/blast/knobMatrix.py --out DIR --jobs 1 --variants base --pulses 5e-9
# (DIR/base_5ns), (b) previewOptions.py --out DIR --jobs 1 (DIR/opt_default), (c) subcycles.py --out DIR --subcycles 1
# (DIR/N1), (d) solidVariant.sh DIR (DIR itself), (e) membraneWaterLaw.sh DIR (DIR and the user's DIR.log),
# (f) inflow3D.sh DIR 1 and (g) probeOvershoot3D.sh DIR on an existing DIR (documented: refused "DIR exists"), (h)
# restartWindow.sh REF 0 2e-9 DIR on an existing DIR. Each killed after 25 s if still going. Never a user's file removed.
. "$(dirname "$0")/../lib.sh"
mk() { rm -rf "$1"; mkdir -p "$1/data"; echo "user's notes" > "$1/notes.txt"; echo "1,2" > "$1/data/run1.csv"; }
chk() { echo "   user's files in ${1#$W/}: $(cd $1 2>/dev/null && ls notes.txt data/run1.csv 2>/dev/null | tr '\n' ' ' || echo 'FOLDER GONE') $( [ -f $1/notes.txt ] && [ "$(cat $1/notes.txt)" = "user's notes" ] || echo '(notes.txt gone or changed)')"; }
run() { local l=$1; shift; cd $W/here; tryt 25 "$l" "$@"; killIn $W; sleep 1; killIn $W; echo "   out: $(grep -av '^ *$' $W/try.log | head -3 | tr '\n' '|' | cut -c1-300)"; }
mkdir -p $W/here; B=$ROOT/bench/blast
mk $W/k/base_5ns; run "(a) knobMatrix.py --out \$W/k --variants base --pulses 5e-9" /usr/bin/python3 $B/knobMatrix.py --out $W/k --jobs 1 --variants base --pulses 5e-9; chk $W/k/base_5ns
mk $W/p/opt_default; run "(b) previewOptions.py --out \$W/p --jobs 1" /usr/bin/python3 $B/previewOptions.py --out $W/p --jobs 1; chk $W/p/opt_default
mk $W/s/N1; run "(c) subcycles.py --out \$W/s --subcycles 1" /usr/bin/python3 $B/subcycles.py --out $W/s --subcycles 1; chk $W/s/N1
mk $W/u; run "(d) solidVariant.sh \$W/u explicit 0.1" bash $B/solidVariant.sh $W/u explicit 0.1; chk $W/u
mk $W/u; echo "user's log" > $W/u.log; run "(e) membraneWaterLaw.sh \$W/u" bash $B/membraneWaterLaw.sh $W/u; chk $W/u; echo "   \$W/u.log: $(head -1 $W/u.log | cut -c1-80)"
mk $W/u; run "(f) inflow3D.sh \$W/u 1 (existing)" bash $B/inflow3D.sh $W/u 1; chk $W/u
mk $W/u; run "(g) probeOvershoot3D.sh \$W/u (existing)" bash $B/probeOvershoot3D.sh $W/u; chk $W/u
mk $W/u; run "(h) restartWindow.sh \$ADV/bdBase 0 2e-9 \$W/u (existing)" bash $B/restartWindow.sh $ADV/bdBase 0 2e-9 $W/u; chk $W/u
