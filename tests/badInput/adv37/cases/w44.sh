#!/bin/bash
# w44: solidToFoam on the wrong files: an indentation restart.h5, a text file named x.h5, a missing file, a directory
. "$(dirname "$0")/../lib.sh"
indDone; try restart.h5 solidToFoam postProcessing/indentation/restart.h5; echo hello > x.h5; try text.h5 solidToFoam x.h5; try missing solidToFoam nothere.h5; mkdir d.h5; try directory solidToFoam d.h5
