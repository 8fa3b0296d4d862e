#!/bin/bash
# CASETIMEOUT=300
# o09b (o09 (h), (i) with the right names: fix19h's NOT covered list): (i) bench/fluid/run.py --quick --parts 1 --out DIR
# with a user's DIR/cost/1D_rhoRiemannFoam_SSPRK3/notes.txt (a folder name run.py writes there); (h) bench/fluid/
# memoryPerCell.py --out DIR --sizes "40 60" --steps 1 with a user's DIR/box40/notes.txt. Each stopped after 25 s: the
# user's file kept or refused = OK; removed = DATALOSS (documented as not changed by fix19h).
. "$(dirname "$0")/../lib.sh"
B=$ROOT/bench; U=$W/u
run() { local l=$1; shift; tryt 25 "$l" "$@"; echo "   said: $(grep -a -m2 -i 'error\|refus\|exists' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"; killAll $W; }
rm -rf $U; mkdir -p $U/d; cd $U/d; mark cost/1D_rhoRiemannFoam_SSPRK3/notes.txt; cd $W
run "(i) bench/fluid/run.py --quick --parts 1 --out DIR (DIR/cost/1D_rhoRiemannFoam_SSPRK3/notes.txt)" /usr/bin/python3 $B/fluid/run.py --quick --parts 1 --out $U/d; cd $U/d; kept_ cost/1D_rhoRiemannFoam_SSPRK3/notes.txt; echo "   DIR/cost: $(ls cost | tr '\n' ' ')"; cd $W
rm -rf $U; mkdir -p $U/d; cd $U/d; mark box40/notes.txt; cd $W
run "(h) bench/fluid/memoryPerCell.py --out DIR --sizes '40 60' --steps 1 (DIR/box40/notes.txt)" /usr/bin/python3 $B/fluid/memoryPerCell.py --out $U/d --sizes "40 60" --steps 1; cd $U/d; kept_ box40/notes.txt; cd $W
