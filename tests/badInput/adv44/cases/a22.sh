#!/bin/bash
# a22 (class 4, cellMesh's 3D modes: quarter3D's dictionary): in a copy of tutorials/blast/quarter3D (hex water): fluid/hexCoeffs 'lateralSze' (typo), 'axialSize' twice, axialSize 0, lateralSize -1e-6, lateralSize nan, boxSize 1e400, fluid/type 'hexx', mode 'quarter3d' (case), mode full3D with hexCoeffs kept, an unknown top-level 'azimuthSizes', membraneLayers 0: each refused naming the file, the entry and the range (and the closest keyword), no mesh written?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/quarter3D" $W/q; cd $W/q; f=system/cellMeshDict; cp $f ../orig
t() { tryf "$1" cellMesh; echo "   mesh files: $(ls constant/*.msh 2>/dev/null | tr '\n' ' ')"; rm -f constant/*.msh; cp ../orig $f; }
sed -i 's/lateralSize 1e-6;/lateralSze 1e-6;/' $f; t "hexCoeffs lateralSze (typo)"
sed -i 's/axialSize   0.5e-6;/axialSize 0.5e-6; axialSize 0.5e-6;/' $f; t "axialSize twice"
sed -i 's/axialSize   0.5e-6;/axialSize 0;/' $f; t "axialSize 0"
sed -i 's/lateralSize 1e-6;/lateralSize -1e-6;/' $f; t "lateralSize -1e-6"
sed -i 's/lateralSize 1e-6;/lateralSize nan;/' $f; t "lateralSize nan"
sed -i 's/boxSize         100e-6;/boxSize 1e400;/' $f; t "boxSize 1e400"
sed -i 's/type            hex;/type hexx;/' $f; t "fluid/type hexx"
sed -i 's/^mode .*/mode quarter3d;/' $f; t "mode quarter3d"
sed -i 's/^membraneLayers .*/membraneLayers 0;/' $f; t "membraneLayers 0"
echo 'azimuthSizes 1e-6;' >> $f; t "unknown azimuthSizes"
