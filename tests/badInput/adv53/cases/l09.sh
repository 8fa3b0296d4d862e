#!/bin/bash
# CASETIMEOUT=900
# l09 (new, class 6/5: a full disk under the Python tools' outputs: planeWave's reference, the plot scripts' figures,
# fluidWedgeMesh's dictionary): the finished preview pwd0 (with its reference) copied into a tmpfs with 24 KB free beyond
# it: (a) planeWave -case . -overwrite (rewrites postProcessing/planeWave/0/reference.dat, ~60 KB), then incidentWindow.py
# on what is left; (b) tutorials/blast/plotBlast.py . ; (c) the finished indentation idn in such a tmpfs:
# tutorials/indentation/plotIndentation.py . ; (d) fluidWedgeMesh.py -o system/blockMeshDict with 2 KB free. Expected:
# each stops rc != 0 naming the file and the full disk, the earlier file (reference.dat) kept whole or absent, never a cut
# file that a later reader takes; a traceback = CRASH (low); a cut reference.dat read as good = SILENT.
. "$(dirname "$0")/../lib.sh"
fill() { local free=$1 src=$2 dst=$3; local sz=$(du -sk --apparent-size $src | cut -f1); mkdir -p $W/fs; umount -l $W/fs 2>/dev/null; mount -t tmpfs -o size=$((sz * 2 + 4096))k tmpfs $W/fs; cp -a $src $W/fs/$dst
  local f=$(df -k --output=avail $W/fs | tail -1); [ $f -gt $free ] && fallocate -l $(( (f - free) * 1024 )) $W/fs/.filler 2>/dev/null || head -c $(( (f - free) * 1024 )) /dev/zero > $W/fs/.filler; echo "   $(df -k --output=avail $W/fs | tail -1) KB free"; cd $W/fs/$dst; }
py() { tryt 200 "$1" /usr/bin/python3 "${@:2}"; echo "   tracebacks $(grep -a -c Traceback $W/try.log) | said: $(grep -a -i -m2 'error\|space\|Traceback' $W/try.log | tr '\n' '|' | cut -c1-250)"; }
pwd0; P=$PWD; R=postProcessing/planeWave/0/reference.dat; md5sum $R > $W/r0; fill 24 $P pw
tryt 300 "(a) planeWave -case . (rewrites its reference), 24 KB free" planeWave -case .; echo "   tracebacks $(grep -a -c Traceback $W/try.log) | said: $(say 3 | cut -c1-300)"; echo "   reference.dat: $(md5sum -c $W/r0 > /dev/null 2>&1 && echo kept || echo "CHANGED ($(stat -c %s $R 2>/dev/null) B)") | stray files: $(find . -newer $W/r0 -type f | head -5 | tr '\n' ' ')"
py "(a2) incidentWindow.py on what is left" $ROOT/bench/blast/analysis/incidentWindow.py .
py "(b) plotBlast.py ., 24 KB free" $ROOT/tutorials/blast/plotBlast.py .; echo "   pngs: $(ls -la *.png 2>/dev/null | awk '{print $5, $9}' | tr '\n' ' ')"
cd $W; umount -l $W/fs; idn; fill 16 $PWD ind; py "(c) plotIndentation.py ., 16 KB free" $ROOT/tutorials/indentation/plotIndentation.py .; echo "   pngs: $(ls -la *.png 2>/dev/null | awk '{print $5, $9}' | tr '\n' ' ')"
cd $W; umount -l $W/fs; mkdir -p $W/e/system; fill 2 $W/e e; py "(d) fluidWedgeMesh.py, 2 KB free" $ROOT/tutorials/blast/fluidWedgeMesh.py -h 0.25e-6 -Z 20e-6 -R 20e-6; echo "   blockMeshDict: $(stat -c %s system/blockMeshDict 2>/dev/null || echo none) B"
cd $W; umount -l $W/fs; rm -rf $W/e; mkdir -p $W/e/system; cd $W/e; /usr/bin/python3 $ROOT/tutorials/blast/fluidWedgeMesh.py -h 0.5e-6 -Z 20e-6 -R 20e-6 > /dev/null 2>&1; md5sum system/blockMeshDict > $W/bm0; echo "   an earlier blockMeshDict: $(stat -c %s system/blockMeshDict) B"
fill 2 $W/e e; py "(d2) fluidWedgeMesh.py -h 0.25e-6 over an earlier blockMeshDict, 2 KB free" $ROOT/tutorials/blast/fluidWedgeMesh.py -h 0.25e-6 -Z 20e-6 -R 20e-6; echo "   the earlier blockMeshDict: $(md5sum -c $W/bm0 > /dev/null 2>&1 && echo kept || echo "CHANGED ($(stat -c %s system/blockMeshDict) B)")"
cd $W; umount -l $W/fs
