"""``hydroservo valve ...``: the seed-000 valve tools on the command line (thin shell over the API); seed 002's are in :mod:`hydroservo.cli_spool`."""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

import numpy as np

from hydroservo.errors import ParameterError

__all__ = ["add_valve_parser"]

_CHAR_UNITS = {"Q_n": "L/min", "Q_L1": "L/min", "K_q0": "L/min", "K_p0": "", "q_lk0": "L/min"}
_TYPES = {
    "SpoolRateLimited": "rate-limited",
    "ServoSolenoidValve": "rate-limited",
    "SpoolSecondOrder": "second-order",
    "SpoolFirstOrder": "first-order",
}
_COMPONENT = {"rate-limited": "SpoolRateLimited", "second-order": "SpoolSecondOrder", "first-order": "SpoolFirstOrder"}


def _numbers(text: str, what: str) -> list[float]:
    try:
        vals = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise ParameterError(f"{what} {text!r}: expected comma-separated numbers, e.g. 5,25,50") from None
    if not vals:
        raise ParameterError(f"{what} {text!r}: expected at least one number")
    return vals


def _frequencies(text: str) -> np.ndarray:
    if ":" in text:
        parts = text.split(":")
        try:
            lo, hi, step = (float(p) for p in parts)
        except ValueError:
            raise ParameterError(f"--frequencies {text!r}: expected START:STOP:STEP in Hz, e.g. 10:300:10") from None
        if not (0 < lo <= hi and step > 0):
            raise ParameterError(f"--frequencies {text!r}: expected 0 < START <= STOP and STEP > 0 [Hz]")
        return np.arange(lo, hi + step / 2, step)
    vals = np.array(_numbers(text, "--frequencies"))
    if np.any(vals <= 0):
        raise ParameterError(f"--frequencies {text!r}: expected positive frequencies [Hz]")
    return vals


def _outdir(arg: str | None, default: str) -> Path:
    out = Path(arg or default)
    out.mkdir(parents=True, exist_ok=True)
    return out


