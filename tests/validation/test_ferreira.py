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
    fit = fit_datasheet(DATASHEET, "variable", "pressure-gain,leakage")
    got = fit.in_paper_units()
    for name, text in ferreira_printed["variable"].items():
        assert got[name] == pytest.approx(float(text.split()[0]), abs=printed_digit(text)), name


def test_fixed_structure_published_parameters(ferreira_printed: dict[str, dict[str, str]]) -> None:
    fit = fit_datasheet(DATASHEET, "fixed", "pressure-gain,flow-gain")
    got = fit.in_paper_units()
    for name, text in ferreira_printed["fixed"].items():
        assert got[name] == pytest.approx(float(text.split()[0]), abs=printed_digit(text)), name


def test_published_sets_reproduce_the_datasheet(ferreira_published: dict[str, dict[str, float]]) -> None:
    """The printed parameters themselves give the datasheet values (to their printed precision)."""
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
    # zero leakage and zero leakage slope at x_s = 1 (eqs. 39-40): A_n(1) and its slope vanish
    p = ferreira_published["fixed"]
    h = 1e-5
    An = ps.fixed_structure(-np.array([1.0 - h, 1.0]), **p)
    assert abs(An[1]) < 1e-4 * p["k3"] ** 0.5
    assert abs((An[1] - An[0]) / h) < 1e-3 * p["k3"] ** 0.5


# -- spool dynamics, section 6 -------------------------------------------------------
def test_identification_round_trip(published_bode: FrequencyResponse) -> None:
    """Seed 000 eq. 43 from a start 35-40 % away from every value: recover all within 1 % (issue floor)."""
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
