# lib.sh (adv44): adv43's lib.sh (tests/badInput/adv43: all helpers of adv35-adv43: ind/indDone, indKilled, blast/blastDone,
# pblast/pblastDone, blastEnd, latest, restart0, sums, changed, nochange, kept, tryf, try, run, fatal, waitFor, sameSeries,
# study, setStudy, cal, prev/PREV, wpDone, blastRef, cmpRef, killAt, marks, flip, h5same, nul, ...) with ADV defaulting to
# /tmp/adv44-adv44, plus:
#   where TEXT...    for each TEXT: "kept (files)" or "GONE", searched in the whole work folder $W (not only the case)
ADV=${ADV:-/tmp/adv44-adv44}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv43/lib.sh"
where() { local t w; for t in "$@"; do w=$(grep -rl --exclude='log.*' -- "$t" $W 2>/dev/null | sed "s|$W/||" | tr '\n' ' '); echo "   '$t': ${w:-GONE}"; done; }
#   iblast [END]     a copy of the preview prepared by its Allrun with a planeWaveInflow top (-Z 40e-6 -inflow 20e-6, -noRun:
#                    constant/inflowWave written by its planeWave -inflow step; END (2e-9) s, writes every 1 ns), cd there; IW holds
#                    the planeWave options that make the same wave ("-inflow 20e-6 -Z 40e-6")
iblast() { prev; ./Allrun -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 40e-6 -inflow 20e-6 -endTime ${1:-2e-9} -writeInterval 1e-9 -noPlots -noVTK -noRun > log.prep 2>&1 || { echo "iblast: Allrun failed"; tail -3 log.prep; }; }
IW="-inflow 20e-6 -Z 40e-6"
#   iEnd END         endTime END in iblast's system/controlDict.allrun (its other lines, the inflow's probes, kept)
iEnd() { sed -i "s/^endTime .*/endTime $1;/" system/controlDict.allrun; grep -q '^endTime' system/controlDict.allrun || echo "endTime $1;" >> system/controlDict.allrun; }
