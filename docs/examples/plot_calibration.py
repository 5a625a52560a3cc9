"""Calibrating the robot arm against rig records
=============================================

The calibration guide's figures (docs/calibration.md), made by the workflows the commands run.

Run: ``python docs/examples/plot_calibration.py`` (writes docs/img/calibration_*.png). The records are the
example files (``hydroservo examples``): the robot arm on the virtual rig with known values.
"""

import os
import shutil
import tempfile
import warnings
from pathlib import Path

from hydroservo.data import example_files
from hydroservo.workflows.calibrate import Calibrate
from hydroservo.workflows.identify import IdentifyFlowCoefficient, IdentifyFriction

IMG = Path(os.environ.get("HYDROSERVO_DOCS_IMG") or Path(__file__).resolve().parents[1] / "img")
warnings.simplefilter("ignore")

work = Path(tempfile.mkdtemp(prefix="hydroservo-docs-"))
for name, text in example_files().items():
    (work / name).write_text(text, encoding="utf-8")


def record(stem: str) -> list[Path]:
    return [work / f"{stem}-200Hz.csv", work / f"{stem}-40Hz.csv"]


report = Calibrate("robot-arm", [record("arm_step")], ["spool.tau", "valve.c_v", "cyl.C_Li", "load.B", "load.F_c0"],
                   inputs=["command.y"], noise=["cyl.pA=0.05 bar", "cyl.pB=0.05 bar", "load.x=0.02 mm"],
                   validate=[record("arm_check")]).run()
files = report.write(work / "cal")
print("\n".join(report.lines()))
shutil.copy(files["fit_1"], IMG / "calibration_fit.png")
shutil.copy(files["validation_1"], IMG / "calibration_validation.png")
calibrated = files["model"]

friction = IdentifyFriction("robot-arm", [record("arm_friction")]).run()
shutil.copy(friction.write(work / "fr")["plot"], IMG / "calibration_friction.png")
print("\n".join(friction.lines()))

flow = IdentifyFlowCoefficient(calibrated, [record("arm_sweep_out"), record("arm_sweep_in")]).run()
shutil.copy(flow.write(work / "kh")["plot"], IMG / "calibration_flow_coefficient.png")
print("\n".join(flow.lines()[:3]))
