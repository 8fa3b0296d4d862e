#!/bin/bash
# z26: indentation loading-table rows at edges never tried: a hold of 0 s, a load of 0 m, an unload deeper than the bead has gone (0.3 um loaded, 1 um unloaded), a load rate of 0, a row label with a comma: each refused naming the row (and file, range), or run to a sensible end?
. "$(dirname "$0")/../lib.sh"
ind; P=constant/indenterProperties; cp $P ../orig
for r in "(B   hold    0       0)" "(B   load    0.3e-6  0)" "(B   unload  0.3e-6  1e-6)" "(B   load    0       0.5e-6)" "(B,x   hold    0       1)"; do
  cp ../orig $P; /usr/bin/python3 - $P "$r" <<'P'
import sys; f=sys.argv[1]; s=open(f).read(); s=s.replace("(B   hold    0       1)", sys.argv[2]); open(f,'w').write(s)
P
  try "row $r" cellIndentationFoam; rm -rf postProcessing; done
