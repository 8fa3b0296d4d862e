# mk.sh ID "header" < body: writes cases/ID.sh (sourced by the case generator only)
mk() { { echo '#!/bin/bash'; echo "# $1: $2"; echo '. "$(dirname "$0")/../lib.sh"'; cat; } > cases/$1.sh; }
