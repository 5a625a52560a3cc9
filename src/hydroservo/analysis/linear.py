r"""Linear analysis of any system: state-space matrices at an operating point, modes, responses.

:func:`linearize` differentiates the system's one CasADi graph at an
operating point (an equilibrium found by trim, a steady motion with some
states free, the initial state, or any state the user gives) and returns a
:class:`LinearModel`

.. math:: \Delta\dot x = A\,\Delta x + B\,\Delta u, \qquad \Delta y = C\,\Delta x + D\,\Delta u

with named states, inputs and outputs, all in SI. The Jacobians are exact
(algorithmic differentiation of the same graph that is simulated, algebraic
unknowns included through the implicit-function theorem), never finite
differences. An *input* is either a component input (``"valve.u"``: a
perturbation added to whatever feeds it, so a connected input is cut open
for the linearisation and nothing else changes) or a parameter
(``"supply.p"``). At an equilibrium or a steady motion this is the general
form of the linearised model of [Efe2014] section 4.3 (eqs. 4.5-4.14):
volumes, bulk moduli and valve coefficients frozen at the point (where the
flows into a chamber do not balance, the derivative of its volume and bulk
modulus adds terms the thesis's form does not have).

:func:`valve_coefficients` gives the valve sensitivity coefficients of
[Efe2014] eqs. 4.8-4.12 (flow gain, flow-pressure coefficient, pressure
sensitivity) of every four-way valve in a system at the point, from the same
Jacobians, beside the closed forms of
:func:`hydroservo.laws.four_way.valve_coefficients`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import casadi as ca
import numpy as np

from hydroservo.errors import ModelError, ParameterError, TrimError, did_you_mean, shorten
from hydroservo.system.assembly import assemble

if TYPE_CHECKING:
    from hydroservo.analysis.frequency import FrequencyResponse
    from hydroservo.system.system import System

__all__ = [
    "LinearModel", "Mode", "ValveCoefficients", "linearize", "operating_point", "valve_coefficients", "input_values",
    "simulated_response",
]

#: Component types whose outputs are signals set by time alone: their outputs are a system's natural inputs.
SIGNALS = ("Step", "Ramp", "Sine", "Square", "Table", "Pulse")


@dataclass
class Mode:
    """One mode of a linear model: a real pole, or a complex pair counted once.

    ``participation`` is the share of each state in the mode (participation
    factors :math:`|l_{ki} r_{ik}|` of the left and right eigenvectors,
    normalised to sum 1; independent of the states' units and scaling).
    """

    eigenvalue: complex  #: [1/s] (the one with positive imaginary part for a pair)
    frequency: float  #: natural frequency :math:`|\lambda|/2\pi` [Hz]
    damping: float  #: damping ratio :math:`-\mathrm{Re}\,\lambda/|\lambda|` [-] (NaN at the origin)
    time_constant: float  #: :math:`-1/\mathrm{Re}\,\lambda` [s] (inf on the imaginary axis, negative if unstable)
    participation: dict[str, float]

    @property
    def oscillatory(self) -> bool:
        return abs(self.eigenvalue.imag) > 1e-9 * max(1.0, abs(self.eigenvalue))

    @property
    def stable(self) -> bool:
        return self.eigenvalue.real < 0

    def main_states(self, share: float = 0.1) -> list[str]:
        """The states taking part with at least ``share``, largest first."""
        return [s for s, v in sorted(self.participation.items(), key=lambda kv: -kv[1]) if v >= share]

    def to_dict(self) -> dict[str, Any]:
        return {
            "eigenvalue": [self.eigenvalue.real, self.eigenvalue.imag],
            "frequency_Hz": self.frequency,
            "damping": None if np.isnan(self.damping) else self.damping,
            "time_constant_s": None if not np.isfinite(self.time_constant) else self.time_constant,
            "participation": {k: v for k, v in self.participation.items() if v >= 0.01},
        }


@dataclass
class LinearModel:
    """A linear state-space model about an operating point, every row and column named (SI).

    ``x0``, ``u0``, ``y0`` are the operating point's states, inputs and
    outputs; ``drift`` the state rates there (zero at an equilibrium; a free
    state's rate at a steady motion, such as the piston's speed).
    """

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    states: list[str]
    inputs: list[str]
    outputs: list[str]
    units: dict[str, str]
    x0: dict[str, float]
    u0: dict[str, float]
    y0: dict[str, float]
    drift: dict[str, float]
    nominal: np.ndarray
    name: str = ""
    t: float = 0.0
    info: dict[str, Any] = field(default_factory=dict)

    # -- modes ---------------------------------------------------------------
    def eigenvalues(self) -> np.ndarray:
        """Poles of the model [1/s]."""
        return np.linalg.eigvals(self._scaled()[0]) if self.A.size else np.zeros(0, complex)

    def _scaled(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """A, B, C in the states' nominal units: the same poles, well conditioned."""
        N = self.nominal
        return self.A * N[None, :] / N[:, None], self.B / N[:, None], self.C * N[None, :]

    def modes(self) -> list[Mode]:
        """The modes, slowest first: poles, natural frequencies, damping ratios and participating states."""
        if not self.A.size:
            return []
        As = self._scaled()[0]
        lam, R = np.linalg.eig(As)
        try:
            L = np.linalg.inv(R)
        except np.linalg.LinAlgError:
            L = np.linalg.pinv(R)
        modes: list[Mode] = []
        scale = float(np.abs(lam).max()) if lam.size else 1.0
        lam = np.where(np.abs(lam) < 1e-12 * scale, 0.0, lam)  # a free integrator's pole is 0, not round-off
        for k in range(lam.size):
            if lam[k].imag < -1e-9 * max(1.0, abs(lam[k])):
                continue  # the conjugate of a pair already counted
            share = np.abs(L[k, :] * R[:, k])
            total = share.sum()
            share = share / total if total > 0 else share
            mag = abs(lam[k])
            modes.append(
                Mode(
                    complex(lam[k]),
                    float(mag / (2 * np.pi)),
                    float(-lam[k].real / mag) if mag > 0 else float("nan"),
                    float(-1.0 / lam[k].real) if lam[k].real != 0 else float("inf"),
                    {s: float(v) for s, v in zip(self.states, share)},
                )
            )
        return sorted(modes, key=lambda m: (abs(m.eigenvalue), m.eigenvalue.imag))

    # -- responses -----------------------------------------------------------
    def _index(self, names: list[str], name: str | None, what: str) -> int:
        if name is None:
            if len(names) == 1:
                return 0
            raise ParameterError(f"{what}: the model has {len(names)} ({', '.join(names)}); name one")
        if name not in names:
            raise ParameterError(f"{what} {name!r}: not one of the model's ({', '.join(names)})")
        return names.index(name)

    def transfer(self, frequencies: Sequence[float] | np.ndarray, input: str | None = None, output: str | None = None) -> np.ndarray:
        """Complex frequency response :math:`C(j\\omega I - A)^{-1}B + D` from ``input`` to ``output`` (SI units)."""
        i = self._index(self.inputs, input, "input")
        o = self._index(self.outputs, output, "output")
        As, Bs, Cs = self._scaled()
        f = np.asarray(frequencies, dtype=float).ravel()
        H = np.empty(f.size, complex)
        eye = np.eye(As.shape[0])
        for k, fk in enumerate(f):
            if As.size:
                try:
                    H[k] = Cs[o] @ np.linalg.solve(2j * np.pi * fk * eye - As, Bs[:, i]) + self.D[o, i]
                except np.linalg.LinAlgError:
                    raise ParameterError(
                        f"frequency {fk:g} Hz: the model has a pole there (a free integrator at 0 Hz); its response is unbounded"
                    ) from None
            else:
                H[k] = self.D[o, i]
        return H

    def bode(
        self, frequencies: Sequence[float] | np.ndarray, input: str | None = None, output: str | None = None
    ) -> FrequencyResponse:
        """Gain (dB of the SI ratio) and phase of ``output`` over ``input``, as a :class:`FrequencyResponse`."""
        from hydroservo.analysis.frequency import FrequencyResponse

        f = np.asarray(frequencies, dtype=float).ravel()
        H = self.transfer(f, input, output)
        i = self._index(self.inputs, input, "input")
        o = self._index(self.outputs, output, "output")
        with np.errstate(divide="ignore"):
            gain = 20 * np.log10(np.abs(H))
        phase = np.degrees(np.unwrap(np.angle(H)))
        return FrequencyResponse(
            np.array([0.0]), f, gain[None, :], phase[None, :], label="linear",
            info={"input": self.inputs[i], "output": self.outputs[o], "linear": True},
        )

    def step(
        self, t_end: float, input: str | None = None, amplitude: float = 1.0, n_points: int = 401
    ) -> tuple[np.ndarray, dict[str, np.ndarray]]:
        """Response to a step of ``amplitude`` (SI) on ``input`` at t = 0 from the operating point.

        Exact for the linear model (zero-order hold on the output grid).
        Returns the times and every output as deviation plus its operating value.
        The deviation model leaves out the drift of a steady motion (a moving
        piston's position advances by its speed besides what is shown).
        """
        from scipy.linalg import expm

        i = self._index(self.inputs, input, "input")
        if int(n_points) < 2 or not float(t_end) > 0:
            raise ParameterError(f"step: t_end = {t_end!r}, n_points = {n_points!r}: expected a positive duration and at least 2 points")
        t = np.linspace(0.0, float(t_end), int(n_points))
        As, Bs, Cs = self._scaled()
        n = As.shape[0]
        dt = t[1] - t[0]
        M = np.zeros((n + 1, n + 1))
        M[:n, :n], M[:n, n] = As * dt, Bs[:, i] * dt
        E = expm(M)
        Phi, Gam = E[:n, :n], E[:n, n]
        z = np.zeros((n, t.size))
        for k in range(1, t.size):
            z[:, k] = Phi @ z[:, k - 1] + Gam * amplitude
        Y = Cs @ z + self.D[:, [i]] * amplitude
        return t, {name: self.y0[name] + Y[j] for j, name in enumerate(self.outputs)}

    # -- exports ---------------------------------------------------------------
    def to_scipy(self) -> Any:
        """A :class:`scipy.signal.StateSpace` (names are lost: SciPy has none)."""
        from scipy.signal import StateSpace

        return StateSpace(self.A, self.B, self.C, self.D)

    def to_control(self) -> Any:
        """A python-control ``StateSpace`` with the states, inputs and outputs named (``pip install control``).

        python-control reserves the dot for its own subsystem names, so
        ``cyl.pA`` is called ``cyl:pA`` there.
        """
        try:
            import control
        except ImportError:
            raise ModelError("LinearModel.to_control needs python-control: pip install control") from None

        def names(seq: list[str]) -> list[str]:
            return [n.replace(".", ":") for n in seq]

        return control.ss(
            self.A, self.B, self.C, self.D, states=names(self.states), inputs=names(self.inputs),
            outputs=names(self.outputs), name=(self.name or "linear").replace(".", "_"),
        )

    def to_dict(self) -> dict[str, Any]:
        """Matrices with their names, the point and the modes: what ``hydroservo linearize --json`` prints."""
        return {
            "model": self.name,
            "t": self.t,
            "states": self.states,
            "inputs": self.inputs,
            "outputs": self.outputs,
            "units": {k: self.units.get(k, "") for k in [*self.states, *self.inputs, *self.outputs]},
            "operating_point": {"states": self.x0, "inputs": self.u0, "outputs": self.y0, "drift": self.drift},
            "A": self.A.tolist(),
            "B": self.B.tolist(),
            "C": self.C.tolist(),
            "D": self.D.tolist(),
            "modes": [m.to_dict() for m in self.modes()],
            **({"info": self.info} if self.info else {}),
        }


def _default_inputs(system: System) -> list[str]:
    """The component inputs fed by signal blocks (the system's commands and disturbances)."""
    found = []
    for target, source in system.connections.items():
        src = system.components.get(source.split(".")[0])
        if src is not None and type(src).__name__ in SIGNALS:
            found.append(target)
    return found


def operating_time(t: float, what: str = "t", given: Any = None) -> float:
    """``t`` [s], the time of an operating point, if it is one: finite and not before the start (0 s); else a
    ParameterError naming ``what`` and the value given."""
    if not (math.isfinite(t) and t >= 0.0):
        shown = given if given is not None else t
        raise ParameterError(f"{what} {shorten(str(shown))!r}: expected the time of the operating point, 0 s or later")
    return float(t)


def operating_point(
    system: System,
    at: str | Mapping[str, Any] = "trim",
    *,
    params: Mapping[str, Any] | None = None,
    t: float = 0.0,
    free: Sequence[str] = (),
) -> dict[str, float]:
    """The states of an operating point (SI).

    ``at`` is

    * ``"trim"``: an equilibrium at time ``t`` (the signals' values then). With ``free`` states it is a
      *steady motion* (:meth:`hydroservo.system.model.Model.trim`): the free states are not solved for and
      their rates need not vanish (a piston's position while it moves at constant speed), the others are solved
      for a steady state. The free states keep the values of the system at time ``t``: the initial values at
      ``t = 0``, else those of a run from the initial state to ``t`` (so the steady motion passes where the
      system is then, not where it started), which is also the solver's guess for the other states;
    * ``"run"``: the state of a run from the initial state at time ``t``, every state as simulated
      (*linearisation along a run*: the states' rates, the ``drift``, need not vanish); ``free`` does not apply;
    * ``"initial"``: the initial state;
    * a mapping of state names to values (numbers in SI or quantities with units; the states not named keep
      their initial values).
    """
    from hydroservo.units import to_si

    t = operating_time(t)

    model = system.build()
    p = system.parameter_vector(params)
    x = np.asarray(model.x0(p), dtype=float).ravel()
    if isinstance(at, Mapping):
        for name, value in at.items():
            if name not in model.state_names:
                raise ParameterError(f"operating point: {name!r} is not a state of {system.name!r}"
                                     f"{did_you_mean(name, model.state_names)}; states: {', '.join(model.state_names)}")
            x[model.state_names.index(name)] = to_si(value, model.units[name], what=name)
        return dict(zip(model.state_names, x.tolist()))
    if at == "initial":
        return dict(zip(model.state_names, x.tolist()))
    if at not in ("trim", "run"):
        raise ParameterError(f"operating point {at!r}: expected 'trim', 'run', 'initial' or a mapping of states to values")
    if at == "run" and free:
        raise ParameterError(
            f"free = {', '.join(free)}: free states belong to a trim (a steady motion); at 'run' every state is the "
            "run's own at t"
        )
    unknown = [n for n in free if n not in model.state_names]
    if unknown:
        raise TrimError(
            f"free = {unknown[0]!r} is not a state of {system.name!r}{did_you_mean(unknown[0], model.state_names)}; "
            f"states: {', '.join(model.state_names)}"
        )
    if at == "run" or (free and t > 0):
        run = _state_at(system, model.state_names, t, params)
        if at == "run":
            return dict(zip(model.state_names, run.tolist()))
        return model.trim(p, t=t, x_guess=run, free=free)
    try:
        return model.trim(p, t=t, x_guess=x, free=free)
    except TrimError:
        if not t > 0:
            raise
    # far from the initial state (a drive moving fast): start from where a run is at time t
    return model.trim(p, t=t, x_guess=_state_at(system, model.state_names, t, params), free=free)


def _state_at(system: System, names: Sequence[str], t: float, params: Mapping[str, Any] | None) -> np.ndarray:
    """Every state of a run of ``system`` from its initial state at time ``t`` [s] (SI); at ``t = 0`` the initial
    state."""
    if not t > 0:
        model = system.build()
        return np.asarray(model.x0(system.parameter_vector(params)), dtype=float).ravel()
    run = system.simulate(t, params=params, n_points=2)
    return np.array([float(run[n][-1]) for n in names])


def linearize(
    system: System,
    at: str | Mapping[str, Any] = "trim",
    *,
    inputs: Sequence[str] | None = None,
    outputs: Sequence[str] | None = None,
    params: Mapping[str, Any] | None = None,
    t: float = 0.0,
    free: Sequence[str] = (),
) -> LinearModel:
    """The linear model of ``system`` at an operating point (see :func:`operating_point`).

    ``inputs`` are component inputs (``"valve.u"``) or parameters
    (``"supply.p"``); default: the inputs fed by signal blocks. ``outputs``
    are states, outputs or aliases; default: the states.
    """
    names = list(_default_inputs(system) if inputs is None else inputs)
    if not names:
        raise ParameterError(
            f"linearize {system.name!r}: no inputs given and none fed by a signal block; name component inputs "
            "(valve.u) or parameters (supply.p)"
        )
    ports, param_inputs = [], []
    for i, name in enumerate(names):
        cname, _, key = name.partition(".")
        comp = system.components.get(cname)
        if comp is not None and key in comp.INPUTS:
            ports.append(name)
        elif comp is not None and key in comp.OPTIONS:
            raise ParameterError(f"input {name!r}: an option (a structural choice), not a number to perturb")
        else:
            try:
                names[i] = system.parameter_key(name)  # a former name becomes the current one
            except (ParameterError, ModelError, KeyError):
                raise ParameterError(
                    f"input {name!r}: neither a component input nor a parameter of {system.name!r}"
                ) from None
            param_inputs.append(names[i])
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise ParameterError(f"inputs: {', '.join(twice)} given twice")
    x0 = operating_point(system, at, params=params, t=t, free=free)
    a = assemble(system, tuple(ports))
    tsym, x, p, f, y = a.t, a.x, a.p, a.f, a.y
    state_names, parameter_names, output_names, units = a.state_names, a.parameter_names, a.output_names, a.units
    nominal, param_units = a.nominal, a.parameter_units
    out_names = list(state_names if outputs is None else outputs)
    signals = {**dict(zip(state_names, ca.vertsplit(x))), **dict(zip(output_names, ca.vertsplit(y)))}
    for o in out_names:
        if o not in signals:
            raise ParameterError(f"output {o!r}: not a state, output or alias of {system.name!r}")
    n_real = len(parameter_names) - len(ports)
    delta = p[n_real:]
    ysel = ca.vertcat(*[signals[o] for o in out_names])
    u_syms = []
    for name_ in names:
        if name_ in ports:
            u_syms.append(delta[ports.index(name_)])
        else:
            u_syms.append(p[parameter_names.index(system.parameter_key(name_))])
    # Jacobians with respect to a mix of parameter and perturbation symbols: one vector of the symbols used
    cols = [ca.jacobian(f, s) for s in u_syms]
    dcols = [ca.jacobian(ysel, s) for s in u_syms]
    fun = ca.Function(
        "linear", [tsym, x, p],
        [ca.jacobian(f, x), ca.horzcat(*cols) if cols else ca.SX(f.numel(), 0), ca.jacobian(ysel, x),
         ca.horzcat(*dcols) if dcols else ca.SX(ysel.numel(), 0), f, ysel],
    )
    pv = np.concatenate([system.parameter_vector(params), np.zeros(len(ports))])
    xv = np.array([x0[s] for s in state_names])
    A, B, C, D, f0, y0 = (np.asarray(m, dtype=float).reshape(m.shape) for m in fun(t, xv, pv))
    u0 = {}
    inputs_of = ca.Function("u", [tsym, x, p], [ca.vertcat(*[_input_value(system, n, signals, p, parameter_names) for n in names])])
    for n_, v in zip(names, np.asarray(inputs_of(t, xv, pv), dtype=float).ravel()):
        u0[n_] = float(v)
    all_units = dict(units)
    for n_ in names:
        all_units[n_] = param_units[system.parameter_key(n_)] if n_ in param_inputs else _port_unit(system, n_)
    return LinearModel(
        A, B, C, D, list(state_names), names, out_names, all_units,
        {s: float(v) for s, v in zip(state_names, xv)}, u0,
        {o: float(v) for o, v in zip(out_names, y0.ravel())},
        {s: float(v) for s, v in zip(state_names, f0.ravel())},
        np.where(np.asarray(nominal) > 0, nominal, 1.0), a.name, float(t),
        {"at": at if isinstance(at, str) else "given", **({"free": list(free)} if free else {}),
         **({"states_from_run": True} if (at == "run" or (at == "trim" and free)) and t > 0 else {})},
    )


def input_values(
    system: System, x: Mapping[str, float], *, params: Mapping[str, Any] | None = None, t: float = 0.0,
    components: Sequence[str] | None = None,
) -> dict[str, float]:
    """The value of every input of ``components`` (default: all) at the state ``x`` and time ``t`` (SI)."""
    a = assemble(system)
    tsym, xs, p, y = a.t, a.x, a.p, a.y
    model = system.build()
    signals = {**dict(zip(model.state_names, ca.vertsplit(xs))), **dict(zip(model.output_names, ca.vertsplit(y)))}
    names = [f"{c}.{k}" for c in (components or list(system.components)) for k in system.components[c].INPUTS]
    if not names:
        return {}
    fun = ca.Function("inputs", [tsym, xs, p], [ca.vertcat(*[_input_value(system, n, signals, p, model.parameter_names) for n in names])])
    xv = np.array([x[s] for s in model.state_names])
    values = np.asarray(fun(t, xv, system.parameter_vector(params)), dtype=float).ravel()
    return dict(zip(names, values.tolist()))


def _port_unit(system: System, target: str) -> str:
    cname, _, key = target.partition(".")
    return system.components[cname].INPUTS[key].unit


def _input_value(system: System, target: str, signals: Mapping[str, Any], p: Any, parameter_names: list[str]) -> Any:
    """The value of an input at the point: what feeds a component input, or the parameter."""
    cname, _, key = target.partition(".")
    comp = system.components.get(cname)
    if comp is not None and key in comp.INPUTS:
        source = system.connections.get(target)
        if source is not None and source in signals:
            return signals[source]
        fed = system.hydraulic_inputs().get(target)
        if fed:
            return sum(coef * signals[ref] for coef, ref in fed)
        default = comp.INPUTS[key].default
        return ca.SX(default if default is not None else float("nan"))
    return p[parameter_names.index(system.parameter_key(target))]


@dataclass
class ValveCoefficients:
    r"""Valve sensitivity coefficients of one four-way valve at an operating point ([Efe2014] eqs. 4.8-4.12).

    ``model`` holds the exact derivatives of the component's own flows (its
    regularisation, leakage and compensation tables included, the slope of
    the tables too); ``closed_form`` those of eqs. 4.8-4.11 for the valve's
    parameters, with the compensated coefficient :math:`c_{v,com} = K H c_v`
    at the point (for a
    :class:`~hydroservo.components.valves.four_way.FourWayValve`; empty for
    other valves). Where the table's slope :math:`dK/dx_v` is not zero the two
    flow gains differ by :math:`c_v\,x_v\,H\,dK/dx_v\sqrt{\Delta p}`. Keys: ``K_Qx_A``, ``K_Qx_B`` [m^2/s], ``K_Qp_A``, ``K_Qp_B``
    [m^3/(s Pa)], ``K_px_A``, ``K_px_B`` [Pa/m].
    """

    valve: str
    point: dict[str, float]
    model: dict[str, float]
    closed_form: dict[str, float]

    def to_dict(self) -> dict[str, Any]:
        return {"valve": self.valve, "point": self.point, "model": self.model, "closed_form": self.closed_form}


def valve_coefficients(
    system: System,
    at: str | Mapping[str, Any] = "trim",
    *,
    params: Mapping[str, Any] | None = None,
    t: float = 0.0,
    free: Sequence[str] = (),
) -> list[ValveCoefficients]:
    """The coefficients of every four-way valve of ``system`` that takes a spool position ``xv`` as input."""
    from hydroservo.laws.four_way import valve_coefficients as closed

    found = []
    x0 = operating_point(system, at, params=params, t=t, free=free)
    for cname, comp in system.components.items():
        if not {"xv", "pA", "pB", "pS", "pT"} <= set(comp.INPUTS) or not {"QA", "QB"} <= set(comp.OUTPUTS):
            continue
        lin = linearize(
            system, x0, inputs=[f"{cname}.xv", f"{cname}.pA", f"{cname}.pB", f"{cname}.pS", f"{cname}.pT"],
            outputs=[f"{cname}.QA", f"{cname}.QB"], params=params, t=t,
        )
        D = lin.D
        model = {"K_Qx_A": D[0, 0], "K_Qx_B": D[1, 0], "K_Qp_A": D[0, 1], "K_Qp_B": D[1, 2]}
        model["K_px_A"] = model["K_Qx_A"] / model["K_Qp_A"] if model["K_Qp_A"] else float("nan")
        model["K_px_B"] = model["K_Qx_B"] / model["K_Qp_B"] if model["K_Qp_B"] else float("nan")
        point = {k: lin.u0[f"{cname}.{k}"] for k in ("xv", "pS", "pT", "pA", "pB")}
        form: dict[str, float] = {}
        compensation = getattr(comp, "compensation", None)
        if type(comp).__name__ == "FourWayValve" and callable(compensation):
            v = system.parameter_values() | system.parse_parameters(params)
            pv = {k: v[f"{cname}.{k}"] for k in ("c_v", "x_PA", "x_AT", "x_PB", "x_BT")}
            vv = input_values(system, x0, params=params, t=t, components=[cname]).get(f"{cname}.vv", 0.0)
            pv["c_v"] *= float(compensation(point["xv"], vv, v[f"{cname}.xv_max"]))  # c_v,com of eq. 3.23
            form = {k: float(val) for k, val in closed(point["xv"], point["pS"], point["pT"], point["pA"], point["pB"], **pv).items()}
        found.append(ValveCoefficients(cname, point, {k: float(val) for k, val in model.items()}, form))
    return found


def simulated_response(
    system: System,
    lin: LinearModel,
    frequencies: Sequence[float] | np.ndarray,
    amplitudes: Sequence[float],
    *,
    input: str | None = None,
    output: str | None = None,
    params: Mapping[str, Any] | None = None,
    settle_periods: int = 10,
    measure_periods: int = 4,
    points_per_period: int = 64,
    rtol: float = 1e-7,
) -> FrequencyResponse:
    """The nonlinear system's response to sines about the operating point of ``lin``, beside the linear one.

    The system is run from the operating point with every signal block frozen
    at its value there and a sine of each amplitude (in the input's unit)
    added to ``input`` (a component input of ``lin``); the fundamental of
    ``output`` over the last ``measure_periods`` periods, after the others
    (at least five of the slowest decaying mode's time constants), divided by
    the amplitude, is the gain and phase (the drift of a steady motion is
    taken out: a moving piston's position may be the output). Where the gain
    departs from :meth:`LinearModel.bode` with the amplitude, linearity ends.
    """
    from hydroservo import components as comp_lib
    from hydroservo.analysis.frequency import FrequencyResponse, gain_phase

    i = lin._index(lin.inputs, input, "input")
    o = lin._index(lin.outputs, output, "output")
    target, out_name = lin.inputs[i], lin.outputs[o]
    cname, _, key = target.partition(".")
    if cname not in system.components or key not in system.components[cname].INPUTS:
        raise ParameterError(f"simulated response: input {target!r} must be a component input (not a parameter)")
    if target in system.hydraulic_inputs():
        raise ParameterError(f"simulated response: input {target!r} is fed by a hydraulic node; choose a signal input")
    f = np.asarray(frequencies, dtype=float).ravel()
    amps = np.asarray(amplitudes, dtype=float).ravel()
    if f.size == 0 or np.any(f <= 0) or amps.size == 0 or np.any(amps <= 0):
        raise ParameterError("simulated response: expected positive frequencies and amplitudes")
    probe = system.copy()
    probe.name = f"{system.name} (sine on {target})"
    # every signal block frozen at its value at the operating time: the sine alone moves the system
    frozen = input_values(system, lin.x0, params=params, t=lin.t)
    for tgt, src in list(probe.connections.items()):
        block = probe.components.get(src.split(".")[0])
        if block is not None and type(block).__name__ in SIGNALS:
            name = f"frozen_{src.split('.')[0]}"
            if name not in probe.components:
                probe.add(comp_lib.Step(name, amplitude=frozen[tgt], t_step=0.0))
            probe.connections[tgt] = f"{name}.y"
    source = probe.connections.get(target)
    probe.add(comp_lib.Sine("probe_sine", amplitude=1.0, frequency=1.0))
    probe.add(comp_lib.Sum("probe_sum", gain1=1.0, gain2=1.0))
    if source is not None:
        probe.connections["probe_sum.u1"] = source
    else:
        probe.set("probe_sine.offset", lin.u0[target])
    probe.connections["probe_sum.u2"] = "probe_sine.y"
    probe.connections[target] = "probe_sum.y"
    for state, value in lin.x0.items():
        probe.set_initial(state, value)
    slow = [m.time_constant for m in lin.modes() if m.eigenvalue.real < 0 and np.isfinite(m.time_constant)]
    settle = 5.0 * max(slow, default=0.0)
    # a steady motion lasts only until a stop: the travel a run may take, from the bounds of the moving states
    model = system.build()
    lo, hi = (np.asarray(b, dtype=float).ravel() for b in model.limit_bounds(system.parameter_vector(params)))
    room = np.inf
    for k, w in enumerate(model.watched):
        rate = lin.drift.get(w.signal, 0.0)
        if w.kind == "travel" and w.signal in lin.x0 and rate != 0:
            edge = hi[k] if rate > 0 else lo[k]
            room = min(room, (edge - lin.x0[w.signal]) / rate)
    H = np.full((amps.size, f.size), np.nan + 0j)
    short: list[float] = []
    for a_i, amp in enumerate(amps):
        for f_i, fk in enumerate(f):
            period = 1.0 / fk
            n_settle = max(settle_periods, int(np.ceil(settle / period)))
            t_end = (n_settle + measure_periods) * period
            if t_end > room:
                short.append(float(fk))  # the piston would reach its stop before the sines settle
                continue
            n = measure_periods * points_per_period
            grid = np.concatenate([[0.0], n_settle * period + np.arange(n + 1) * period / points_per_period])
            res = probe.simulate(t_end, params={**(params or {}), "probe_sine.amplitude": amp, "probe_sine.frequency": fk},
                                 t_eval=grid, rtol=rtol, max_steps=10_000_000)
            y = np.asarray(res[out_name])[1:]
            tt = grid[1:]
            y = y - (y[-1] - y[0]) * (tt - tt[0]) / (tt[-1] - tt[0])  # a steady motion's drift out
            w = 2 * np.pi * fk
            yk, tk = y[:-1], tt[:-1]  # whole periods, the end point left out
            a1 = 2.0 / yk.size * np.sum(yk * np.sin(w * tk))
            b1 = 2.0 / yk.size * np.sum(yk * np.cos(w * tk))
            H[a_i, f_i] = (a1 + 1j * b1) / amp
    with np.errstate(invalid="ignore"):
        gain, phase = gain_phase(np.where(np.isnan(H), 1.0, H), f)
    gain[np.isnan(H)], phase[np.isnan(H)] = np.nan, np.nan
    info: dict[str, Any] = {"input": target, "output": out_name, "linear": False}
    if short:
        info["not_run"] = (
            f"at {max(short):g} Hz and below the runs ({settle_periods + measure_periods} periods or more) would drive the "
            f"steady motion into its stop (about {room:.3g} s away); those points are NaN"
        )
    return FrequencyResponse(amps, f, gain, phase, label="simulated (nonlinear)", info=info)
