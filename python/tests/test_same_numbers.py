"""The Python package against the command line: every file in tests/data through
``axcheck eval --json`` and through :func:`axcheck.evaluate` gives the same JSON (the
same keys and, bit for bit, the same numbers), and the same read errors."""

import json
import os
import subprocess
from pathlib import Path
from typing import Any, Dict, List, Tuple

import pytest

import axcheck

REPO = Path(__file__).resolve().parents[2]
DATA = REPO / "tests" / "data"
EXAMPLE = REPO / "example-campaign"
SUFFIXES = {".csv", ".rtl", ".rta", ".txt", ".xlsx", ".tsv", ".dat", ".md"}


def cli() -> str:
    """The command line built beside the package (``AXCHECK_BIN`` to choose another)."""
    given = os.environ.get("AXCHECK_BIN")
    if given:
        return given
    target = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    return str(target / "release" / "axcheck")


def run(*args: str) -> Tuple[int, str, str]:
    done = subprocess.run([cli(), *args], capture_output=True, text=True, cwd=REPO)
    return done.returncode, done.stdout, done.stderr


def data_files() -> List[str]:
    files = [p for p in DATA.rglob("*") if p.is_file() and p.suffix.lower() in SUFFIXES]
    return sorted(str(p.relative_to(REPO)) for p in files)


def test_there_are_files_to_compare() -> None:
    assert len(data_files()) > 50


@pytest.mark.parametrize("path", data_files())
def test_eval_is_the_command_lines(path: str) -> None:
    code, stdout, stderr = run("eval", "--json", path)
    try:
        m = axcheck.read(path)  # the name as given, relative to the repository
    except axcheck.ReadError as e:
        assert code == 2, f"the CLI read {path}, Python did not: {e}"
        assert stderr.strip() == f"axcheck: error: {e}"
        return
    except ValueError as e:  # not a read error: the CLI refuses it too
        assert code == 2, f"{path}: {e}"
        return
    assert code == 0, f"Python read {path}, the CLI did not: {stderr}"
    ours: Dict[str, Any] = axcheck.evaluate(m).json
    ours.pop("uncertainty")
    theirs = json.loads(stdout)
    assert ours == theirs
    # Bit for bit: the same text as well as the same values.
    assert json.dumps(ours) == json.dumps(theirs)


@pytest.mark.parametrize(
    "path",
    ["tests/data/iso230-2_table2.csv", "example-campaign/data/vmc07-y.csv", "example-campaign/data/rotary-c.csv"],
)
def test_diagnose_is_the_command_lines(path: str) -> None:
    code, stdout, stderr = run("diagnose", "--json", path)
    assert code == 0, stderr
    assert axcheck.diagnose(axcheck.read(path)) == json.loads(stdout)


def test_compensate_is_the_command_lines() -> None:
    path = "example-campaign/data/vmc07-x.csv"
    active = "example-campaign/active/VMC-07/X.ini"
    args = ["--axis", "X1", "--reference", "0", "--active", active, "--active-backlash", "4.196"]
    code, stdout, stderr = run("compensate", path, "-c", "siemens-840d", "--json", *args)
    assert code == 0, stderr
    ours = axcheck.compensate(
        axcheck.read(path), "siemens-840d", active=active, active_backlash=4.196, reference=0.0, axis="X1"
    )
    text = ours.pop("file_text")
    assert ours == json.loads(stdout)
    assert text.startswith("; ") or "$AA_ENC_COMP" in text
    code, table, _ = run("compensate", path, "-c", "siemens-840d", *args)
    assert code == 0 and table == text


def test_verify_is_the_command_lines() -> None:
    before = "example-campaign/data/mill3-y-before.csv"
    after = "example-campaign/data/mill3-y.csv"
    table = "example-campaign/active/MILL-3/Y.txt"
    other = "example-campaign/active/MILL-3/X.txt"
    args = ["--table", table, "-c", "linuxcnc", "--other", f"X={other}", "--json"]
    code, stdout, stderr = run("verify", before, after, *args)
    assert code in (0, 1), stderr
    ours = axcheck.verify(axcheck.read(before), axcheck.read(after), "linuxcnc", table, others={"X": other})
    assert ours == json.loads(stdout)
    assert ours["verdict"] != "effective"  # Y was loaded with its trims negated


