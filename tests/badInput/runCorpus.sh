#!/bin/bash
# The bad-input corpus (tests/badInput/corpus): every row breaks one input
# of a good case and runs a real application on it. Each row must
#   - exit non-zero, without a signal or timeout (exit < 124),
#   - print no crash trace (segmentation fault, sigFpe/sigSegv, abort,
#     stack trace, uncaught exception, Python traceback, sanitizer report),
#   - name the file (regex column 'file') and the entry (column 'entry'),
#   - leave every file that existed before the run unchanged (md5 of each
#     file of the case, logs excepted: the good results stay good).
# Usage: runCorpus.sh [-l | --list] [NAME-REGEX]
#        runCorpus.sh --prepare DIR
#        runCorpus.sh --bases DIR [--shard K/N] [NAME-REGEX]
#   -l         print the listing (name, base, application, what is broken)
#   --prepare  build the good cases (the bases) into DIR (new or empty) and
#              exit: ctest's fixture badInputBases, shared by the shards
#   --bases    the rows on the bases of an earlier --prepare DIR (by
#              default they are built into a temporary folder first)
#   --shard    of the selected rows, the K-th of every N (rows K, K+N, ...
#              in the corpus' order; K in [1, N]): the ctest tests
#              badInput.corpus.K run the corpus in N parts
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
corpus=$here/corpus

# Rows: name | base | application | file regex | entry regex | edit
rows() { grep -v '^[[:space:]]*\(#\|$\)' "$corpus"; }
field() { awk -F ' [|] ' -v i="$2" '{ gsub(/^ +| +$/, "", $i); print $i }' <<< "$1"; }

if [ "${1:-}" = -l ] || [ "${1:-}" = --list ]
then
    printf '%-28s %-7s %-20s %s\n' case base application "edit (in the case)"
    rows | while IFS= read -r row
    do
        printf '%-28s %-7s %-20s %s\n' "$(field "$row" 1)" "$(field "$row" 2)" \
            "$(field "$row" 3)" "$(field "$row" 6)"
    done
    exit 0
fi
prepare="" bases="" shard=1 shards=1
while [ $# -gt 0 ]
do
    case "$1" in
        --prepare|--bases)
            [ $# -ge 2 ] && [ -n "$2" ] \
                || { echo "badInput: $1 needs a folder" >&2; exit 1; }
            if [ "$1" = --prepare ]; then prepare=$2; else bases=$2; fi
            shift 2 ;;
        --shard)
            [[ "${2:-}" =~ ^([1-9][0-9]*)/([1-9][0-9]*)$ ]] \
                && [ "${BASH_REMATCH[1]}" -le "${BASH_REMATCH[2]}" ] \
                || { echo "badInput: --shard '${2:-}': give K/N with" \
                     "1 <= K <= N (e.g. --shard 2/3)" >&2; exit 1; }
            shard=${BASH_REMATCH[1]} shards=${BASH_REMATCH[2]}
            shift 2 ;;
        -*) echo "badInput: unknown option $1 (valid: -l, --list," \
                "--prepare DIR, --bases DIR, --shard K/N)" >&2; exit 1 ;;
        *) break ;;
    esac
done
[ -z "$prepare" ] || [ -z "$bases" ] \
    || { echo "badInput: --prepare and --bases exclude each other" >&2; exit 1; }
select=${1:-.}

. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ -n "$prepare" ]
then
    # nothing good overwritten: a new or empty folder only
    if [ -e "$prepare" ] && [ -n "$(ls -A "$prepare" 2>/dev/null)" ]
    then
        echo "badInput: --prepare $prepare exists and is not empty (give a" \
            "new folder, or remove it)" >&2
        exit 1
    fi
    mkdir -p "$prepare" || exit 1
    bases=$(cd "$prepare" && pwd)
    build=yes
elif [ -n "$bases" ]
then
    [ -d "$bases" ] || { echo "badInput: --bases $bases is not a folder" \
        "(made by runCorpus.sh --prepare)" >&2; exit 1; }
    bases=$(cd "$bases" && pwd)
    build=no
else
    bases=$work/bases
    mkdir -p "$bases"
    build=yes
fi

