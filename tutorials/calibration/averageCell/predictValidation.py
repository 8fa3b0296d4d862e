"""Prediction of the validation cell (paper sec. 3.3) with the calibrated
materials: tutorials/indentation/validationCell (default mesh, stage A to
0.3 nN) with constant/solidProperties.calibrated of this case; its peaks
against the paper's Table 3 in validationCell/results.md."""

import os
import shutil
import subprocess
import sys

try:
    from neuronFsi import script
except ImportError:
    sys.exit("predictValidation.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import logs, postProcessing, scratch

here = os.path.dirname(os.path.abspath(__file__))
src = os.path.join(os.environ["FOAM_TUTORIALS"], "indentation/validationCell")
case = os.path.join(here, "validationCell")
calibrated = os.path.join(here, "constant/solidProperties.calibrated")
if not os.path.isfile(calibrated):
    sys.exit("predictValidation: no %s (run calibrateCell first)"
             % calibrated)
shutil.rmtree(case, ignore_errors=True)
scratch.copyInputs(src, case, ("system", "constant"))
shutil.copy(calibrated, os.path.join(case, "constant/solidProperties"))
for app in ("cellMesh", "cellIndentationFoam"):
    with open(os.path.join(case, "log." + app), "w") as log:
        if subprocess.call([app], cwd=case, stdout=log,
                           stderr=subprocess.STDOUT):
            sys.exit("predictValidation: %s failed (see %s)"
                     % (app, log.name))

# Paper Table 3 (its "mN" are nN): experiment and the paper's simulation
labels = ["C%d,%s" % (c, r) for c in (1, 2, 3) for r in ("i", "ii", "iii")]
experiment = [11.5, 10.8, 10.3, 5.0, 4.9, 4.8, 3.0, 3.0, 3.0]
simulation = [11.5, 11.0, 10.2, 5.3, 4.6, 4.3, 2.5, 2.5, 2.5]
table = postProcessing.readTable(os.path.join(
    case, "postProcessing/indentation/peaks.dat"))
peaks = {label: force*1e9 for label, force in
         zip(table.column("label"), table.column("force", finite=True))}
run = logs.indentationRun(os.path.join(case, "log.cellIndentationFoam"))
delta0, cpu, ne = run["delta0"]*1e6, run["cpu"], run["elements"]
ours = [peaks[k] for k in labels]
err = [100*(o/e - 1) for o, e in zip(ours, experiment)]
L = ["Validation cell with the calibrated materials: %d elements, delta0 = "
     "%.3f um (paper 0.84 um), F_B = %.3f nN, F_E = %.3f nN, CPU %.1f s"
     % (ne, delta0, peaks["endB"], peaks["endE"], cpu), "",
     "| | " + " | ".join(labels) + " |", "|---" * 10 + "|",
     "| paper experiment [nN] | " + " | ".join("%.1f" % v for v in experiment)
     + " |",
     "| paper simulation [nN] | " + " | ".join("%.1f" % v for v in simulation)
     + " |",
     "| calibrated [nN] | " + " | ".join("%.3f" % v for v in ours) + " |",
     "| vs experiment | " + " | ".join("%+.0f %%" % e for e in err) + " |",
     "", "Mean absolute error against the experiment: %.1f %%"
     % (sum(abs(e) for e in err)/len(err))]
open(os.path.join(case, "results.md"), "w").write("\n".join(L) + "\n")