# -- valve fit -------------------------------------------------------------------
def cmd_fit(args: argparse.Namespace) -> int:
    from hydroservo import plotting
    from hydroservo.identification.datasheet import PAPER_UNITS, PARAMETER_UNITS, fit_curves, fit_datasheet
    from hydroservo.identification.files import component_toml, paper_unit_comment, read_datasheet, read_static_curves
    from hydroservo.pseudo_sections import sections_from_measurements
    from hydroservo.units import from_si

    ds = read_datasheet(args.datasheet)
    curves = read_static_curves(args.curves) if args.curves else None
    if curves is not None and args.match:
        raise ParameterError("--match applies to a datasheet fit; with --curves every curve is fitted by least squares")
    fit = (
        fit_curves(curves, ds, args.structure) if curves is not None else fit_datasheet(ds, args.structure, args.match)
    )
    name = ds.name or Path(str(args.datasheet)).stem
    slug = "".join(ch if ch.isalnum() or ch in "-_" else "-" for ch in Path(str(args.datasheet)).stem)
    out = _outdir(args.out, f"hydroservo-valve-{slug}")
    what = "least squares on the measured curves" if curves is not None else f"matching {' and '.join(fit.match)}"
    title = f"{name}: {fit.structure} structure, {what}"
    measured_sections = None
    if curves is not None:
        A_p, A_n = sections_from_measurements(curves["P_L"], curves["q_lk"], ds.P_s)
        measured_sections = {"x_s": curves["x_s"], "A_p": A_p, "A_n": A_n}
    files = {
        "pseudo_sections": plotting.plot_pseudo_sections(
            fit, measured=measured_sections, title=title, file=out / "pseudo_sections.png"
        ),
        "null_characteristics": plotting.plot_null_characteristics(
            fit, ds.P_s, measured=curves, file=out / "null_characteristics.png"
        ),
        "load_flow": plotting.plot_load_flow(fit, ds.P_n, measured=curves, title=title, file=out / "load_flow.png"),
        "pressure_flow": plotting.plot_pressure_flow(fit, ds.P_s, file=out / "pressure_flow.png"),
    }
    paths = {k: str(out / f"{k}.png") for k in files}
    chars = fit.characteristics()
    shown = {k: from_si(v, "m^3/s", u) if u else v for k, v in chars.items() for u in [_CHAR_UNITS[k]]}
    given = {
        k: from_si(getattr(ds, k), "m^3/s", _CHAR_UNITS[k]) if _CHAR_UNITS[k] else getattr(ds, k)
        for k in ("Q_n", "K_q0", "K_p0", "q_lk0")
        if getattr(ds, k) is not None
    }
    comments = {k: paper_unit_comment(v, PARAMETER_UNITS[k], PAPER_UNITS[k]) for k, v in fit.params.items()}
    toml = component_toml(
        "PseudoSectionValve",
        fit.params,
        PARAMETER_UNITS,
        options={"structure": fit.structure},
        comments=comments,
        header=(
            f"{name}: pseudo-section valve fitted by hydroservo (seed 000, {fit.structure} structure),\n"
            f"nominal flow exact, {what}.\n"
            'Use it in a model file: [components.valve] file = "valve.toml"  (type may be\n'
            "overridden with ServoSolenoidValve to add the spool dynamics)."
        ),
        extra={
            "datasheet": ds.as_mapping(),
            "fit": {"match": list(fit.match)},
            "characteristics": {k: f"{v:.6g} {_CHAR_UNITS[k]}".strip() for k, v in shown.items()},
        },
    )
    (out / "valve.toml").write_text(toml)
    paths["parameters"] = str(out / "valve.toml")
    paper = fit.in_paper_units()
    if args.json:
        print(
            json.dumps(
                {
                    "valve": name,
                    "structure": fit.structure,
                    "match": list(fit.match),
                    "parameters": paper,
                    "units": {k: PAPER_UNITS[k] or "-" for k in paper},
                    "characteristics": {k: shown[k] for k in ("Q_n", "K_q0", "K_p0", "q_lk0")},
                    "characteristic_units": {k: _CHAR_UNITS[k] or "-" for k in ("Q_n", "K_q0", "K_p0", "q_lk0")},
                    "datasheet": given,
                    "deviation": fit.deviation,
                    "files": paths,
                },
                indent=2,
            )
        )
        return 0
    print(f"{name}: {fit.structure}-structure pseudo-sections (seed 000), Q_n exact, {what}")
    for k, v in paper.items():
        print(f"  {k:>6} = {v:.6g} {PAPER_UNITS[k]}")
    print("characteristic     model     datasheet  deviation")
    for k in ("Q_n", "K_q0", "K_p0", "q_lk0"):
        u = _CHAR_UNITS[k] or "-"
        g = given.get(k)
        dev = f"{100 * fit.deviation[k]:+.2f} %" if k in fit.deviation else ""
        note = "  (not matched: eq. 23)" if curves is None and abs(fit.deviation.get(k, 0.0)) > 1e-6 else ""
        print(f"  {k:<6} {shown[k]:>10.5g} {'' if g is None else f'{g:>10.5g}':>10} {u:<6} {dev}{note}")
    for k, v in fit.deviation.items():
        if k.startswith("rms_"):
            print(f"  misfit of {k[4:]}: {100 * v:.2f} % rms of its largest value")
    print(f"wrote {', '.join(paths.values())}")
    return 0


# -- valve bode ------------------------------------------------------------------
def _dynamics(source: str) -> tuple[str, dict[str, Any]]:
    from hydroservo.identification.files import VALVES, read_component_file

    if source in VALVES:
        return "rate-limited", dict(VALVES[source]["dynamics"])
    comp = read_component_file(source)
    kind = comp.pop("type")
    if kind not in _TYPES:
        raise ParameterError(
            f"{source}: component type {kind!r} has no spool dynamics; expected one of {', '.join(_TYPES)}"
        )
    model = _TYPES[kind]
    from hydroservo.identification.spool import SPOOL_MODELS

    keep = set(SPOOL_MODELS[model]) | {"delay"}
    return model, {k: v for k, v in comp.items() if k in keep}


