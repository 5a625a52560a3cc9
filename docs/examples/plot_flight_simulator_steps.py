"""Flight-simulator actuator: step responses
=========================================

Step responses of the [FlightSimulatorND] flight-simulator actuator, +2 V (retraction) and -2 V (extension).

Run: ``python docs/examples/plot_flight_simulator_steps.py`` (writes docs/img/flight_simulator_steps.png).
"""

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import hydroservo as hs

system = hs.load_model("flight-simulator")
fig, axes = plt.subplots(4, 1, sharex=True, figsize=(8, 9))
for volts, style in ((2.0, "-"), (-2.0, "--")):
    r = system.simulate(t_end=3.0, params={"source.amplitude": volts})
    label = f"{volts:+g} V"
    axes[0].plot(r.t, r.get("xv", "in"), style, label=label)
    axes[1].plot(r.t, r.get("ydot", "in/s"), style, label=label)
    axes[2].plot(r.t, r.get("y", "in"), style, label=label)
    axes[3].plot(r.t, r.get("p2", "psi"), style, label=f"P2, {label}")
    axes[3].plot(r.t, r.get("p1", "psi"), style, label=f"P1, {label}", alpha=0.6)
axes[3].axhline(1500, color="k", lw=0.8, ls=":", label="supply")
for ax, lab in zip(axes, ["spool x_v [in]", "velocity ydot [in/s]", "displacement y [in]", "pressure [psi]"]):
    ax.set_ylabel(lab)
    ax.grid(True, alpha=0.3)
axes[0].legend(loc="upper right", fontsize="small")
axes[3].legend(loc="upper right", fontsize="x-small", ncol=3)
axes[-1].set_xlabel("t [s]")
fig.suptitle("FlightSimulatorND flight-simulator actuator: command steps of ±2 V (positive retracts)")
fig.tight_layout()
out = Path(os.environ.get("HYDROSERVO_DOCS_IMG") or Path(__file__).resolve().parents[1] / "img") / "flight_simulator_steps.png"
fig.savefig(out, dpi=100)
print(out)
