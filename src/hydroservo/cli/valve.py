"""``hydroservo valve``: the valve tools. ``fit``, ``bode`` and ``fit-dynamics`` here (the servo-solenoid
valve of FerreiraND); ``characteristics`` and ``identify`` (the staged-slot valve of MareAttarND) in
:mod:`hydroservo.cli.valve_bench`."""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

from hydroservo.cli import valve_bench
from hydroservo.cli.common import add_output_options, frequencies, numbers, output_folder
from hydroservo.errors import HydroservoError, ParameterError

if TYPE_CHECKING:
    import numpy as np

    from hydroservo.io.files import OutputFolder

__all__ = ["add_parsers"]

_CHAR_UNITS = {"Q_n": "L/min", "Q_L1": "L/min", "K_q0": "L/min", "K_p0": "", "q_lk0": "L/min"}
_NULL = ("Q_n", "K_q0", "K_p0", "q_lk0")


def _shown(values: dict[str, float]) -> dict[str, float]:
    """Characteristics in their display units (L/min)."""
    from hydroservo.units import from_si

    return {k: from_si(v, "m^3/s", _CHAR_UNITS[k]) if _CHAR_UNITS[k] else v for k, v in values.items()}


# -- valve fit -------------------------------------------------------------------
_FIT_FILES = ("pseudo_sections", "null_characteristics", "load_flow", "pressure_flow")


def _fit_plots(fit: Any, curves: Any, out: OutputFolder, title: str) -> dict[str, str]:
    from hydroservo.laws.pseudo_section import sections_from_measurements
    from hydroservo.plotting import pseudo_section as plots

    ds, valve = fit.datasheet, fit.valve
    measured_sections = None
    if curves is not None:
        A_p, A_n = sections_from_measurements(curves["P_L"], curves["q_lk"], ds.P_s)
        measured_sections = {"x_s": curves["x_s"], "A_p": A_p, "A_n": A_n}
    plots.plot_pseudo_sections(valve, measured=measured_sections, title=title, file=out.file("pseudo_sections.png"))
    plots.plot_null_characteristics(valve, ds.P_s, measured=curves, file=out.file("null_characteristics.png"))
    plots.plot_load_flow(valve, ds.P_n, measured=curves, title=title, file=out.file("load_flow.png"))
    plots.plot_pressure_flow(valve, ds.P_s, file=out.file("pressure_flow.png"))
    return {k: out.final(f"{k}.png") for k in _FIT_FILES}


def _fit_parameter_file(fit: Any, name: str, what: str, shown: dict[str, float]) -> str:
    from hydroservo.io.component_file import component_toml
    from hydroservo.laws.pseudo_section import PARAMETER_UNITS, PRINTED_UNITS
    from hydroservo.units import from_si

    comments = {
        k: f"= {from_si(v, PARAMETER_UNITS[k], PRINTED_UNITS[k]):.6g} {PRINTED_UNITS[k]}"
        for k, v in fit.params.items()
        if PRINTED_UNITS[k]
    }
    return component_toml(
        "PseudoSectionValve",
        fit.params,
        PARAMETER_UNITS,
        options={"structure": fit.structure},
        comments=comments,
        header=(
            f"{name}: pseudo-section valve fitted by hydroservo (FerreiraND, {fit.structure} structure),\n"
            f"nominal flow exact, {what}.\n"
            'Use it in a model file: [components.valve] file = "valve.toml"  (type may be\n'
            "overridden with ServoSolenoidValve to add the spool dynamics)."
        ),
        extra={
            "datasheet": fit.datasheet.as_mapping(),
            "fit": {"match": list(fit.match)},
            "characteristics": {k: f"{v:.6g} {_CHAR_UNITS[k]}".strip() for k, v in shown.items()},
        },
    )


def _print_fit(fit: Any, name: str, what: str, shown: dict[str, float], given: dict[str, float], curves: Any) -> None:
    from hydroservo.laws.pseudo_section import PRINTED_UNITS

    print(f"{name}: {fit.structure}-structure pseudo-sections (FerreiraND), Q_n exact, {what}")
    for k, v in fit.in_paper_units().items():
        print(f"  {k:>6} = {v:.6g} {PRINTED_UNITS[k]}")
    print("characteristic     model     datasheet  deviation")
    for k in _NULL:
        u = _CHAR_UNITS[k] or "-"
        g = given.get(k)
        dev = f"{100 * fit.deviation[k]:+.2f} %" if k in fit.deviation else ""
        note = "  (not matched: eq. 23)" if curves is None and abs(fit.deviation.get(k, 0.0)) > 1e-6 else ""
        print(f"  {k:<6} {shown[k]:>10.5g} {'' if g is None else f'{g:>10.5g}':>10} {u:<6} {dev}{note}")
    for k, v in fit.deviation.items():
        if k.startswith("rms_"):
            print(f"  misfit of {k[4:]}: {100 * v:.2f} % rms of its largest value")


