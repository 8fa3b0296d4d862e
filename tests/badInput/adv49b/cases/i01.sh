#!/bin/bash
# i01 (class 4, cellMesh `meshType`): the r-z dictionary with meshType Structured (case), STRUCTURED, 'structured ' quoted,
# a number, a list, an empty word, given twice in the dictionary, and `unstructured` in quarter3D: each refused naming the
# file, the entry, the value and the valid values (and the closest one), exit non-zero, no cell.msh written; `structured`
# and `unstructured` in r-z and `structured` in quarter3D mesh (exit 0, cell.msh written).
. "$(dirname "$0")/../lib.sh"
for v in Structured STRUCTURED '"structured "' 1 '(structured)' '""' 'structured; meshType structured'; do
  mdir; mset meshType "$v"; cm; echo "   cell.msh: $(ls constant/cell.msh 2>/dev/null || echo none)"; done
mdir quarter3D; mset meshType unstructured; cm; echo "   cell.msh: $(ls constant/cell.msh 2>/dev/null || echo none)"
for m in axisymmetric quarter3D; do for v in structured unstructured; do [ $m = quarter3D ] && [ $v = unstructured ] && continue
  mdir $m; mset meshType $v; cm; echo "   $m $v: cell.msh $(ls -s constant/cell.msh 2>/dev/null || echo none); $(grep -a -i -m2 'structured\|contact' $W/try.log | cut -c1-160 | tr '\n' '|')"; done; done
