#!/bin/bash
# CASETIMEOUT=600
# n36 (new, class 6: planeWave's temporary column in TMPDIR on a full disk - a small /tmp, or TMPDIR on a quota): p8;
# planeWave -case . -dz 12.5e-9 with TMPDIR a tmpfs of 200 KiB and of 2 MiB; then TMPDIR a folder that is not writable
# (a file) and one that does not exist. Expected: refused or failed in one line naming TMPDIR and the full disk (or
# falling back), the case's planeWave files unchanged, nothing left in TMPDIR; "blockMesh failed" without the cause = UNCLEAR.
. "$(dirname "$0")/../lib.sh"
p8; md5sum postProcessing/planeWave/0/* > $W/m0; P=$PWD
for s in 200k 2m; do unmountAll; cd $P || exit 1; rm -rf $W/fs; tiny $s; [ -d $W/fs ] || { echo "   premise: no tmpfs"; continue; }
  TMPDIR=$W/fs tryt 300 "(a) TMPDIR a tmpfs of $s" env TMPDIR=$W/fs planeWave -case . -dz 12.5e-9; echo "   said: $(say 2 | cut -c1-300) | left in TMPDIR: $(ls $W/fs | tr '\n' ' ') | case files: $(md5sum -c $W/m0 2>/dev/null | grep -c ': OK$') of $(wc -l < $W/m0) as before"; done
unmountAll; cd $P || exit 1; echo x > $W/notadir; tryt 300 "(b) TMPDIR a file" env TMPDIR=$W/notadir planeWave -case .; echo "   said: $(say 2 | cut -c1-250)"
tryt 300 "(c) TMPDIR missing" env TMPDIR=$W/nothere planeWave -case .; echo "   said: $(say 2 | cut -c1-250)"