def test_a_read_error_names_file_line_and_field(tmp_path: Path) -> None:
    bad = tmp_path / "bad.csv"
    bad.write_text("target_mm,direction,run,deviation_um\n0,up,1,1.5\n10,up,1,abc\n")
    with pytest.raises(axcheck.ReadError) as raised:
        axcheck.read(str(bad))
    e = raised.value
    assert e.path == str(bad)
    assert e.line == 3
    assert e.field == "deviation_um"
    assert str(e).startswith(f"{bad}:3")
    assert isinstance(e, ValueError)


def test_a_frame_reads_as_its_file() -> None:
    pandas = pytest.importorskip("pandas")
    m = axcheck.read("tests/data/iso230-2_table2.csv")
    frame = m.to_frame()
    assert list(frame.columns) == ["target_mm", "direction", "run", "deviation_um", "time_s"]
    assert len(frame) == 110  # 11 targets, 5 runs, 2 directions
    again = axcheck.Measurement.from_frame(frame.drop(columns=["time_s"]))
    assert axcheck.evaluate(again).values == axcheck.evaluate(m).values
    assert isinstance(frame, pandas.DataFrame)


def test_table_2_layout() -> None:
    pytest.importorskip("pandas")
    e = axcheck.evaluate(axcheck.read("tests/data/iso230-2_table2.csv"))
    table = e.targets()
    assert len(table) == 11
    # ISO 230-2 Table 2, target 1: x̄↑ = −1.6 µm, B₁ = −3.86 µm.
    assert round(table.loc[1, "mean_up"], 2) == -1.6
    assert round(table.loc[1, "reversal"], 2) == -3.86
    assert set(e.expanded_uncertainty) >= {"A", "E", "M", "R", "B"}


def test_check_is_the_summary_table_of_run(tmp_path: Path) -> None:
    """`axcheck.check` gives the rows of `summary.csv` as `run` writes it, cell by cell."""
    import csv

    out = tmp_path / "out"
    code, _, stderr = run("run", "example-campaign/campaign.yaml", "--out", str(out), "--no-pdf")
    assert code == 1, stderr  # the example fails on purpose
    checked = axcheck.check("example-campaign/campaign.yaml", diagnose=True)
    assert not checked.passed
    with open(out / "summary.csv", newline="", encoding="utf-8") as f:
        written = list(csv.reader(f))
    assert written[0] == checked.columns
    assert len(written) - 1 == len(checked.rows) == 33
    for theirs, ours in zip(written[1:], checked.rows):
        for column, text, cell in zip(checked.columns, theirs, ours):
            if cell is None:
                assert text == "", column
            elif isinstance(cell, bool):
                assert text == str(cell).lower(), column
            elif isinstance(cell, float):
                assert float(text) == cell, column  # bit for bit
            else:
                assert text == str(cell), column


def test_run_writes_the_campaigns_outputs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("AXCHECK_BIN", cli())
    done = axcheck.run("example-campaign/campaign.yaml", str(tmp_path / "out"), "--no-pdf")
    assert done.exit_status == 1
    assert len(done.results["axes"]) == 33  # one entry per axis test
    assert (tmp_path / "out" / "summary.html").is_file()
    with pytest.raises(RuntimeError, match="nope.yaml"):
        axcheck.run("nope.yaml", str(tmp_path / "other"))


def test_plan_is_the_command_lines(tmp_path: Path) -> None:
    out = tmp_path / "plan.yaml"
    code, _, stderr = run("plan", "--kind", "linear", "--travel", "1000", "--pitch", "10", "-o", str(out))
    assert code == 0, stderr
    ours = axcheck.plan("linear", 1000, pitch=10)
    assert ours["yaml"] == out.read_text(encoding="utf-8")
    assert ours["targets"][0] == 10.0 and ours["targets"][-1] == 990.0 and ours["runs"] == 5
    assert ours["findings"] == []
    # Targets given are checked by the same rules: 3 targets over 980 mm are too few
    # (ISO 230-2 4.3.2), and evenly spaced ones may alias a periodic error (4.2).
    few = axcheck.plan("linear", 1000, targets=[10.0, 500.0, 990.0])
    assert [f["id"] for f in few["findings"]] == ["iso-4.3.2-targets", "iso-4.2-uniform-spacing"]


def test_the_figures_are_the_reports_scenes() -> None:
    """ISO 230-2 Fig. 2a and 2b as SVG: well-formed, with the parameters the report's
    chart prints beside them."""
    import xml.etree.ElementTree as ET

    e = axcheck.evaluate(axcheck.read("tests/data/iso230-2_table2.csv"))
    texts = {}
    for name, svg in e.figures().items():
        root = ET.fromstring(svg)
        texts[name] = [t.text for t in root.iter("{http://www.w3.org/2000/svg}text")]
    both = texts["bidirectional"]
    for symbol, value in (("A", "9.59"), ("E", "7.70"), ("M", "3.99")):
        assert both[both.index(symbol) + 1] == value, both
    each = texts["unidirectional"]
    assert each[each.index("A↑") + 1] == "6.14" and each[each.index("A↓") + 1] == "5.77", each


