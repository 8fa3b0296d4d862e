#!/bin/bash
# CASETIMEOUT=600
# n16 (new, class 4: dictionaries with Windows line ends, CRLF - a case edited on Windows or mailed): the whole file
# converted with `sed 's/$/\r/'`: (a) system/controlDict.allrun of the short preview (endTime 2e-11 etc.); (b)
# constant/fsiProperties; (c) constant/indenterProperties of the smoke indentation (its protocol table); (d) the sod tube's
# system/riemannProblemDict (setRiemannProblem); (e) system/cellMeshDict.allrun (membraneLayers 2). Each against the same
# file with LF. Expected: each read as the LF file (the same results: OpenFOAM takes \r as white space) or refused naming
# the file and the line; a value read otherwise (e.g. "2e-11\r" a word, a key "endTime\r" unknown) without a word, or a
# different result = SILENT.
. "$(dirname "$0")/../lib.sh"
crlf() { sed -i 's/$/\r/' "$1"; echo "   $1: $(grep -c $'\r$' "$1") CRLF lines"; }
sb; cp -a . $W/s0; tryt 200 "(0) LF" cellBlastFoam; cp 2e-11/p $W/p.lf 2>/dev/null; echo "   times $(ls -d [0-9]* | tr '\n' ' ')"
cd $W; rm -rf blast; cp -a s0 blast; cd blast; crlf system/controlDict.allrun; tryt 200 "(a) controlDict.allrun CRLF" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250) | times $(ls -d [0-9]* | tr '\n' ' ') | 2e-11/p $(cmp -s 2e-11/p $W/p.lf && echo same || echo DIFFERS)"
cd $W; rm -rf blast; cp -a s0 blast; cd blast; crlf constant/fsiProperties; tryt 200 "(b) fsiProperties CRLF" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250) | 2e-11/p $(cmp -s 2e-11/p $W/p.lf && echo same || echo DIFFERS)"
cd $W; idn; cp postProcessing/indentation/peaks.dat $W/pk.lf; cd $W; rm -rf ind; ind; crlf constant/indenterProperties; tryt 300 "(c) indenterProperties CRLF" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250) | peaks.dat $(cmp -s postProcessing/indentation/peaks.dat $W/pk.lf && echo same || echo DIFFERS)"
cd $W; sod; cp 0/p $W/sodp.lf; crlf system/riemannProblemDict; rm -rf 0; cp -r 0.orig 0; tryt 200 "(d) riemannProblemDict CRLF" setRiemannProblem; echo "   said: $(say 2 | cut -c1-250) | 0/p $(cmp -s 0/p $W/sodp.lf && echo same || echo DIFFERS)"
cd $W; mdir; mset membraneLayers 2; cm > /dev/null; cp constant/cell.msh $W/cm.lf; rm -f constant/cell.msh; crlf system/cellMeshDict.allrun; tryt 200 "(e) cellMeshDict.allrun CRLF" cellMesh; echo "   said: $(say 2 | cut -c1-250) | cell.msh $(cmp -s constant/cell.msh $W/cm.lf && echo same || echo DIFFERS)"
