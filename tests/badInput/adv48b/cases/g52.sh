#!/bin/bash
# g52 (class 4/5, solidToFoam on what is not a solid.h5) on bd: a FIFO named x.h5, a directory, /dev/zero, an empty file, the indentation's restart.h5 (a checkpoint, not results), a symbolic link to itself: each refused within seconds naming the file and what it is; never a hang on the FIFO (30 s), never a mesh written from a checkpoint.
. "$(dirname "$0")/../lib.sh"
idn; R=$PWD/postProcessing/indentation/restart.h5; bd; mkfifo ../x.h5; mkdir ../d.h5; : > ../e.h5; ln -s l.h5 ../l.h5
for f in ../x.h5 ../d.h5 /dev/zero ../e.h5 $R ../l.h5; do tryt 30 "$f" solidToFoam $f; echo "   times now: $(ls -d [0-9]* | tr '\n' ' ')"; done
