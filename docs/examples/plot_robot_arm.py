"""Robot arm: fidelity ladder and Sobol indices
============================================

The robot-arm study's figures: the fidelity ladder's error map, and the Sobol indices of six parameters.

Run: ``python docs/examples/plot_robot_arm.py`` (writes docs/img/robot_arm_ladder.png and
docs/img/robot_arm_sobol.png, through the same plotting functions the commands ``hydroservo ladder`` and
``hydroservo sensitivity --method sobol`` use).
"""

import os
import warnings
from pathlib import Path

import hydroservo as hs
from hydroservo.analysis.ladder import STEPS, build_ladder, ladder_defaults, ladder_table
from hydroservo.analysis.sensitivity import sobol
from hydroservo.plotting.ladder import plot_ladder_classes

IMG = Path(os.environ.get("HYDROSERVO_DOCS_IMG") or Path(__file__).resolve().parents[1] / "img")
warnings.simplefilter("ignore")  # a linear model driving a chamber below vacuum is flagged in the map, not here

arm = hs.load_model("robot-arm")
d = ladder_defaults(arm)
ladder = ladder_table(build_ladder(arm, t=d["t"], free=d["free"]), STEPS, parameter=d["parameter"], output=d["output"])
plot_ladder_classes(ladder, file=IMG / "robot_arm_ladder.png",
                    title="robot arm: displacement error of each model against the model as given (Table 5.3 classes)")

ranges = {
    "valve.c_v": ("1.0e-4 m^2/s/Pa^0.5", "2.0e-4 m^2/s/Pa^0.5"),
    "spool.tau": ("20 ms", "40 ms"),
    "supply.scale": (25 / 30, 35 / 30),
    "load.m": ("15 kg", "35 kg"),
    "cyl.C_Li": ("0.5e-13 m^3/s/Pa", "2e-13 m^3/s/Pa"),
    "force.amplitude": ("-200 N", "200 N"),
}
study = sobol(arm, ranges, 1024, metrics=["final(x_mm)", "rise_time(x_mm, 0.1 s)",
                                          "mean(cyl.pA, 0.4 s, 0.6 s)", "peak(cyl.pA)"])
study.plot(file=IMG / "robot_arm_sobol.png", title=f"robot arm: Sobol indices of six parameters ({study.runs.stats['runs']} runs)")
print(study.runs.stats)
print(study.indices.round(3).to_string())