def test_a_polars_frame_reads_as_its_file() -> None:
    polars = pytest.importorskip("polars")
    m = axcheck.read("tests/data/iso230-2_table2.csv")
    rows = m.readings()
    columns = ["target_mm", "direction", "run", "deviation_um"]
    frame = polars.DataFrame({c: [r[k] for r in rows] for k, c in enumerate(columns)})
    assert axcheck.evaluate(axcheck.Measurement.from_frame(frame)).values == axcheck.evaluate(m).values


def test_the_catalogue_names_each_parameter_with_its_clause() -> None:
    """Each parameter an evaluation gives is in the catalogue, with the clause `eval --json`
    prints in `details`."""
    e = axcheck.evaluate(axcheck.read("tests/data/gost27843_example.csv"), standard="gost27843")
    catalogue = {p["key"]: p for p in axcheck.parameters("gost27843")}
    assert set(e.values) <= set(catalogue)
    for detail in e.parameters:
        assert catalogue[detail["key"]]["clause"] == detail["clause"]
        assert catalogue[detail["key"]]["name"] == detail["name"]
    iso = {p["key"]: p["clause"] for p in axcheck.parameters()}
    assert iso["A"] == "ISO 230-2 2.23" and iso["B"] == "ISO 230-2 2.13"



GEOMETRY = "tests/data/geometry"


@pytest.mark.parametrize(
    "args, ours",
    [
        (
            [f"{GEOMETRY}/x-straightness-y.csv", "--test", "straightness", "--direction", "Y", "--local", "300"],
            lambda: axcheck.straightness(axcheck.read(f"{GEOMETRY}/x-straightness-y.csv"), local=300, direction="Y"),
        ),
        (
            [f"{GEOMETRY}/x-straightness-y.csv", "--test", "straightness", "--line", "end-point", "--optics", "0.5,0.5,0.15"],
            lambda: axcheck.straightness(
                axcheck.read(f"{GEOMETRY}/x-straightness-y.csv"), line="end_point", optics=(0.5, 0.5, 0.15)
            ),
        ),
        (
            [f"{GEOMETRY}/x-pitch.csv", "--test", "angular", "--direction", "B"],
            lambda: axcheck.angular(axcheck.read(f"{GEOMETRY}/x-pitch.csv", angular=True), direction="B"),
        ),
        (
            [f"{GEOMETRY}/hp5528a-axis-1.csv", "--test", "squareness", "--second", f"{GEOMETRY}/hp5528a-axis-2.csv",
             "--line", "end-point", "--square-error", "1.5", "--convention", "under-90"],
            lambda: axcheck.squareness(
                axcheck.read(f"{GEOMETRY}/hp5528a-axis-1.csv"), axcheck.read(f"{GEOMETRY}/hp5528a-axis-2.csv"),
                line="end_point", square_error=1.5, convention="under_90",
            ),
        ),
        (
            [f"{GEOMETRY}/x-straightness-y.csv", "--test", "squareness", "--second", f"{GEOMETRY}/y-straightness-x.csv",
             "--square-u", "0.2", "--optics", "hp5528a-short"],
            lambda: axcheck.squareness(
                axcheck.read(f"{GEOMETRY}/x-straightness-y.csv"), axcheck.read(f"{GEOMETRY}/y-straightness-x.csv"),
                square_u=0.2, optics="hp5528a_short",
            ),
        ),
    ],
)
def test_the_other_tests_are_the_command_lines(args: List[str], ours: Any) -> None:
    code, stdout, stderr = run("eval", "--json", *args)
    assert code == 0, stderr
    assert json.dumps(ours()) == json.dumps(json.loads(stdout))


def test_an_angular_file_is_read_only_as_one() -> None:
    with pytest.raises(axcheck.ReadError) as raised:
        axcheck.read(f"{GEOMETRY}/x-pitch.csv")
    assert raised.value.field is None or "deviation_arcsec" in str(raised.value)
    with pytest.raises(axcheck.ReadError) as raised:
        axcheck.read(f"{GEOMETRY}/x-straightness-y.csv", angular=True)
    assert raised.value.field == "deviation_um"
    assert "an angular test of a linear axis takes angular deviations" in str(raised.value)
