#!/bin/bash
# CASETIMEOUT=300
# p32 (new, class 2: a case whose sub-folders are symbolic links into ANOTHER case, a common way to share a mesh or keep
# results elsewhere, cleaned by its tutorial Allclean): the finished preview A (bd, its Allclean copied in) and B, a copy of
# A's inputs whose (a) constant/ is a link to A's constant/; (b) system/ a link to A's system/; (c) postProcessing/ and
# solid/ links to a user's folders holding the user's files; then B's ./Allclean. Expected: A's files (constant/cell.msh,
# constant/polyMesh, constant/*.allrun, system/*.allrun ...) and the user's kept (an Allclean removes the links, not
# what they point to), or refused naming the links; another case's mesh or inputs removed through a link = DATALOSS.
. "$(dirname "$0")/../lib.sh"
bd; cp $ROOT/tutorials/blast/axisymmetricPreview/Allclean .; A=$PWD; cd $A; sums > $W/sA
mkB() { cd $W; rm -rf B; mkdir B; cd B; cp -r $A/0.orig $A/Allclean .; for d in 0 1e-09 2e-09; do cp -r $A/$d .; done; }
st() { cd $A; echo "   A changed: $(changed $W/sA | cut -c1-400)"; cd $W/B 2>/dev/null; }
mkB; ln -s $A/constant constant; cp -r $A/system system; tryt 60 "(a) B's Allclean, B/constant a link to A's constant" ./Allclean; echo "   said: $(grep -a -m1 -i 'error\|link' $W/try.log | cut -c1-200) | B/constant: $(ls -la $W/B | grep constant | awk '{print $NF}')"; st
cd $A; cp -a $A $W/A0; sums > $W/sA
mkB; cp -r $A/constant constant; ln -s $A/system system; tryt 60 "(b) B's Allclean, B/system a link to A's system" ./Allclean; echo "   said: $(grep -a -m1 -i 'error\|link' $W/try.log | cut -c1-200)"; st
cd $A; sums > $W/sA; mkdir -p $W/user/pp $W/user/sol; cd $W/user; mark pp/notes.txt; mark sol/mine.h5
mkB; cp -r $A/constant constant; cp -r $A/system system; ln -s $W/user/pp postProcessing; ln -s $W/user/sol solid; tryt 60 "(c) B's Allclean, B/postProcessing and B/solid links to a user's folders" ./Allclean; echo "   said: $(grep -a -m1 -i 'error\|link' $W/try.log | cut -c1-200)"
cd $W/user; kept_ pp/notes.txt; kept_ sol/mine.h5
