#!/bin/bash
# v40: Allrun locks: nested: an outer Allrun (lock of the folder above) runs the sod case's Allrun; meanwhile the outer Allrun again, the sod Allrun by hand and rhoRiemannFoam by hand
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/outer"; cp -r "$ROOT/tutorials/verification/sodIdealGas" "$W/outer/sod"; cd "$W/outer"
sed -i 's/^endTime .*/endTime 0.01;/' sod/system/riemannProblemDict; sed -i "s/^nCells .*/nCells 2000;/" sod/system/blockMeshDict
cat > Allrun <<'X'
#!/bin/bash
cd "${0%/*}" || exit 1
. "$PROJECT_DIR"/etc/RunFunctions
allrunOptions "" "$@" < /dev/null
( cd sod && ./Allclean > /dev/null && ./Allrun )
X
chmod +x Allrun; setsid ./Allrun > log.outer 2>&1 & ap=$!; for i in $(seq 50); do [ -f sod/log.rhoRiemannFoam ] && break; sleep 0.2; done; sleep 0.5
echo "sod solver running: $(pgrep -s $ap rhoRiemann | head -1)"
./Allrun > log.outer2 2>&1; echo "outer again rc=$?"; head -2 log.outer2 | cut -c1-200
(cd sod && ./Allrun > log.hand 2>&1; echo "sod Allrun by hand rc=$?"; head -2 log.hand | cut -c1-200)
(cd sod && rhoRiemannFoam > log.handsolver 2>&1; echo "rhoRiemannFoam by hand rc=$?"; grep -a -A1 FATAL log.handsolver | tail -1 | cut -c1-200)
wait $ap; echo "outer rc=$?"; tail -2 log.outer
