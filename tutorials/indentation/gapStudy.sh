#!/bin/bash
# Short runs behind the gap study of docs/results/indentation.md: stage A
# (until 0.3 nN, the validation cell's criterion), the 15 s hold B and the
# first 10 um/s cycle, so each variant gives delta0, F_B and the fast peak
# C1,i in a few CPU seconds.
#
# usage: gapStudy.sh <case> <name> [key=value ...]
#   <case>   averageCell | validationCell
#   key      an entry of system/cellMeshDict, constant/indenterProperties
#            or constant/solidProperties (replaced where it is found), or
#            cellMaterials=<set>: the paper's parameter set included in
#            materials (table, text, textFactor4, instantaneous:
#            etc/caseDicts/cellMaterials), or
#            membraneAs=<region>: the membrane takes that region's paper
#            material (C10, mu1, tau1) of Table 2, or
#            material.<region>=C10,mu1,tau1: that region's material
#            [Pa, Pa, s]
# Prints: name, elements, delta0 [um], F_B [nN], C1,i [nN], CPU time [s].
# FULL=1 keeps the case's whole protocol (Table 1) and prints the nine
# peaks and F_E [nN] as well.
# WORK (default: a temporary directory) keeps the case folders.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
src=$1 name=$2
shift 2
work=${WORK:-$(mktemp -d)}
c=$work/${src}_$name
# an earlier case of this script only, never a user's folder (adv51 n01)
. "$here/../../etc/scratchFolder"
scratchFolder gapStudy.sh "$c" @case
cp -r "$here/$src/." "$c/"
cd "$c"
/usr/bin/python3 - "$@" <<'PY'
import os, re, sys
from neuronFsi.indenterProperties import setProtocol
files = ["system/cellMeshDict", "constant/indenterProperties",
         "constant/solidProperties"]
text = {f: open(f).read() for f in files}
# the short protocol: A (to 1.41 um, or to at most 3 um when it ends at
# forceTarget), B and one fast cycle
A = "3e-6" if re.search(r"\nforceTarget\s", text["constant/indenterProperties"]) \
    or any(kv.startswith("forceTarget=") for kv in sys.argv[1:]) else "1.41e-6"
if os.environ.get("FULL") != "1":
  text["constant/indenterProperties"] = setProtocol(
      text["constant/indenterProperties"],
      [("A", "load", "0.3e-6", A), ("B", "hold", "0", "15"),
       ("C1", "load", "10e-6", "2e-6"), ("C1", "unload", "10e-6", "2e-6")],
      "constant/indenterProperties")
from neuronFsi import foamDict
TABLE2 = foamDict.read(os.path.join(os.environ["PROJECT_DIR"],
                                    "etc/caseDicts/cellMaterials/table"))
PAPER = {r: (TABLE2[r]["C10"], TABLE2[r]["mu1"], TABLE2[r]["tau1"])
         for r in ("membrane", "cytoplasm")}
def material(region, C10, mu1, tau1):
    """A region's material, last in the materials of solidProperties"""
    t, n = re.subn(r"(\nmaterials\s*\{.*?)(\n\})",
                   lambda m: m.group(1) + "\n    %s { C10 %r; d0 0; mu1 %r; "
                   "tau1 %r; }" % (region, C10, mu1, tau1) + m.group(2),
                   text["constant/solidProperties"], count=1, flags=re.S)
    if not n:
        sys.exit("gapStudy: no materials in constant/solidProperties")
    text["constant/solidProperties"] = t
for kv in sys.argv[1:]:
    k, v = kv.split("=", 1)
    if k.startswith("material."):
        material(k.split(".", 1)[1], *(float(x) for x in v.split(",")))
        continue
    if k == "membraneAs":
        material("membrane", *PAPER[v])
        continue
    if k == "cellMaterials":
        t, n = re.subn(r"cellMaterials/\w+", "cellMaterials/" + v,
                       text["constant/solidProperties"])
        if not n:
            sys.exit("gapStudy: no #include of etc/caseDicts/cellMaterials "
                     "in constant/solidProperties")
        text["constant/solidProperties"] = t
        continue
    for f in files:
        # solidProperties: also the entries of materials
        indent = "[ \t]*" if f == "constant/solidProperties" else ""
        t, n = re.subn(r"(\n%s%s\s+)[^;]*;" % (indent, re.escape(k)),
                       lambda m: m.group(1) + v + ";", text[f])
        if n:
            text[f] = t
            break
    else:
        if k == "forceTarget":
            text["constant/indenterProperties"] += "\nforceTarget %s;\n" % v
        else:
            sys.exit("gapStudy: no entry '%s' in %s" % (k, files))
for f in files:
    open(f, "w").write(text[f])
PY
cellMesh > log.cellMesh 2>&1 || { tail log.cellMesh; exit 1; }
cellIndentationFoam > log.cellIndentationFoam 2>&1 \
    || { tail -5 log.cellIndentationFoam; exit 1; }
/usr/bin/python3 - "$name" <<'PY'
import re, sys
log = open("log.cellIndentationFoam").read()
ne = re.search(r"(\d+) elements", log).group(1)
cpu = re.search(r"CPU time ([0-9.]+) s", log).group(1)
m = re.search(r"delta0 = ([0-9.eE+-]+) m", log)
d0 = float(m.group(1))*1e6 if m else 1.41
pk = {l.split()[0]: float(l.split()[3])*1e9
      for l in open("postProcessing/indentation/peaks.dat")
      if not l.startswith("#")}
if "endE" in pk:
    keys = ["endB"] + ["C%d,%s" % (c, r) for c in (1, 2, 3)
                       for r in ("i", "ii", "iii")] + ["endE"]
    print("| %s | %s | %.3f | %s | %s |" % (sys.argv[1], ne, d0,
          " | ".join("%.3f" % pk[k] for k in keys), cpu))
else:
    print("| %s | %s | %.3f | %.3f | %.2f | %s |"
          % (sys.argv[1], ne, d0, pk["endB"], pk["C1,i"], cpu))
PY