def _crossing(freqs: np.ndarray, y: np.ndarray, level: float) -> float | None:
    below = np.flatnonzero(y < level)
    if not below.size or below[0] == 0:
        return None
    i = below[0]
    return float(np.interp(level, [y[i], y[i - 1]], [freqs[i], freqs[i - 1]]))


def _bandwidths(resp: Any) -> dict[str, dict[str, float | None]]:
    return {
        f"{100 * a:g} %": {
            "f_-3dB_Hz": _crossing(resp.frequencies, resp.gain_db[i], -3.0),
            "f_-90deg_Hz": _crossing(resp.frequencies, resp.phase_deg[i], -90.0),
        }
        for i, a in enumerate(resp.amplitudes)
    }


def cmd_bode(args: argparse.Namespace) -> int:
    from hydroservo.identification.spool import spool_response

    model, params = _dynamics(args.params)
    amps = np.array(_numbers(args.amplitudes, "--amplitudes")) / 100.0
    freqs = _frequencies(args.frequencies)
    resp = spool_response(params, amps, freqs, model, label=model)
    stem = Path(args.params).stem
    out = _outdir(args.out, f"hydroservo-bode-{stem}")
    csv_path = resp.to_csv(out / "bode.csv")
    resp.plot(title=f"{stem}: spool position / command ({model})", file=out / "bode.png")
    if args.json:
        print(
            json.dumps(
                {
                    "model": model,
                    "parameters": params,
                    "amplitudes_percent": (100 * amps).tolist(),
                    "frequencies_Hz": freqs.tolist(),
                    "gain_dB": resp.gain_db.tolist(),
                    "phase_deg": resp.phase_deg.tolist(),
                    "bandwidth": _bandwidths(resp),
                    "files": {"csv": str(csv_path), "plot": str(out / "bode.png")},
                },
                indent=2,
            )
        )
        return 0
    print(f"{stem}: {model} spool model, {', '.join(f'{k}={v}' for k, v in params.items())}")
    for amp, bw in _bandwidths(resp).items():
        f3, f90 = bw["f_-3dB_Hz"], bw["f_-90deg_Hz"]
        print(
            f"  ±{amp:>6}: -3 dB at {'>' + str(freqs[-1]) if f3 is None else f'{f3:.1f}'} Hz, "
            f"-90 deg at {'>' + str(freqs[-1]) if f90 is None else f'{f90:.1f}'} Hz"
        )
    print(f"wrote {csv_path} and {out / 'bode.png'}")
    return 0


# -- valve fit-dynamics --------------------------------------------------------
def _start(text: str | None) -> dict[str, str]:
    if not text:
        return {}
    out = {}
    for item in text.split(","):
        if "=" not in item:
            raise ParameterError(f"--start {item!r}: expected NAME=VALUE, e.g. 'omega_n=700 rad/s,zeta=0.7'")
        k, v = item.split("=", 1)
        out[k.strip()] = v.strip()
    return out


