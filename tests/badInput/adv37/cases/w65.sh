#!/bin/bash
# w65: calibrateCell -nProcs at the edges: 0, -1, 2.5, nan, 1e9
. "$(dirname "$0")/../lib.sh"
cal; for n in 0 -1 2.5 nan 1e9; do try "-nProcs $n" calibrateCell -case . -nProcs $n; done
