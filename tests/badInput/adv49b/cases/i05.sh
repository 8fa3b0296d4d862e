#!/bin/bash
# i05 (class 4, the preview Allrun's -meshType): -meshType Structured, STRUCTURED, tetrahedra, '' (empty), no value at the end,
# given twice (structured then unstructured), and -meshType=structured: each refused before anything is done, naming the
# option, the value and the valid values (unstructured|structured), exit non-zero, the case folder unchanged (no log.*,
# no .allrun file, no .allrunOptions).
. "$(dirname "$0")/../lib.sh"
prev; sums > ../s0
for a in "-meshType Structured" "-meshType STRUCTURED" "-meshType tetrahedra" "-meshType ''" "-meshType" "-meshType structured -meshType unstructured" "-meshType=structured"; do
  eval "tryt 120 \"Allrun $PREV -noRun $a\" ./Allrun $PREV -noRun $a"; echo "   msg: $(grep -a -i -m1 'meshType' $W/try.log | cut -c1-220)"; echo "   changed: $(changed ../s0)"; done
