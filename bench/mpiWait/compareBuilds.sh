#!/bin/bash
# The results of two builds compared bit for bit (issue 18 item 5, branch
# eff18c: a change of the exchanges that must not change one bit).
#
#   bench/mpiWait/compareBuilds.sh DIR BASE NEW [END]
#       DIR   scratch folder (created; must not exist)
#       BASE, NEW  two builds: copies of a worktree's
#             platforms/linux64GccDPInt32Opt (bin/, lib/), e.g. main's
#             build copied before a branch's rebuild
#       END   endTime of the serial quarter [s] (default 1.5e-8)
#     runs, each with BASE then NEW (the two quarters at the same time):
#       - the tutorial's 3D quarter (tutorials/blast/quarter3D, Allrun
#         -noRun -endTime END, prepared once) with cellBlastFoam, serial;
#       - the colliding 50 MPa shock tube of tests/verification/
#         parallelEqualsSerial.sh (rhoRiemannFoam: the fixed-mesh step)
#         serial and on 2 ranks;
#     and compares them as --cases does (the shock tubes: every file).
#
#   bench/mpiWait/compareBuilds.sh --cases A B
#       two finished runs of the quarter (e.g. DIR/quarter3D of two
#       mpiWait.sh runs with BUILD= two builds): the logs and solid.h5
#       (tests/blast/compareRestart.py --bitwise --h5), the coupling, water
#       probe and interface maxima files (cmp), every file of every written
#       time (serial or processor*/, cmp).
#
# Exit status non-zero on any difference. NICENESS=N: the runs at nice -n N
# (default 10).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
nice=${NICENESS:-10}

compareCases()
{
    local a=$1 b=$2 f t n=0 d=0 p
    /usr/bin/python3 "$root/tests/blast/compareRestart.py" "$a" "$b" \
        --bitwise --h5
    for f in postProcessing/fsi/0/coupling.dat postProcessing/fluidProbes/0/p \
        postProcessing/solidInterfaces/0/interfaceMaxima.dat
    do
        cmp "$a/$f" "$b/$f"
        echo "identical: $f"
    done
    for p in . $(cd "$a" && ls -d processor* 2>/dev/null)
    do
        for t in $(cd "$a/$p" && ls -d [0-9]* 2>/dev/null | grep -v '^0$')
        do
            while read -r f
            do
                n=$((n + 1))
                cmp -s "$a/$p/$t/$f" "$b/$p/$t/$f" \
                    || { d=$((d + 1)); echo "DIFFERENT: $p/$t/$f"; }
            done < <(cd "$a/$p/$t" && find . -type f)
        done
    done
    echo "written times: $n files compared, $d different"
    [ "$d" -eq 0 ] && [ "$n" -gt 0 ]
}

if [ "${1:-}" = --cases ]
then
    [ $# -eq 3 ] || { sed -n 2,30p "$0"; exit 1; }
    compareCases "$2" "$3"
    exit
fi

[ $# -ge 3 ] || { sed -n 2,30p "$0"; exit 1; }
dir=$1; base=$2; new=$3; end=${4:-1.5e-8}
for b in "$base" "$new"
do
    [ -x "$b/bin/cellBlastFoam" ] && [ -x "$b/bin/rhoRiemannFoam" ] \
        && [ -d "$b/lib" ] || {
        echo "compareBuilds.sh: $b has no bin/cellBlastFoam," \
             "bin/rhoRiemannFoam and lib/" >&2
        exit 1
    }
done
[ ! -e "$dir" ] || { echo "compareBuilds.sh: $dir exists" >&2; exit 1; }
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
base=$(cd "$base" && pwd)
new=$(cd "$new" && pwd)

# with build $1 in case $2: the command
with()
{
    local b=$1 c=$2
    shift 2
    (cd "$c" && PATH=$b/bin:$PATH LD_LIBRARY_PATH=$b/lib:$LD_LIBRARY_PATH \
        nice -n "$nice" "$@")
}

echo "== $(date -u '+%F %H:%M UTC'), load $(cut -d' ' -f1-3 /proc/loadavg)"
python3 -m neuronFsi.scratch "$root/tutorials/blast/quarter3D" \
    "$dir/prepared" 0.orig constant system Allrun --ignore polyMesh '*.msh'
(cd "$dir/prepared" && PROJECT_DIR=$root ./Allrun -noRun -noPlots \
    -endTime "$end" > log.prepare 2>&1) \
    || { tail -20 "$dir/prepared/log.prepare"; exit 1; }
cp -a "$dir/prepared" "$dir/quarterBase"
cp -a "$dir/prepared" "$dir/quarterNew"
with "$base" "$dir/quarterBase" cellBlastFoam > "$dir/quarterBase/log.run" 2>&1 &
pidBase=$!
with "$new" "$dir/quarterNew" cellBlastFoam > "$dir/quarterNew/log.run" 2>&1 &
pidNew=$!
wait $pidBase
wait $pidNew
echo "quarter, serial, to $end s: $(grep -c '^Time =' "$dir/quarterBase/log.run")" \
    "/ $(grep -c '^Time =' "$dir/quarterNew/log.run") steps"
compareCases "$dir/quarterBase" "$dir/quarterNew"

src=$root/tutorials/verification/waterCollision50MPa
for n in 1 2
do
    for b in base new
    do
        c=$dir/shockTube${n}_$b
        mkdir "$c"
        cp -r "$src"/{0.orig,system,constant} "$c"/
        rm -rf "$c/constant/polyMesh"
        # as tests/verification/parallelEqualsSerial.sh: the waves cross
        # the processor boundary
        sed -i 's/^x0 .*/x0          -10e-6;/' "$c/system/riemannProblemDict"
        cat > "$c/system/decomposeParDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method          simple;
coeffs          { n (2 1 1); }
DICT
        build=$base
        [ $b = new ] && build=$new
        with "$build" "$c" bash -c \
            'cp -r 0.orig 0 && blockMesh > log.blockMesh && setRiemannProblem > log.set'
        if [ $n = 1 ]
        then
            with "$build" "$c" rhoRiemannFoam > "$c/log.solver" 2>&1
        else
            with "$build" "$c" decomposePar > "$c/log.decomposePar" 2>&1
            with "$build" "$c" mpirun -np 2 --bind-to none -x PATH \
                -x LD_LIBRARY_PATH rhoRiemannFoam -parallel \
                > "$c/log.solver" 2>&1
        fi
        grep -q '^End' "$c/log.solver"
    done
    diff -r -q -x 'log.*' "$dir/shockTube${n}_base" "$dir/shockTube${n}_new"
    echo "shock tube on $n rank(s): every file identical" \
         "($(cd "$dir/shockTube${n}_base" && find . -type f ! -name 'log.*' \
             | wc -l) files, $(grep -c '^Time =' \
             "$dir/shockTube${n}_base/log.solver") steps)"
done
echo "compareBuilds.sh: no difference"