def cmd_fit(args: argparse.Namespace) -> int:
    from hydroservo.identification import fit_curves, fit_datasheet
    from hydroservo.io.curves import read_static_curves
    from hydroservo.io.datasheet import read_datasheet
    from hydroservo.laws.pseudo_section import PRINTED_UNITS

    ds = read_datasheet(args.datasheet)
    curves = read_static_curves(args.curves) if args.curves else None
    if curves is not None and args.match:
        raise ParameterError("--match applies to a datasheet fit; with --curves every curve is fitted by least squares")
    name = ds.name or Path(str(args.datasheet)).stem
    slug = "".join(ch if ch.isalnum() or ch in "-_" else "-" for ch in Path(str(args.datasheet)).stem)
    out = output_folder(args, f"hydroservo-valve-{slug}")
    out.expect([f"{k}.png" for k in _FIT_FILES] + ["valve.toml"])
    fit = fit_curves(curves, ds, args.structure) if curves is not None else fit_datasheet(ds, args.structure, args.match)
    what = "least squares on the measured curves" if curves is not None else f"matching {' and '.join(fit.match)}"
    shown = _shown(fit.characteristics())
    given = _shown({k: getattr(ds, k) for k in _NULL if getattr(ds, k) is not None})
    with out:
        paths = _fit_plots(fit, curves, out, f"{name}: {fit.structure} structure, {what}")
        out.file("valve.toml").write_text(_fit_parameter_file(fit, name, what, shown))
    paths["parameters"] = out.final("valve.toml")
    if not args.json:
        _print_fit(fit, name, what, shown, given, curves)
        print(f"wrote {', '.join(paths.values())}")
        return 0
    paper = fit.in_paper_units()
    report = {
        "valve": name,
        "structure": fit.structure,
        "match": list(fit.match),
        "parameters": paper,
        "units": {k: PRINTED_UNITS[k] or "-" for k in paper},
        "characteristics": {k: shown[k] for k in _NULL},
        "characteristic_units": {k: _CHAR_UNITS[k] or "-" for k in _NULL},
        "datasheet": given,
        "deviation": fit.deviation,
        "files": paths,
    }
    print(json.dumps(report, indent=2))
    return 0


# -- valve bode ------------------------------------------------------------------
def _dynamics(source: str) -> tuple[str, dict[str, Any]]:
    """The spool model and its parameters: a built-in valve's published dynamics, or a component file's."""
    from hydroservo.components import REGISTRY
    from hydroservo.data import parameter_set
    from hydroservo.identification.spool_dynamics import SPOOL_COMPONENTS, SPOOL_MODELS, fidelity_of
    from hydroservo.io.component_file import read_component_file
    from hydroservo.io.datasheet import BUILTIN_VALVES
    from hydroservo.units import is_bare_number

    if source in BUILTIN_VALVES:
        table = parameter_set(BUILTIN_VALVES[source]).table("dynamics")
        return "rate-limited", {k: float(v) if is_bare_number(v) else v for k, v in table.items()}
    comp = read_component_file(source)
    kind = comp.pop("type")
    cls = REGISTRY.resolve(kind)
    model = None if cls is None else fidelity_of(cls)
    if model is None:
        kinds = ", ".join(c.__name__ for c in SPOOL_COMPONENTS.values())
        raise ParameterError(f"{source}: component type {kind!r} has no spool dynamics; expected one of {kinds}")
    keep = set(SPOOL_MODELS[model]) | {"delay"} | set(SPOOL_COMPONENTS[model].RENAMED)
    return model, {k: v for k, v in comp.items() if k in keep}


