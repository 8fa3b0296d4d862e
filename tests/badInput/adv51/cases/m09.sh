#!/bin/bash
# CASETIMEOUT=900
# m09 (fix19g's keyword places, adv50b k01/k02/k04/k05, varied): where an unknown or doubled keyword is said to be written,
# against where it is: (a) `coupling { maxIterr 3; }` in a new constant/fsiProperties.allrun (line 3); (b) `explicitSafty
# 0.5;` in constant/solidProperties.allrun (line 2); (c) a misspelt keyword in the smoke indentation's indenterProperties
# (its line); (d) cellMeshDict.allrun with CRLF line endings, the unknown keyword on line 3; (e) after a 4-line /* */
# comment in cellMeshDict.allrun (line 6); (f) in a file included by cellMeshDict.allrun (`#include "extra"`, line 2 of
# extra); (g) the same keyword twice in fsiProperties.allrun's coupling{} (lines 3 and 4) and once in fsiProperties and
# once in .allrun (replaces by design); (h) an unknown keyword on the last line without a newline; (i) an unknown
# keyword inside interface{} given in fsiProperties.allrun. Each refused rc 1 naming the file and line where it is written
# and the closest valid keyword; (g)'s second form runs.
. "$(dirname "$0")/../lib.sh"
where() { echo "   msg: $(msg 6 | cut -c1-500)"; echo "   places: $(grep -a -o '[A-Za-z./]*\(Properties\|Dict\)[A-Za-z.]*\( at\)\? line [0-9]*\|[a-z]*/extra[ a-z]*line [0-9]*\|lines\? [0-9]*\( and\| to\) \(line \)\?[0-9]*' $W/try.log | sort -u | tr '\n' '|' | cut -c1-300)"; }
sb; cp -a . ../b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
printf 'coupling\n{\n    maxIterr 3;\n}\n' > constant/fsiProperties.allrun; tryt 90 "(a) coupling{maxIterr} in fsiProperties.allrun line 3" cellBlastFoam; where
back; printf '// mine\nexplicitSafty 0.5;\n' > constant/solidProperties.allrun; tryt 90 "(b) explicitSafty in solidProperties.allrun line 2" cellBlastFoam; where
back; printf 'coupling\n{\n    maxIter 3;\n    maxIter 4;\n}\n' > constant/fsiProperties.allrun; tryt 90 "(g1) maxIter twice in fsiProperties.allrun lines 3, 4" cellBlastFoam; where
back; printf 'coupling\n{\n    maxIter 3;\n}\n' > constant/fsiProperties.allrun; tryt 90 "(g2) maxIter in fsiProperties and in .allrun (replaces)" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log)"; where
back; printf 'coupling\n{\n    maxIter 3;\n}\nexplicitSafty 0.5;' > constant/solidProperties.allrun; tryt 90 "(h) solidProperties.allrun, explicitSafty on the last line without a newline (line 5)" cellBlastFoam; where
back; printf '\ninterface\n{\n    motionDistanse 4e-6;\n}\n' > constant/fsiProperties.allrun; tryt 90 "(i) interface{motionDistanse} in fsiProperties.allrun line 4" cellBlastFoam; where
cd $W; ind; n=$(grep -n "^radius\|^ *radius" constant/indenterProperties | head -1 | cut -d: -f1); sed -i "${n}s/radius/radiuss/" constant/indenterProperties; tryt 90 "(c) indenterProperties radiuss at line $n" cellIndentationFoam; where
mdir; printf 'nucleusSize 0.5e-6;\r\ncytoplasmSize 0.5e-6;\r\nmembraneSise 0.4e-6;\r\nmembraneSize 0.4e-6;\r\n' > system/cellMeshDict.allrun; tryt 60 "(d) cellMeshDict.allrun CRLF, membraneSise at line 3" cellMesh; where
mdir; printf 'nucleusSize 0.5e-6;\n/* four\n   lines\n   of comment */\ncytoplasmSize 0.5e-6;\nmembraneSise 0.4e-6;\n' >> system/cellMeshDict.allrun; tryt 60 "(e) after a comment, membraneSise at cellMeshDict.allrun line 9" cellMesh; where; cat -n system/cellMeshDict.allrun | sed -n 9p | sed 's/^/   line: /'
mdir; printf '// extra\nmembraneSise 0.4e-6;\n' > system/extra; echo '#include "extra"' >> system/cellMeshDict.allrun; tryt 60 "(f) membraneSise at line 2 of system/extra, included by cellMeshDict.allrun" cellMesh; where
