#!/bin/bash
# transparentCell.sh DIR SCALE LAW [Allrun options]: the axisymmetric
# preview (a copy in DIR, tests/blast/runPreview.sh) at mesh level xSCALE
# (-h 0.25e-6 SCALE, -far 1e-6 SCALE, -dz 0.25e-6 SCALE, -cell 0.5e-6
# SCALE: the ladder of docs/results/blastPlaneWave.md, "The default at
# x0.7"; with -inflow 20e-6 and -outer 8 times -far unless given, the
# tutorial's defaults when those ladders were run; SCALE default: the
# tutorial's default sizes, none given), with water probes at z = 10 um,
# r = 0.1, 1, 2, 4, 8 um, and LAW:
#   water  the transparent cell: the membrane's quadratic law (paper eq. 2)
#          replaced by water's Mie-Grueneisen law (nucleus and cytoplasm
#          have it already, every region rho0 1000 kg/m^3): the whole
#          scene is water to its shear moduli (1e2 Pa against K = 2 GPa),
#          so the water-only 1D column is its exact answer;
#   posed  the tutorial's cell as it is.
# Then cellBlastFoam, planeWave -check (DIR/axisymmetricPreview/
# log.planeWaveCheck) and, for posed, planeWave -check -layered
# (log.planeWaveLayered). Prints the water cells, the time loop's CPU and
# the check's table. MEMBRANE_LAYERS (environment, optional): the
# membrane's elements across its 200 nm (cellMeshDict membraneLayers; the
# tutorial's 1 at every level), the cell's mesh written again with it.
# Further settings from the environment (optional; docs/results/
# blastPlaneWave.md, "The cheapest default that meets item 1"):
#   SCALE_H, SCALE_FAR, SCALE_DZ, SCALE_CELL  that size's level instead of
#          SCALE (-h, -far, -dz, -cell: e.g. SCALE_DZ=0.35 refines only
#          the column above the cell's box)
#   CELL_MESH '...'  entries appended to system/cellMeshDict.allrun, the
#          cell's mesh written again (e.g. 'nucleusSize 1.75e-7;
#          cytoplasmSize 1.75e-7;': the cell's interior finer than -cell,
#          its membrane's faces, which the water's -h must resolve, not)
#   LIMITER   the fluid's reconstruct() limiter in system/fvSchemes: MUSCL
#          (the tutorial's), vanLeer, vanAlbada, Minmod (U: its V scheme),
#          or a multidimensional one, BarthJespersen, venkatakrishnan (U
#          the same name: per component)
#   MAXCO     the fluid Courant number (system/controlDict maxCo; 0.9)
#   SOLID_OVERRIDE '...'  appended to the copy's constant/
#          solidProperties.allrun (as bench/blast/probeOvershoot3D.sh), e.g.
#          'materials { nucleus { b1 0.06; b2 1.2247; } ... }': the solid's
#          linear and quadratic artificial bulk viscosity of a region
#          (the library's default 0.06 1.2)
#   REFERENCE FILE  planeWave -reference FILE: the reference.dat of an
#          earlier run of the same pulse, column and probe heights
# Issue 17 item 1 (docs/results/blastPlaneWave.md, "The transparent
# cell"); tests/blast/transparentCell.sh runs it at x1. Example:
#   bench/blast/transparentCell.sh /tmp/t07 0.7 water -pulse 1e-8 -endTime 9e-8
set -euo pipefail
[ $# -ge 3 ] || { sed -n 2,40p "$0"; exit 1; }
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
dir=$1; scale=$2; law=$3; shift 3
case $law in water|posed) ;; *) echo "transparentCell.sh: LAW $law: water or posed" >&2; exit 1 ;; esac
size() { /usr/bin/python3 -c "import sys; print('%.6g' % (float(sys.argv[1])*float(sys.argv[2])))" "$1" "${2:-$scale}"; }
sizes=()
# SCALE default: the tutorial's default sizes (no -h, -far, -dz, -cell);
# a level: those sizes, and the water to 20 um with the ring graded to 8
# -far (the tutorial's defaults before 2026-12-05, with which the ladders
# of the docs were run) unless -inflow or -outer is given
if [ "$scale" != default ]
then
    far=$(size 1e-6 "${SCALE_FAR:-}")
    sizes=(-h "$(size 0.25e-6 "${SCALE_H:-}")" -far "$far" \
        -dz "$(size 0.25e-6 "${SCALE_DZ:-}")" -cell "$(size 0.5e-6 "${SCALE_CELL:-}")")
    case " $* " in *" -inflow "*) ;; *) sizes+=(-inflow 20e-6) ;; esac
    case " $* " in *" -outer "*) ;; *) sizes+=(-outer "$(size 8 "$far")") ;; esac
