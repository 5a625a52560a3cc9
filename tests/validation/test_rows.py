"""Every row of every validation gives the verdict it expects (what ``hydroservo validate NAME`` exits 0 on).

One test per validation of :data:`hydroservo.validation.VALIDATIONS`. Each row carries its source (citation
key and equation, table or section), the published value, the tolerance and why (hydroservo/validation/*.py,
docs/validation.md); a row whose verdict differs from ``row.expected`` is a regression, or an improvement to
record in the row. The other files of tests/validation/ check the sources in more detail.
"""

from __future__ import annotations

import pytest

from hydroservo.validation import VALIDATIONS, regressions

#: Validations that take more than about 5 s (the FerreiraND Bode identification and datasheet fits; Hopsan's 34
#: models, imported and run, about 20 s).
SLOW = {"servo-solenoid-cylinder", "hopsan-examples"}


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.slow) if n in SLOW else n for n in VALIDATIONS])
def test_every_row_gives_its_expected_verdict(name: str, validated) -> None:
    checks = validated(name)
    assert checks, f"validation {name!r} has no rows"
    bad = regressions(checks)
    assert not bad, "\n".join(
        f"{c.row.key} ({c.row.source}): published {c.row.published}, computed {c.computed:.6g}, "
        f"verdict {c.verdict!r}, expected {c.row.expected!r}"
        for c in bad
    )