def _crossing(freqs: np.ndarray, y: np.ndarray, level: float) -> float | None:
    import numpy as np

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
    import numpy as np

    from hydroservo.identification.spool_dynamics import spool_response
    from hydroservo.io.bode import write_bode

    model, params = _dynamics(args.params)
    amps = np.array(
        numbers(args.amplitudes, "--amplitudes", above=0.0, at_most=100.0, expected="0 < amplitude <= 100 % of stroke")
    ) / 100.0
    freqs = frequencies(args.frequencies)
    stem = Path(args.params).stem
    out = output_folder(args, f"hydroservo-bode-{stem}")
    out.expect(["bode.csv", "bode.png"])
    resp = spool_response(params, amps, freqs, model, label=model)
    with out:
        write_bode(resp, out.file("bode.csv"))
        resp.plot(title=f"{stem}: spool position / command ({model})", file=out.file("bode.png"))
    files = {"csv": out.final("bode.csv"), "plot": out.final("bode.png")}
    if args.json:
        report = {
            "model": model,
            "parameters": params,
            "amplitudes_percent": (100 * amps).tolist(),
            "frequencies_Hz": freqs.tolist(),
            "gain_dB": resp.gain_db.tolist(),
            "phase_deg": resp.phase_deg.tolist(),
            "bandwidth": _bandwidths(resp),
            "files": files,
        }
        print(json.dumps(report, indent=2))
        return 0
    print(f"{stem}: {model} spool model, {', '.join(f'{k}={v}' for k, v in params.items())}")
    for amp, bw in _bandwidths(resp).items():
        f3, f90 = bw["f_-3dB_Hz"], bw["f_-90deg_Hz"]
        print(
            f"  ±{amp:>6}: -3 dB at {'>' + str(freqs[-1]) if f3 is None else f'{f3:.1f}'} Hz, "
            f"-90 deg at {'>' + str(freqs[-1]) if f90 is None else f'{f90:.1f}'} Hz"
        )
    print(f"wrote {files['csv']} and {files['plot']}")
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


def _spool_file(fit: Any, bode: str) -> str:
    """The parameter file of a fitted spool model; the delay is recorded beside a component that has none."""
    from hydroservo.identification.spool_dynamics import SPOOL_COMPONENTS, SPOOL_MODELS
    from hydroservo.io.component_file import component_toml

    cls = SPOOL_COMPONENTS[fit.model]
    has_delay = "delay" in cls.PARAMETERS
    header = (
        f"Spool dynamics fitted by hydroservo to {Path(bode).name} (FerreiraND eq. 43, then the delay)\n"
        f"max gain error up to 200 Hz: {fit.max_gain_error(200.0):.3g} dB"
    )
    if not has_delay:
        header += f"\nthe fitted delay, {fit.params['delay']:.4g} s, is not a parameter of {cls.__name__}"
    return component_toml(
        cls.__name__,
        {k: v for k, v in fit.params.items() if has_delay or k != "delay"},
        {**SPOOL_MODELS[fit.model], "delay": "s"},
        header=header,
        extra=None if has_delay else {"fit": {"delay_s": fit.params["delay"]}},
    )


def cmd_fit_dynamics(args: argparse.Namespace) -> int:
    from hydroservo.identification.spool_dynamics import SPOOL_MODELS, check_start, fit_spool_dynamics
    from hydroservo.io.bode import read_bode

    data = read_bode(args.bode)
    models = list(SPOOL_MODELS) if args.model == "all" else [args.model]
    start = _start(args.start)
    if start and len(models) > 1:
        raise ParameterError(f"--start {args.start!r}: starting values apply to one model; expected --model with one")
    if start:
        try:
            check_start(models[0], start)
        except HydroservoError as exc:
            raise ParameterError(f"--start {args.start!r}: {exc}") from None
    out = output_folder(args, f"hydroservo-fit-{Path(args.bode).stem}")
    out.expect(["fit.png"] + [f"spool_{m}.toml" for m in models])
    fits = {m: fit_spool_dynamics(data, m, start if len(models) == 1 else None) for m in models}
    data.label = "data"
    first = fits[models[0]]
    title = f"{Path(args.bode).stem}: Bode data and fitted models"
    with out:
        first.data.plot([f.response for f in fits.values()], title=title, file=out.file("fit.png"), f_max=200.0)
        for m, fit in fits.items():
            out.file(f"spool_{m}.toml").write_text(_spool_file(fit, args.bode))
    files = {"plot": out.final("fit.png"), **{f"parameters_{m}": out.final(f"spool_{m}.toml") for m in fits}}
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


def add_parsers(sub: Any) -> None:
    """Add ``valve`` and its sub-commands."""
    valve = sub.add_parser(
        "valve",
        help="valve tools: datasheet fit, Bode, dynamics fit (FerreiraND); characteristics, identify (MareAttarND)",
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
    add_output_options(p, "a folder named after the input")
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
    add_output_options(p, "a folder named after the input")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_bode)

    p = vsub.add_parser("fit-dynamics", help="fit spool dynamics to Bode data (CSV: frequency, amplitude, gain, phase)")
    p.add_argument("bode", metavar="BODE.csv")
    p.add_argument("--model", choices=["rate-limited", "second-order", "first-order", "all"], default="rate-limited")
    p.add_argument("--start", default=None, metavar="NAME=VALUE,...", help="starting values, e.g. 'omega_n=700 rad/s'")
    add_output_options(p, "a folder named after the input")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_fit_dynamics)

    valve_bench.add_parsers(vsub)
