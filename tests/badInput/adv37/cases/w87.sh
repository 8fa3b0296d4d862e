#!/bin/bash
# w87: solidToFoam -region with a path or odd name: ../escape, a/b, '' , 0: refused, nothing written outside the case?
. "$(dirname "$0")/../lib.sh"
blastDone; for r in ../escape a/b "" 0; do try "-region '$r'" solidToFoam -region "$r" solid/solid.h5; done; ls .. | tr '\n' ' '