fi
# DIR.log only over this script's own earlier log (its DIR an earlier
# output of runPreview.sh): a user's file of that name was overwritten
# (adv51 n01 (f)); DIR itself is runPreview.sh's to check
if [ -e "$dir.log" ] && [ "$(cat "$dir/.scratchFolder" 2>/dev/null)" != runPreview.sh ]
then
    echo "transparentCell.sh: error: $dir.log exists and is not the log of" \
        "an earlier run of this script: give another DIR, or move it away." \
        "Nothing was removed." >&2
    exit 1
fi
bash "$here/../../tests/blast/runPreview.sh" "$dir" "${sizes[@]}" \
    -noPlots -noVTK -noRun "$@" > "$dir.log" 2>&1 \
    || { tail -5 "$dir.log"; exit 1; }
cd "$dir/axisymmetricPreview"
/usr/bin/python3 - <<'PY'
import re
# the water probes at z = 10 um (below the inflow plane)
f = "system/controlDict.allrun"
s = open(f).read()
probes = " ".join("(%g 1e-05 0)" % r for r in (1e-7, 1e-6, 2e-6, 4e-6, 8e-6))
s, n = re.subn(r"probeLocations \([^;]*\);", "probeLocations ( %s );" % probes, s)
if n != 1:
    raise SystemExit("transparentCell.sh: no probeLocations in %s" % f)
open(f, "w").write(s)
PY
if [ "$law" = water ]
then
    python3 -m neuronFsi.membraneLaw water constant/solidProperties || exit 1
fi
if [ -n "${MEMBRANE_LAYERS:-}${CELL_MESH:-}" ]
then
    [ -z "${MEMBRANE_LAYERS:-}" ] \
        || echo "membraneLayers $MEMBRANE_LAYERS;" >> system/cellMeshDict.allrun
    [ -z "${CELL_MESH:-}" ] || /usr/bin/python3 - "$CELL_MESH" <<'PY'
import re, sys
# each "key value;" of CELL_MESH replaces the entry Allrun wrote, or is added
f = "system/cellMeshDict.allrun"
s = open(f).read()
for key, value in re.findall(r"(\w+)\s+([^;]+);", sys.argv[1]):
    s, n = re.subn(r"^%s .*;$" % key, "%s %s;" % (key, value), s, flags=re.M)
    if n == 0:
        s += "%s %s;\n" % (key, value)
open(f, "w").write(s)
PY
    cellMesh > log.cellMesh 2>&1 || { tail -3 log.cellMesh; exit 1; }
    grep "membrane thickness" log.cellMesh
    grep -v "^//" system/cellMeshDict.allrun | paste -sd' '
fi
if [ -n "${LIMITER:-}" ]
then
    case $LIMITER in
        MUSCL|vanLeer|vanAlbada|Minmod) vector=${LIMITER}V ;;
        BarthJespersen|venkatakrishnan) vector=$LIMITER ;;
        *) echo "transparentCell.sh: LIMITER $LIMITER: MUSCL, vanLeer, vanAlbada, Minmod, BarthJespersen or venkatakrishnan" >&2; exit 1 ;;
    esac
    for v in rho p
    do
        foamDictionary -entry "interpolationSchemes/reconstruct($v)" -set "$LIMITER" system/fvSchemes > /dev/null
    done
    foamDictionary -entry "interpolationSchemes/reconstruct(U)" -set "$vector" system/fvSchemes > /dev/null
    foamDictionary -entry interpolationSchemes -value system/fvSchemes | grep reconstruct | tr -s ' ' | paste -sd' '
fi
if [ -n "${MAXCO:-}" ]
then
    foamDictionary -entry maxCo -set "$MAXCO" system/controlDict > /dev/null
    echo "maxCo $(foamDictionary -entry maxCo -value system/controlDict)"
fi
if [ -n "${SOLID_OVERRIDE:-}" ]
then
    echo "$SOLID_OVERRIDE" >> constant/solidProperties.allrun
    echo "constant/solidProperties.allrun + $SOLID_OVERRIDE"
fi
# the regions' volumetric laws, as the solver reads them
foamDictionary -expand constant/solidProperties 2>/dev/null \
    | grep -E "^ *(volumetric|rho0|C0|d0|b1|b2) " | tr -s ' ' | paste -sd' '
echo "water cells: $(awk '/^ *cells:/ {print $2; exit}' log.checkMesh)"
nice -n 10 cellBlastFoam > log.cellBlastFoam 2>&1
grep "^CPU time of the time loop" log.cellBlastFoam
status=0
reference=()
[ -z "${REFERENCE:-}" ] || reference=(-reference "$REFERENCE")
nice -n 10 planeWave -case . -check "${reference[@]}" > log.planeWaveCheck 2>&1 || status=$?
grep -v "^#" log.planeWaveCheck
if [ "$law" = posed ]
then
    nice -n 10 planeWave -case . -check -layered > log.planeWaveLayered 2>&1 \
        || status=$?
    echo "layered:"
    grep -v "^#" log.planeWaveLayered
fi
exit $status
