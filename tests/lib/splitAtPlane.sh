# Sourced by the parallel tests (tests/blast/fluid3DParallel.sh,
# tests/blast/parallel.sh) after etc/bashrc.
# splitAtPlane DIR COMPONENT VALUE: a manual 2-rank decomposition of the
# case DIR (system/decomposeParDict, constant/cellDecomposition): rank 1
# holds the cells whose centre has COMPONENT (x, y or z) above VALUE [m],
# rank 0 the others. Not decomposed here (decomposePar).
splitAtPlane()
{
    (
        cd "$1"
        local format
        format=$(foamDictionary -entry writeFormat -value system/controlDict)
        foamDictionary -entry writeFormat -set ascii system/controlDict \
            > /dev/null
        postProcess -func writeCellCentres -time 0 > log.centres 2>&1 \
            || { tail log.centres; exit 1; }
        foamDictionary -entry writeFormat -set "$format" system/controlDict \
            > /dev/null
        /usr/bin/python3 - "0/C$2" "$3" <<'PY'
import sys
from neuronFsi.decomposition import writeManual
from neuronFsi.foamField import internalField
c = internalField(sys.argv[1])
writeManual(".", (c > float(sys.argv[2])).astype(int))
PY
        rm -f 0/C 0/Cx 0/Cy 0/Cz 0/V
        cat > system/decomposeParDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method          manual;
coeffs          { dataFile "cellDecomposition"; }
DICT
    )
}
