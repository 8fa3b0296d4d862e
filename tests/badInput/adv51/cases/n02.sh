#!/bin/bash
# CASETIMEOUT=900
# n02 (new, class 4/5: the probes' dictionary, movingMeshProbes fluidProbes of the preview's controlDict): the short
# preview (sb, endTime 2e-11) with fluidProbes edited: (a) one probe outside the mesh (1e-3 1e-3 0) beside the four, (b)
# every probe outside, (c) a probe on the axis (0 50e-6 0) and one on the loaded face (1e-7 100e-6 0), (d) a probe off
# the wedge's plane (1e-7 50e-6 1e-3), (e) a nan coordinate, (f) the same probe twice, (g) interpolationScheme cellPointt
# (unknown) and cell, (h) cellLinearFit with fields (p U), (i) fields (foo), fields (), fields (p p), fields (phi) with
# cellLinearFit, (j) fixedLocations maybe (not a switch) and no, (k) on 2 ranks (pbd restarted to 3e-9): a probe outside
# the mesh, and a probe on the ranks' split plane y = 4e-6. Each: refused at the start rc 1 naming the function object,
# the entry and the probe (or run with the probe's file saying what it holds); never a -1e300 (VGREAT) fill written as
# a measured value without a word, never a signal.
. "$(dirname "$0")/../lib.sh"
F=postProcessing/fluidProbes/0/p
res() { echo "   sig: $(sig) | End: $(grep -a -c '^End' $W/try.log) | warnings: $(grep -a -c -i 'warning' $W/try.log) $(grep -a -m1 -i -A2 'warning' $W/try.log | tr '\n' ' ' | tr -s ' ' | cut -c1-250)"; echo "   msg: $(msg 5 | cut -c1-400)"
  [ -f $F ] && echo "   $F: $(grep -c '^#' $F) header lines, probes: $(grep -a '^# Probe' $F | tr '\n' ' ' | cut -c1-250) | last row: $(tail -1 $F | tr -s ' ' | cut -c1-200)"; }
sb; hdr0 system/controlDict; cp -a . ../b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
loc() { /usr/bin/python3 - system/controlDict "$1" <<'P'
import re, sys
p, new = sys.argv[1], sys.argv[2]; t = open(p).read()
m = re.search(r'probeLocations\s*\((.*?)\n\s*\);', t, re.S); t = t[:m.start()] + 'probeLocations (' + new + ');' + t[m.end():]; open(p, 'w').write(t)
P
}
pl="(1e-7 90e-6 0) (1e-7 50e-6 0) (1e-7 20e-6 0) (1e-7 10e-6 0)"
loc "$pl (1e-3 1e-3 0)"; hdr system/controlDict; tryt 120 "(a) a fifth probe outside the mesh (1e-3 1e-3 0)" cellBlastFoam; res; back
loc "(1e-3 1e-3 0) (-1 -1 0)"; tryt 120 "(b) every probe outside" cellBlastFoam; res; back
loc "(0 50e-6 0) (1e-7 100e-6 0)"; tryt 120 "(c) a probe on the axis and one on the loaded face" cellBlastFoam; res; back
loc "(1e-7 50e-6 1e-3)"; tryt 120 "(d) a probe off the wedge's plane (z 1e-3)" cellBlastFoam; res; back
loc "(1e-7 nan 0)"; tryt 120 "(e) a nan coordinate" cellBlastFoam; res; back
loc "(1e-7 50e-6 0) (1e-7 50e-6 0)"; tryt 120 "(f) the same probe twice" cellBlastFoam; res; back
for s in cellPointt cell; do subset system/controlDict fluidProbes interpolationScheme $s > /dev/null; tryt 120 "(g) interpolationScheme $s" cellBlastFoam; res; back; done
subset system/controlDict fluidProbes interpolationScheme cellLinearFit > /dev/null; subset system/controlDict fluidProbes fields "(p U)" > /dev/null; tryt 120 "(h) cellLinearFit fields (p U)" cellBlastFoam; res; back
for f in "(foo)" "()" "(p p)"; do subset system/controlDict fluidProbes fields "$f" > /dev/null; tryt 120 "(i) fields $f" cellBlastFoam; res; back; done
subset system/controlDict fluidProbes interpolationScheme cellLinearFit > /dev/null; subset system/controlDict fluidProbes fields "(phi)" > /dev/null; tryt 120 "(i) cellLinearFit fields (phi)" cellBlastFoam; res; back
for s in maybe no; do subset system/controlDict fluidProbes fixedLocations $s > /dev/null; tryt 120 "(j) fixedLocations $s" cellBlastFoam; res; back; done
cd $W; rm -rf blast b0; pbd; rs; rm -f .runLock; cp -a . ../p0; backp() { cd $W; rm -rf pblast; cp -a p0 pblast; cd pblast; }
F=postProcessing/fluidProbes/2e-09/p
loc "$pl (1e-3 1e-3 0)"; tryt 180 "(k1) 2 ranks: a fifth probe outside the mesh" mpirun -np 2 cellBlastFoam -parallel; res; backp
loc "(1e-7 4e-6 0) (2e-6 4e-6 0)"; tryt 180 "(k2) 2 ranks: probes on the split plane y = 4e-6" mpirun -np 2 cellBlastFoam -parallel; res; ls postProcessing/fluidProbes/ | sed 's/^/   folders: /'
