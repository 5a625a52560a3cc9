"""Position servo beside Hopsan
============================

hydroservo's ``position-servo`` beside Hopsan's result of its Position Servo example.

Run: ``python docs/examples/plot_position_servo.py`` (writes docs/img/position_servo_hopsan.png).
Top: piston position, hydroservo (Hopsan's laws), Hopsan converged and at its default step,
and hydroservo with its default cylinder floor (check valves); middle: their distance from
Hopsan's converged result; bottom: chamber A pressure as the valve sees it, zoomed on the first
cavitation after the step.
"""

import io
import os
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import hydroservo as hs
from hydroservo.data import reference_text

ref = np.genfromtxt(io.StringIO(reference_text("hopsan_position_servo.csv")), delimiter=",", skip_header=1)
warnings.simplefilter("ignore")  # the chamber peaks (53 MPa, as Hopsan's) are flagged as implausible
system = hs.load_model("position-servo")
r = system.simulate(n_points=30001, max_steps=10**6)
check = system.copy()
check.set("cyl.pressure_floor", "check-valve")
check.set("cyl.p_floor", "0 Pa_abs")
rc = check.simulate(n_points=30001, max_steps=10**6)

fig, (ax1, ax3, ax2) = plt.subplots(3, 1, figsize=(9, 10.5))
ax1.plot(ref[:, 0], ref[:, 1], color="0.6", lw=4, label="Hopsan, converged (Ts → 0)")
ax1.plot(ref[:, 0], ref[:, 4], color="tab:orange", lw=1, ls="--", label="Hopsan, Ts = 1e-4 s (its default)")
ax1.plot(r.t, r["load.x"], color="tab:blue", lw=1, label="hydroservo, Hopsan's laws (cavity)")
ax1.plot(rc.t, rc["load.x"], color="tab:red", lw=0.8, alpha=0.8, label="hydroservo, default floor (check valves)")
ax1.plot(r.t, r["reference.y"], color="k", lw=0.8, ls=":", label="position command")
ax1.set_ylabel("piston position x [m]")
ax1.set_xlabel("time [s]")
ax1.legend(loc="lower right", fontsize="small")
ax1.grid(True, alpha=0.3)
ax1.set_title("Position Servo: hydroservo against Hopsan")

on_ref = np.searchsorted(r.t, ref[:, 0])
floor = 1e-4  # mm: below this the comparison is at the reference's resolution
for dev, style, label in (
    (np.abs(ref[:, 4] - ref[:, 1]), dict(color="tab:orange", ls="--", lw=1), "Hopsan, Ts = 1e-4 s"),
    (np.abs(rc["load.x"][on_ref] - ref[:, 1]), dict(color="tab:red", lw=0.8), "hydroservo, default floor (check valves)"),
    (np.abs(r["load.x"][on_ref] - ref[:, 1]), dict(color="tab:blue", lw=1), "hydroservo, Hopsan's laws (cavity)"),
):
    ax3.semilogy(ref[:, 0], np.maximum(dev * 1e3, floor), label=label, **style)
rng = np.ptp(ref[:, 1])
ax3.axhline(0.005 * rng * 1e3, color="k", lw=0.8, ls=":", label="0.5 % of range (acceptance)")
ax3.axhline(0.0005 * rng * 1e3, color="0.5", lw=0.8, ls=":", label="0.05 % of range (reference's uncertainty)")
ax3.set_ylim(floor, 3e4)
ax3.set_ylabel("|x - x_Hopsan converged| [mm]")
ax3.set_xlabel("time [s]")
ax3.legend(loc="upper center", fontsize="x-small", ncol=3)
ax3.grid(True, which="both", alpha=0.3)

zoom = (ref[:, 0] >= 1.0) & (ref[:, 0] <= 1.3)
ax2.plot(ref[zoom, 0], (ref[zoom, 3] - 101325) / 1e6, color="0.6", lw=4, label="Hopsan, converged")
ax2.plot(ref[zoom, 0], (ref[zoom, 6] - 101325) / 1e6, color="tab:orange", lw=1, ls="--", label="Hopsan, Ts = 1e-4 s")
m = (r.t >= 1.0) & (r.t <= 1.3)
ax2.plot(r.t[m], r["cyl.pA"][m] / 1e6, color="tab:blue", lw=1, label="hydroservo, cavity law")
ax2.set_ylabel("chamber A pressure, gauge [MPa]")
ax2.set_xlabel("time [s]")
ax2.legend(loc="upper right", fontsize="small")
ax2.grid(True, alpha=0.3)
fig.tight_layout()
out = Path(os.environ.get("HYDROSERVO_DOCS_IMG") or Path(__file__).resolve().parents[1] / "img") / "position_servo_hopsan.png"
fig.savefig(out, dpi=110)
print(f"wrote {out}")
