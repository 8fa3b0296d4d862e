#!/bin/bash
# v72: Allrun locks: a case's Allrun started by hand (sod, 2000 cells) while an outer Allrun (as tutorials/Allrun: Allclean then Allrun of each case) reaches that case
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/outer"; cp -r "$ROOT/tutorials/verification/sodIdealGas" "$W/outer/sod"; cd "$W/outer"
sed -i 's/^endTime .*/endTime 0.01;/' sod/system/riemannProblemDict; sed -i "s/^nCells .*/nCells 2000;/" sod/system/blockMeshDict
cat > Allrun <<'X'
#!/bin/bash
cd "${0%/*}" || exit 1
. "$PROJECT_DIR"/etc/RunFunctions
allrunOptions "" "$@" < /dev/null
for case in sod/; do ( cd "$case" && ./Allclean > /dev/null && ./Allrun ); done
X
chmod +x Allrun; (cd sod && setsid ./Allrun > ../sod.log 2>&1) & hp=$!; for i in $(seq 50); do [ -f sod/log.rhoRiemannFoam ] && break; sleep 0.2; done; sleep 0.5
echo "sod case before: $(ls sod | tr '\n' ' ')"
./Allrun > outer.log 2>&1; echo "outer Allrun rc=$?"; tail -2 outer.log | cut -c1-200; echo "sod case after: $(ls sod | tr '\n' ' ')"
wait $hp; echo "the hand-started sod Allrun rc=$?"; tail -3 sod.log | cut -c1-200
