#!/bin/bash
# x61: calibrateCell curve targets from CSV files at edges never tried: one data row, only a header, the last time repeated (times not strictly increasing), a quoted decimal comma ("1,5e-10"), a force 0 everywhere: refused naming file, row and reason before any forward run?
. "$(dirname "$0")/../lib.sh"
cal; cp system/calibrationDict ../cd0; sed -i '/^targets/,$d' system/calibrationDict; printf 'targets\n{\n    curve { file "m.csv"; sigma 0.02e-9; }\n}\n' >> system/calibrationDict
for c in 'time [s],force [N]\n1,1e-10' 'time [s],force [N]' 'time [s],force [N]\n0,0\n1,1e-10\n1,2e-10' 'time [s],force [N]\n0,0\n1,"1,5e-10"' 'time [s],force [N]\n0,0\n1,0\n2,0'; do printf "$c\n" > m.csv; try "$(echo "$c" | tr '\n' '|' | cut -c1-40)" timeout 50 calibrateCell -nProcs 1; done; ls postProcessing 2>/dev/null
