"""Time tables read from CSV files (hydroservo.io.tables) feeding a table source."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.errors import ParameterError
from hydroservo.io import read_time_table


def test_table_source_from_csv(tmp_path) -> None:
    path = tmp_path / "u.csv"
    path.write_text("t,volts\n0,0\n1,2\n2,2\n")
    s = hs.System("table")
    s.add(c.Table("u", *read_time_table(path, "volts"), unit="V"))
    s.add(c.Lag("lag", unit="V"))
    s.connect("u.y", "lag.u")
    r = s.simulate(t_eval=[0.0, 0.5, 1.5])
    np.testing.assert_allclose(r["u.y"], [0.0, 1.0, 2.0])
    with pytest.raises(ParameterError, match="'amps' is not a column"):
        c.Table("u", *read_time_table(path, "amps"))


def test_lookup_table_parsed_as_hopsan_reads_it() -> None:
    """Hopsan's CSV conventions (Signal1DLookupTable): lines skipped, then initial comment lines, any one-character
    separator, a decimal comma, columns by 0-based index, rows sorted by their breakpoints."""
    from hydroservo.io.tables import parse_lookup_table

    text = "title line\n# x;a;y\n\n3;7;9,5\n1; 5 ;1\n2;6;4\n"
    x, y = parse_lookup_table(text, 0, 2, separator=";", skip=1, comment="#")
    np.testing.assert_array_equal(x, [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(y, [1.0, 4.0, 9.5])
    x, y = parse_lookup_table("0,1\n1,3\n", 1, 0)  # the columns swapped
    np.testing.assert_array_equal(x, [1.0, 3.0])
    np.testing.assert_array_equal(y, [0.0, 1.0])


@pytest.mark.parametrize(
    ("text", "options", "message"),
    [
        ("0,1\n1,x\n", {}, r"line 2, column 1: 'x' is no finite number"),
        ("0,1\n1,nan\n", {}, "is no finite number"),
        ("0,1\n1\n", {}, r"line 2: 1 column\(s\); expected column 1"),
        ("0,1\n", {}, "1 row"),
        ("0,1\n0,2\n", {}, "two rows have the breakpoint 0"),
        ("0,1\n1,2\n", {"separator": ";;"}, "expected one character"),
        ("0,1\n1,2\n", {"comment": "//"}, "expected one character"),
        ("# 0,1\n1,2\n", {}, r"line 1, column 0: '# 0' is no finite number"),  # no comment character given
    ],
)
def test_malformed_lookup_tables_are_refused(text: str, options: dict, message: str) -> None:
    from hydroservo.io.tables import parse_lookup_table

    with pytest.raises(ParameterError, match=message):
        parse_lookup_table(text, **options, what="LUT")


def test_lookup_table_file_missing_or_binary_is_refused(tmp_path) -> None:
    from hydroservo.io.tables import read_lookup_table

    with pytest.raises(ParameterError, match="cannot read"):
        read_lookup_table(tmp_path / "none.csv", what="LUT")
    (tmp_path / "b.csv").write_bytes(b"0,1\x00\n1,2\n")
    with pytest.raises(ParameterError, match="binary"):
        read_lookup_table(tmp_path / "b.csv", what="LUT")


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("0 1\n1 2\n", "does not begin with 'VERSION'"),
        ("'VERSION'\n3\n't'\n1 2\n'x'\n1\n0\n1\n", "PLO version '3': expected 1 or 2"),
        ("'VERSION'\n1\n't'\n2 3\n'Time', 'x', 'y'\n1 1 1\n0 0 0\n1 1 1\n", "6 numbers of data where the header announces 9"),
        ("'VERSION'\n1\n't'\n1 2\n'Time', 'Data'\n1 1\n0 x\n1 2\n", "a field that is no number"),
        ("'VERSION'\n1\n't'\n1 2\n'Time', 'Data'\n1 1\n0 1\n0 2\n", "two rows have the breakpoint 0"),
    ],
)
def test_plo_tables_are_read_as_hopsans_ploparser_and_malformed_ones_refused(text: str, message: str) -> None:
    """Hopsan's PLO text (Signal1DPLOLookupTable): a first 'Time' column is not counted in the header's number of
    columns, the plot scales are skipped, the rows sorted; no 'VERSION', another version, too few numbers, a field
    that is no number and a repeated breakpoint are refused."""
    from hydroservo.io.tables import parse_plo_table

    text_ok = "'VERSION'\n2\n'title' 'm'\n2 3\n'Time',  'a',  'b'\n1 1 1\n0 5 9\n1 3 1\n2 4 4\nDAT m\n"
    x, y = parse_plo_table(text_ok, "a", "b")
    np.testing.assert_array_equal(x, [3.0, 4.0, 5.0])
    np.testing.assert_array_equal(y, [1.0, 4.0, 9.0])
    with pytest.raises(ParameterError, match=message):
        parse_plo_table(text, "Time", "Data" if "Data" in text else "x", what="LUT")
