"""Bode data files (hydroservo.io.bode): round trip and bad files."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.analysis import FrequencyResponse
from hydroservo.errors import ParameterError
from hydroservo.identification import spool_response
from hydroservo.io import read_bode, write_bode
from hydroservo.validation.ferreira import bode_grid, published_dynamics

PUBLISHED = published_dynamics()
AMPS, _ = bode_grid()


def test_bode_csv_round_trip_and_bad_files(tmp_path, published_bode: FrequencyResponse) -> None:
    path = write_bode(published_bode, tmp_path / "bode.csv")
    back = read_bode(path)
    np.testing.assert_allclose(back.gain_db, published_bode.gain_db, rtol=1e-9)
    np.testing.assert_allclose(back.amplitudes, AMPS)
    bad = tmp_path / "bad.csv"
    bad.write_text("frequency [Hz],gain [dB]\n10,0.1\n")
    with pytest.raises(ParameterError, match="missing column.*amplitude"):
        read_bode(bad)
    bad.write_text("frequency [rad/s],amplitude [%],gain [dB]\n10,5,0.1\n")
    with pytest.raises(ParameterError, match="expected unit \\[hz\\]"):
        read_bode(bad)
    bad.write_text("frequency [Hz],amplitude [%],gain [dB]\n10,5,0.1\n20,25,0.1\n")
    with pytest.raises(ParameterError, match="every amplitude at every frequency"):
        read_bode(bad)
    with pytest.raises(ParameterError, match="fractions of the stroke"):
        spool_response(PUBLISHED, [5.0], [10.0])