def cmd_fit_dynamics(args: argparse.Namespace) -> int:
    from hydroservo.analysis.frequency import FrequencyResponse
    from hydroservo.identification.files import component_toml
    from hydroservo.identification.spool import SPOOL_MODELS, fit_spool_dynamics

    data = FrequencyResponse.from_csv(args.bode)
    models = list(SPOOL_MODELS) if args.model == "all" else [args.model]
    start = _start(args.start)
    out = _outdir(args.out, f"hydroservo-fit-{Path(args.bode).stem}")
    fits = {m: fit_spool_dynamics(data, m, start if len(models) == 1 else None) for m in models}
    data.label = "data"
    first = fits[models[0]]
    first.data.plot(
        [f.response for f in fits.values()],
        title=f"{Path(args.bode).stem}: Bode data and fitted models",
        file=out / "fit.png",
        f_max=200.0,
    )
    files = {"plot": str(out / "fit.png")}
    for m, fit in fits.items():
        units = {**SPOOL_MODELS[m], "delay": "s"}
        # Only the rate-limited component has a delay parameter; the others record the fitted delay beside it.
        has_delay = m == "rate-limited"
        header = (
            f"Spool dynamics fitted by hydroservo to {Path(args.bode).name} (seed 000 eq. 43, then the delay)\n"
            f"max gain error up to 200 Hz: {fit.max_gain_error(200.0):.3g} dB"
        )
        if not has_delay:
            header += f"\nthe fitted delay, {fit.params['delay']:.4g} s, is not a parameter of {_COMPONENT[m]}"
        path = out / f"spool_{m}.toml"
        path.write_text(
            component_toml(
                _COMPONENT[m],
                {k: v for k, v in fit.params.items() if has_delay or k != "delay"},
                units,
                header=header,
                extra=None if has_delay else {"fit": {"delay_s": fit.params["delay"]}},
            )
        )
        files[f"parameters_{m}"] = str(path)
    if args.json:
        print(json.dumps({"fits": {m: f.summary() for m, f in fits.items()}, "files": files}, indent=2, default=float))
        return 0
    for m, fit in fits.items():
        s = fit.summary()
        params = ", ".join(f"{k} = {v:.5g} {s['units'][k]}".replace(" -", "") for k, v in fit.params.items())
        print(f"{m}: {params}")
        print(
            f"  gain error up to 200 Hz: max {s['max_gain_error_dB_to_200Hz']:.3f} dB; rms per amplitude: "
            + ", ".join(f"{a} {r:.3f} dB" for a, r in s["gain_rms_dB"].items())
        )
    print(f"wrote {', '.join(files.values())}")
    return 0


def add_valve_parser(sub: Any) -> None:
    from hydroservo.cli_spool import add_spool_commands

    valve = sub.add_parser(
        "valve",
        help="valve tools: datasheet fit, Bode, dynamics fit (seed 000); characteristics, identify (seed 002)",
    )
    vsub = valve.add_subparsers(dest="valve_command", required=True)

    p = vsub.add_parser("fit", help="pseudo-section parameters from datasheet values, with plots and a parameter file")
    p.add_argument(
        "datasheet", metavar="DATASHEET", help="TOML file with a [datasheet] table, or a built-in valve (KBSDG4V-3)"
    )
    p.add_argument("--structure", choices=["variable", "fixed"], default="variable")
    p.add_argument(
        "--match",
        default=None,
        metavar="A,B",
        help="the two null characteristics to reproduce: pressure-gain, flow-gain, leakage "
        "(default: pressure-gain,leakage when given)",
    )
    p.add_argument(
        "--curves",
        default=None,
        metavar="CSV",
        help="measured x_s, P_L, q_lk (and Q_L): fit them by least squares instead of the null characteristics",
    )
    p.add_argument("--out", default=None, metavar="DIR")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_fit)

    p = vsub.add_parser("bode", help="amplitude-dependent Bode plot of spool dynamics")
    p.add_argument("params", metavar="PARAMS", help="component file (SpoolRateLimited, ...) or built-in valve name")
    p.add_argument(
        "--amplitudes", default="5,25,50", metavar="A,B,...", help="amplitudes in %% of stroke (default 5,25,50)"
    )
    p.add_argument(
        "--frequencies", default="10:300:10", metavar="F", help="START:STOP:STEP or list [Hz] (default 10:300:10)"
    )
    p.add_argument("--out", default=None, metavar="DIR")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_bode)

    p = vsub.add_parser("fit-dynamics", help="fit spool dynamics to Bode data (CSV: frequency, amplitude, gain, phase)")
    p.add_argument("bode", metavar="BODE.csv")
    p.add_argument("--model", choices=["rate-limited", "second-order", "first-order", "all"], default="rate-limited")
    p.add_argument("--start", default=None, metavar="NAME=VALUE,...", help="starting values, e.g. 'omega_n=700 rad/s'")
    p.add_argument("--out", default=None, metavar="DIR")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_fit_dynamics)

    add_spool_commands(vsub)
