#!/bin/bash
# w48: planeWave -probes and -except with wrong values: -probes nothing, -probes solid,solid, -except p9, -except ''
. "$(dirname "$0")/../lib.sh"
blastDone; for o in "-probes nothing" "-probes solid,solid" "-except p9" "-except ,"; do try "$o" planeWave -case . $o; done
