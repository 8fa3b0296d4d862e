#!/bin/bash
# CASETIMEOUT=600
# o03 (fix19h's checkLongRun.py / incidentWindow.py / readReference on cut or damaged outputs, adv51 m06, varied: other
# damage than m06's): the finished preview with planeWave's reference (pwd0; log.first copied to log.cellBlastFoam, the
# name checkLongRun.py reads), checkLongRun.py CASE 2e-9 with (a) log.cellBlastFoam a folder, (b) 64 zeroed bytes inside
# solid/solid.h5's last step, (c) fsi/coupling.dat's last row with an extra column, (d) solidProbes.dat's middle row
# holding 'abc', (e) solid/solid.h5 a folder; incidentWindow.py CASE with postProcessing/planeWave/0/reference.dat
# (f) an inf in a row, (g) its rows in reversed time order, (h) a time row duplicated with another value, (i) a folder,
# (j) --series 10 5 1 (not ordered), (k) --level 1e9 and 1.0000000000000002e9 (the edge of (0, 1e9] Pa). Each: one line
# naming the file/argument rc 1, or a FAIL line; never a traceback, never numbers measured from the damaged rows.
. "$(dirname "$0")/../lib.sh"
pwd0; cp log.first log.cellBlastFoam; C=$PWD; cp -a $C $W/pw0
back() { cd $W; rm -rf pw; cp -a pw0 pw; cd pw; }
CL="$ROOT/tests/blast/checkLongRun.py"
cl() { tryt 120 "$1" /usr/bin/python3 $CL $C 2e-9; echo "   traceback: $(grep -c Traceback $W/try.log) | out: $(grep -a -v '^ *$' $W/try.log | tail -4 | tr '\n' '|' | cut -c1-500)"; back; }
cl "(0) checkLongRun.py on the finished run (control)"
rm log.cellBlastFoam; mkdir log.cellBlastFoam; cl "(a) log.cellBlastFoam a folder"
/usr/bin/python3 - solid/solid.h5 <<'P'
import h5py, sys
f = h5py.File(sys.argv[1], 'r'); ks = sorted(f['steps'].keys(), key=lambda k: int(k)); d = f['steps'][ks[-1]]
name = [n for n in d.keys() if isinstance(d[n], h5py.Dataset)][0]; ds = d[name]; off = ds.id.get_offset()
off = ds.id.get_chunk_info(0).byte_offset if off is None else off; f.close()
print('   zeroed 64 bytes at', off + 16, 'in step', ks[-1], name)
with open(sys.argv[1], 'r+b') as g: g.seek(off + 16); g.write(b'\0' * 64)
P
cl "(b) 64 zeroed bytes inside solid.h5's last step"
f=postProcessing/fsi/0/coupling.dat; sed -i '$ s/$/ 12345/' $f; cl "(c) coupling.dat's last row with an extra column"
f=postProcessing/solidProbes/0/solidProbes.dat; n=$(grep -vc '^#' $f); awk -v m=$((n/2)) '!/^#/{i++} !/^#/ && i==m {$2="abc"} {print}' $f > $W/x && cp $W/x $f; cl "(d) solidProbes.dat's middle row holding abc"
rm -rf solid/solid.h5; mkdir solid/solid.h5; cl "(e) solid/solid.h5 a folder"
R=postProcessing/planeWave/0/reference.dat
iwc() { tryt 120 "$1" /usr/bin/python3 "$ROOT/bench/blast/analysis/incidentWindow.py" $C "${@:2}"; echo "   traceback: $(grep -c Traceback $W/try.log) | out: $(grep -a -v '^ *$' $W/try.log | tail -5 | tr '\n' '|' | cut -c1-600)"; back; }
iwc "(0) incidentWindow.py (control)"
head -3 $R | sed 's/^/   ref: /'
awk '!/^#/{i++} !/^#/ && i==20 {$2="inf"} {print}' $R > $W/x && cp $W/x $R; iwc "(f) reference.dat: an inf in row 20"
(grep '^#' $R; grep -v '^#' $R | tac) > $W/x && cp $W/x $R; iwc "(g) reference.dat: rows reversed"
awk '!/^#/{i++} {print} !/^#/ && i==20 {$2=$2*3; print}' $R > $W/x && cp $W/x $R; iwc "(h) reference.dat: row 20 duplicated with 3x its value"
rm $R; mkdir $R; iwc "(i) reference.dat a folder"
iwc "(j) --series 10 5 1" --series 10 5 1
iwc "(k1) --level 1e9" --level 1e9
iwc "(k2) --level 1.0000000000000002e9" --level 1.0000000000000002e9
