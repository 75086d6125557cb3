"""``axcheck.evaluate_files``: every file of tests/data in one call gives what ``read``
then ``evaluate`` give one by one (the same JSON, bit for bit), in the paths' order, on
one thread or several, and the same read errors in the same places."""

import json
from pathlib import Path
from typing import List, Union

import pytest

import axcheck
from test_same_numbers import data_files


def one_by_one(path: str) -> Union[str, axcheck.ReadError]:
    try:
        m = axcheck.read(path)
    except axcheck.ReadError as e:
        return e
    return json.dumps(axcheck.evaluate(m).json)


def as_text(done: List[Union[axcheck.Evaluation, axcheck.ReadError]]) -> List[Union[str, axcheck.ReadError]]:
    return [d if isinstance(d, axcheck.ReadError) else json.dumps(d.json) for d in done]


@pytest.mark.parametrize("jobs", [1, 2, None])
def test_every_file_as_one_by_one(jobs: Union[int, None]) -> None:
    files = data_files()
    expected = [one_by_one(f) for f in files]
    got = as_text(axcheck.evaluate_files(files, jobs=jobs, errors="return"))
    assert len(got) == len(files)
    errors = 0
    for path, e, g in zip(files, expected, got):
        if isinstance(e, axcheck.ReadError):
            assert isinstance(g, axcheck.ReadError), path
            assert (str(g), g.path, g.line, g.column, g.sheet, g.field) == (
                str(e), e.path, e.line, e.column, e.sheet, e.field
            )
            errors += 1
        else:
            assert g == e, path
    assert 0 < errors < len(files)  # both kinds were compared


def test_the_first_error_is_raised_after_all_were_tried() -> None:
    files = data_files()
    bad = [f for f in files if isinstance(one_by_one(f), axcheck.ReadError)]
    good = "tests/data/iso230-2_table2.csv"
    with pytest.raises(axcheck.ReadError) as raised:
        axcheck.evaluate_files([good, bad[1], bad[0], good])
    assert raised.value.path == bad[1]


def test_options_reach_every_file() -> None:
    path = Path("tests/data/iso230-2_table2.csv")
    [gost] = axcheck.evaluate_files([path], standard="gost27843", s_from_ranges=True)
    assert gost.json == axcheck.evaluate(axcheck.read(str(path)), "gost27843", True).json
    assert axcheck.evaluate_files([]) == []
    with pytest.raises(ValueError, match="errors"):
        axcheck.evaluate_files([path], errors="ignore")  # type: ignore[call-overload]
    with pytest.raises(ValueError, match="unknown standard"):
        axcheck.evaluate_files([path], standard="iso9999")