# --- the good cases -------------------------------------------------------
# fluid: the 50 MPa water shock tube, meshed and initialised
makeFluid() {
    local c=$bases/fluid
    mkdir -p "$c"
    cp -r "$root/tutorials/verification/waterShock50MPa"/{0.orig,system,constant} "$c"/
    rm -rf "$c/constant/polyMesh"
    (cd "$c" && cp -r 0.orig 0 && blockMesh > /dev/null 2>&1 \
        && setRiemannProblem > /dev/null 2>&1)
}
# solid: the average-cell indentation on a coarse fallback mesh, with a
# previous result in postProcessing/
makeSolid() {
    local c=$bases/solid
    mkdir -p "$c"
    cp -r "$root/tutorials/indentation/averageCell"/{system,constant} "$c"/
    rm -f "$c/constant/cell.msh"
    gmsh -2 -setnumber D 16.8 -setnumber H 7.9 -setnumber h 1.6 \
        -setnumber hc 0.8 -setnumber nm 24 \
        "$root/tests/lib/cellFallback.geo" \
        -o "$c/constant/cell.msh" > /dev/null 2>&1
    mkdir -p "$c/postProcessing/indentation"
    for f in force.dat peaks.dat solid.h5 solid.xmf
    do
        echo "previous result $f" > "$c/postProcessing/indentation/$f"
    done
}
# mesh: the cellMesh dictionary of tests/cellMesh, previous meshes present
makeMesh() {
    local c=$bases/mesh
    mkdir -p "$c/system" "$c/constant"
    cp "$here/cellMeshDict" "$c/system/"
    echo "previous mesh" > "$c/constant/cell.msh"
    echo "previous mesh" > "$c/constant/fluid.msh"
}
# fsi: the pulse-through-a-layer FSI case of tests/fsi, meshed
makeFsi() {
    local c=$bases/fsi
    cp -r "$root/tests/fsi/pulseLayer" "$c"
    (cd "$c" && blockMesh > /dev/null 2>&1)
}
# h5: a result file of the solid library (two steps) and a case for
# solidToFoam with a previous conversion
makeH5() {
    local c=$bases/h5
    mkdir -p "$c/system" "$c/constant"
    "${MAKE_SOLID_RESULTS:-$root/build/bin/makeSolidResults}" "$c" > /dev/null
    cat > "$c/system/controlDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application solidToFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime 1; deltaT 1; writeControl timeStep; writeInterval 1;
DICT
    for f in fvSchemes fvSolution
    do
        echo "FoamFile { version 2.0; format ascii; class dictionary; object $f; }" > "$c/system/$f"
    done
    mkdir -p "$c/1/solid"
    echo "previous result" > "$c/1/solid/D"
}
# blast: the preview's water (0/ from 0.orig, thermo, schemes, controlDict)
# with its top a planeWaveInflow boundary of the 100 um column: the
# dictionaries planeWave -inflow reads
makeBlast() {
    local c=$bases/blast t=$root/tutorials/blast/axisymmetricPreview
    mkdir -p "$c/constant" "$c/system"
    cp -r "$t/0.orig" "$c/0"
    cp "$t/constant/thermophysicalProperties" "$c/constant/"
    cp "$t/system"/{fvSchemes,fvSolution,controlDict} "$c/system/"
    (cd "$c" && /usr/bin/python3 -c "from neuronFsi import planeWave
planeWave.setInflowBoundary('.', 1e-4)")
}
# inflow: the 1D column of tests/verification/planeWaveInflow.py ending
# at 10 um, its top a planeWaveInflow boundary with its constant/inflowWave
# (rhoRiemannFoam; the run's results removed)
makeInflow() {
    local c=$bases/inflow
    /usr/bin/python3 "$root/tests/verification/planeWaveInflow.py" \
        --keep "$bases/inflowWork" > "$bases/inflowWork.log" 2>&1
    cp -r "$bases/inflowWork/short" "$c"
    (cd "$c" && rm -rf postProcessing log.* && foamListTimes -rm > /dev/null)
}
# preview, quarter: the blast tutorials' cases as committed (their Allrun
# options; a row's edit may run ./Allrun -noRun first)
makeTutorial() {
    local c=$bases/$1 t=$root/tutorials/blast/$2
    mkdir -p "$c"
    cp -r "$t"/{0.orig,system,constant,Allrun,Allclean} "$c"/
    (cd "$c" && ./Allclean > /dev/null)
}
makePreview() { makeTutorial preview axisymmetricPreview; }
makeQuarter() { makeTutorial quarter quarter3D; }
# study: tutorials/blast/pulseStudy as committed (its Allrun runs
# pulseStudy on system/pulseStudyDict)
makeStudy() {
    local c=$bases/study t=$root/tutorials/blast/pulseStudy
    mkdir -p "$c"
    cp -r "$t"/{system,Allrun,Allclean} "$c"/
}
# paper: tutorials/paper as committed (its Allrun runs paperFigures on
# system/paperDict)
makePaper() {
    local c=$bases/paper t=$root/tutorials/paper
    mkdir -p "$c"
    cp -r "$t"/{system,Allrun,Allclean} "$c"/
}
if [ $build = yes ]
then
    for b in Fluid Solid Mesh Fsi H5 Blast Inflow Preview Quarter Study Paper
    do
        make$b
    done
fi
for b in fluid solid mesh fsi h5 blast inflow preview quarter study paper
do
    [ -d "$bases/$b" ] || { echo "badInput: base case $b not built" \
        "(in $bases)"; exit 1; }
done
if [ -n "$prepare" ]
then
    echo "badInput: the base cases are in $bases"
    exit 0
fi

# --- the rows -------------------------------------------------------------
crash='Segmentation|sigFpe|sigSegv|sigAbrt|Aborted|core dumped|printStack|terminate called|AddressSanitizer|runtime error:|Traceback \(most recent call last\)'
failures=0
n=0
# The rows' six fields split once (those of field(), joined by the unit
# separator), and the names the regex selects (grep -E on the name, as
# each row was filtered before): no process per row and field
us=$'\x1f'
rows | awk -F ' [|] ' -v OFS="$us" \
    '{ for (i = 1; i <= 6; i++) gsub(/^ +| +$/, "", $i); print $1, $2, $3, $4, $5, $6 }' \
    > "$work/rows"
declare -A selected=()
while IFS= read -r name
do
    selected[$name]=1
done < <(cut -d "$us" -f1 "$work/rows" | grep -E -- "$select")
k=0
while IFS="$us" read -r name base app fileRe entryRe edit
do
    [ -n "${selected[$name]:-}" ] || continue
    k=$((k + 1))
    [ $(( (k - 1) % shards + 1 )) -eq "$shard" ] || continue
    n=$((n + 1))
    c=$work/case
    rm -rf "$c"
    if [ -z "$base" ] || [ ! -d "$bases/$base" ] || [ -z "$edit" ]
    then
        echo "FAIL $name: malformed row (base '$base', edit '$edit')"
        failures=$((failures + 1)); continue
    fi
    cp -r "$bases/$base" "$c"
    # stdin from /dev/null: the rows are read from the loop's stdin, and a
    # program that reads it (mpirun forwards it to rank 0) took the rows
    # after it, which then never ran
    if ! (cd "$c" && eval "$edit") < /dev/null > "$work/edit.log" 2>&1
    then
        echo "FAIL $name: the edit failed: $(head -3 "$work/edit.log")"
        failures=$((failures + 1)); continue
    fi
    (cd "$c" && find . -type f ! -name 'log*' -exec md5sum {} +) \
        > "$work/before"
    start=${EPOCHREALTIME/[.,]/}
    (cd "$c" && eval "timeout -k 5 120 $app") < /dev/null > "$work/out" 2>&1
    code=$?
    secs=$(( (${EPOCHREALTIME/[.,]/} - start + 50000)/100000 ))
    secs=$((secs/10)).$((secs%10))
    # the message: from the first error line on (the banner echoes the
    # command line and the case, which must not count as naming them)
    sed -n '/FATAL\|[Ee]rror\|ERROR/,$p' "$work/out" > "$work/msg"
    why=""
    if [ $code -eq 0 ]; then why="exit 0"
    elif [ $code -ge 124 ]; then why="killed, timed out or crashed (exit $code)"
    elif grep -Eq "$crash" "$work/out"; then
        why="crash trace: $(grep -Em1 "$crash" "$work/out")"
    elif ! grep -Eq -- "$fileRe" "$work/msg"; then
        why="the message does not name the file ('$fileRe')"
    elif ! grep -Eq -- "$entryRe" "$work/msg"; then
        why="the message does not name the entry ('$entryRe')"
    elif ! (cd "$c" && md5sum --quiet -c "$work/before") > "$work/md5" 2>&1; then
        why="a file that existed before was changed: $(head -2 "$work/md5" | tr '\n' ' ')"
    fi
    if [ -n "$why" ]
    then
        echo "FAIL $name ($app): $why"
        grep -A8 -E "FATAL|rror" "$work/out" | head -14 | sed 's/^/    /'
        failures=$((failures + 1))
    else
        msg=$(grep -Eh -- "$entryRe" "$work/msg" | head -1 | tr -s ' ' | cut -c1-110)
        printf 'ok   %-28s %5s s exit %d: %s\n' "$name" "$secs" "$code" "$msg"
    fi
done < "$work/rows"

[ $n -gt 0 ] || { echo "badInput: no case matches '$select'" \
    "$([ "$shards" -eq 1 ] || echo "in shard $shard/$shards")"; exit 1; }
echo "badInput corpus: $((n - failures)) of $n cases passed$(
    [ "$shards" -eq 1 ] || echo " (shard $shard/$shards of the $k selected)")"
[ $failures -eq 0 ]
