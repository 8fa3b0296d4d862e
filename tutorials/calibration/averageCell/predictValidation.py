"""Prediction of the validation cell (paper sec. 3.3) with the calibrated
materials: tutorials/indentation/validationCell (default mesh, stage A to
0.3 nN) with constant/solidProperties.calibrated of this case; its peaks
against the paper's Table 3 in validationCell/results.md."""

import atexit
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
import fnmatch

from neuronFsi import caseLock, logs, postProcessing, scratch

here = os.path.dirname(os.path.abspath(__file__))
src = os.path.join(os.environ["FOAM_TUTORIALS"], "indentation/validationCell")
case = os.path.join(here, "validationCell")
calibrated = os.path.join(here, "constant/solidProperties.calibrated")
if not os.path.isfile(calibrated):
    sys.exit("predictValidation: no %s (run calibrateCell first)"
             % calibrated)
# The tutorial's lock for the whole prediction (adv51 n06 (b): a second
# predictValidation.py removed the case the first's solver ran in; n10:
# the Allclean removed it under the running solver): under its Allrun the
# Allrun's lock, taken over. The new prediction is made in
# validationCell.new and replaces validationCell only once it has its
# results (adv51 n06 (a): a re-run killed after 20 s had removed the
# earlier prediction first); validationCell must be an earlier prediction
# of this script (a user's file there is named, nothing removed)
OWN = ("system", "constant", "log.*", "postProcessing", "results.md", "VTK",
       "[0-9]*", caseLock.FILE)
lock = caseLock.held(here, "predictValidation.py")
lock.__enter__()
atexit.register(lock.__exit__, None, None, None)
new = case + ".new"
# a prediction of a build before this rule has no marker: it is this
# script's when every entry is of its kind
if os.path.isdir(case) and not os.path.exists(os.path.join(case,
                                                          scratch.MARKER)) \
        and all(any(fnmatch.fnmatchcase(n, e) for e in OWN)
                for n in os.listdir(case)):
    with open(os.path.join(case, scratch.MARKER), "w") as f:
        f.write("predictValidation.py\n")
scratch.checkOutputFolder("predictValidation.py", case, OWN)
scratch.outputFolder("predictValidation.py", new, OWN)
scratch.copyInputs(src, new, ("system", "constant"))
shutil.copy(calibrated, os.path.join(new, "constant/solidProperties"))
for app in ("cellMesh", "cellIndentationFoam"):
    with open(os.path.join(new, "log." + app), "w") as log:
        if subprocess.call([app], cwd=new, stdout=log,
                           stderr=subprocess.STDOUT):
            sys.exit("predictValidation: %s failed (see %s; %s is kept)"
                     % (app, log.name, case))

# Paper Table 3 (its "mN" are nN): experiment and the paper's simulation
labels = ["C%d,%s" % (c, r) for c in (1, 2, 3) for r in ("i", "ii", "iii")]
experiment = [11.5, 10.8, 10.3, 5.0, 4.9, 4.8, 3.0, 3.0, 3.0]
simulation = [11.5, 11.0, 10.2, 5.3, 4.6, 4.3, 2.5, 2.5, 2.5]
table = postProcessing.readTable(os.path.join(
    new, "postProcessing/indentation/peaks.dat"))
peaks = {label: force*1e9 for label, force in
         zip(table.column("label"), table.column("force", finite=True))}
run = logs.indentationRun(os.path.join(new, "log.cellIndentationFoam"))
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
open(os.path.join(new, "results.md"), "w").write("\n".join(L) + "\n")
# the new prediction replaces the earlier one (checked above: this
# script's own) only now that it has its results
if os.path.isdir(case):
    shutil.rmtree(case)
os.rename(new, case)
