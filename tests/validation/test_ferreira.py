"""The KBSDG4V-3 servo-solenoid valve against FerreiraND: printed pseudo-sections, datasheet, Bode identification.

Published values are those of FerreiraND section 5 (KBSDG4V-3), read from the
package's parameter set ``FerreiraND`` (one source for the printed values).
The paper prints four significant digits; the tolerance is one unit in the
last printed digit (alpha = 4.2415 is printed 4.241: truncated, not rounded).

The published spool dynamics (section 6: omega_n, xi, L_v, L_a and the
delay) are the ``[dynamics]`` table of the same parameter set
(:func:`hydroservo.validation.ferreira.published_dynamics`). The
manufacturer's curves are not available, so identification is proven on data
generated from these values.
"""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.analysis import FrequencyResponse
from hydroservo.components import PseudoSectionValve
from hydroservo.data import parameter_set
from hydroservo.identification import fit_datasheet, fit_spool_dynamics
from hydroservo.laws import pseudo_section as ps
from hydroservo.validation import printed_digit
from hydroservo.validation.ferreira import published_dynamics

PAPER = parameter_set("FerreiraND")
DATASHEET = PAPER.table("datasheet")
PUBLISHED = published_dynamics()


# -- static model, section 5 --------------------------------------------------------
def test_variable_structure_published_parameters(ferreira_printed: dict[str, dict[str, str]]) -> None:
    # k, gamma, alpha, beta, x_t as FerreiraND section 5 prints them (eqs. 26, 29, 32), from the datasheet fitted the
    # paper's way; tolerance one unit in the last printed digit (module docstring)
    fit = fit_datasheet(DATASHEET, "variable", "pressure-gain,leakage")
    got = fit.in_paper_units()
    for name, text in ferreira_printed["variable"].items():
        assert got[name] == pytest.approx(float(text.split()[0]), abs=printed_digit(text)), name


def test_fixed_structure_published_parameters(ferreira_printed: dict[str, dict[str, str]]) -> None:
    # k1..k5 as FerreiraND section 5 prints them (eqs. 34, 36, 37, 39, 40); tolerance one unit in the last printed digit
    fit = fit_datasheet(DATASHEET, "fixed", "pressure-gain,flow-gain")
    got = fit.in_paper_units()
    for name, text in ferreira_printed["fixed"].items():
        assert got[name] == pytest.approx(float(text.split()[0]), abs=printed_digit(text)), name


def test_published_sets_reproduce_the_datasheet(ferreira_published: dict[str, dict[str, float]]) -> None:
    """The printed parameters themselves give the datasheet values (to their printed precision).

    Datasheet: FerreiraND section 5 (Q_n, K_q0 at P_n = 35 bar per edge; K_p0, q_lk0 at P_s = 70 bar), the
    [datasheet] table of the parameter set. The parameters are printed to four significant digits, i.e. rounded by
    up to 5e-4 relative, and the characteristics move with them: 5e-4 for q_lk0, K_q0 and the fixed K_p0 (found
    3.6e-4, 9e-5, 1.3e-4), 2e-4 for Q_n (found 1.2e-4 and 7e-5). The variable K_p0 is the printed k itself (in the
    exponential core P_L = tanh(k x_s)), exact but for the finite-difference slope: 1e-9.
    """
    P_n, P_s = PAPER.si("datasheet", "P_n", "Pa"), PAPER.si("datasheet", "P_s", "Pa")
    var = (
        PseudoSectionValve("v", structure="variable")
        .replace(**ferreira_published["variable"])
        .characteristics(P_n, P_s)
    )
    fix = PseudoSectionValve("v", structure="fixed").replace(**ferreira_published["fixed"]).characteristics(P_n, P_s)
    Q_n, K_q0, q_lk0 = (PAPER.si("datasheet", k, "m^3/s") for k in ("Q_n", "K_q0", "q_lk0"))
    K_p0 = PAPER.si("datasheet", "K_p0", "")
    assert var["Q_n"] == pytest.approx(Q_n, rel=2e-4)
    assert var["K_p0"] == pytest.approx(K_p0, rel=1e-9)
    assert var["q_lk0"] == pytest.approx(q_lk0, rel=5e-4)
    assert fix["Q_n"] == pytest.approx(Q_n, rel=2e-4)
    assert fix["K_q0"] == pytest.approx(K_q0, rel=5e-4)
    assert fix["K_p0"] == pytest.approx(K_p0, rel=5e-4)
    # zero leakage and zero leakage slope at x_s = 1 (eqs. 39-40): A_n(1) and its slope vanish, to the printed
    # precision of terms of order sqrt(k3) that cancel there (1e-4, and 1e-3 for the finite-difference slope)
    p = ferreira_published["fixed"]
    h = 1e-5
    An = ps.fixed_structure(-np.array([1.0 - h, 1.0]), **p)
    assert abs(An[1]) < 1e-4 * p["k3"] ** 0.5
    assert abs((An[1] - An[0]) / h) < 1e-3 * p["k3"] ** 0.5


# -- spool dynamics, section 6 -------------------------------------------------------
@pytest.mark.slow  # over 5 s (the default suite stays inside its 5 minutes)
def test_identification_round_trip(published_bode: FrequencyResponse) -> None:
    """FerreiraND eq. 43 from a start 35-40 % away from every value: recover all within 1 %.

    Data: the published dynamics (FerreiraND section 6, the [dynamics] table) on the Bode grid of Fig. 10 (5, 25,
    50 % and 10-300 Hz, the [bode] table). 1 % is the tolerance of the validation rows bode.* (the floor the
    identification must meet, as the manufacturer's curves are not available); noise free, 1e-4 is what is achieved.
    """
    factors = {"omega_n": 1.35, "zeta": 0.65, "L_v": 1.4, "L_a": 0.6}
    start = {k: PUBLISHED[k] * f for k, f in factors.items()}
    fit = fit_spool_dynamics(published_bode, "rate-limited", start)
    for k, v in PUBLISHED.items():
        assert fit.params[k] == pytest.approx(v, rel=1e-2), k
        assert abs(fit.params[k] / v - 1) < 1e-4, k  # what is actually achieved, noise free
    assert fit.max_gain_error(200.0) < 1e-3


@pytest.mark.slow
def test_validation_table_of_ferreira(validated) -> None:
    """``hydroservo validate servo-solenoid-cylinder``: every row gives the verdict it expects.

    Nothing of FerreiraND is "NOT reproduced": every printed value is reproduced, and the unmatched K_q0 and the
    "typically 200 Hz" bandwidth are information rows (hydroservo/validation/ferreira.py says why).
    """
    checks = validated("servo-solenoid-cylinder")
    assert {c.verdict for c in checks} <= {"reproduced", "info"}
    assert {c.row.key: c.verdict for c in checks} == {c.row.key: c.row.expected for c in checks}
