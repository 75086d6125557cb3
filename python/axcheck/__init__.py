"""axcheck in Python: ISO 230-2 (GB/T 17421.2), GOST 27843, VDI 3441 and NMTBA
positioning tests evaluated by the same code as the ``axcheck`` command line.

Every function returns what the command line prints for the same request (``eval --json``,
``diagnose --json``, ``compensate --json``, ``verify --json``), parsed: the same keys and,
bit for bit, the same numbers. pandas is needed only for the DataFrame methods, matplotlib
only for :meth:`Evaluation.plot`.

>>> import axcheck
>>> m = axcheck.read("tests/data/iso230-2_table2.csv")
>>> e = axcheck.evaluate(m)
>>> round(e.values["A"], 2)  # ISO 230-2 2.23, bidirectional accuracy of positioning
9.59
"""

from __future__ import annotations

import json
import os
from typing import TYPE_CHECKING, Any, Dict, Iterable, List, Literal, Optional, Tuple, Union, overload

from . import _axcheck
from ._errors import ReadError

if TYPE_CHECKING:  # pragma: no cover
    import pandas

__all__ = [
    "Checked",
    "Run",
    "Evaluation",
    "Measurement",
    "ReadError",
    "check",
    "compensate",
    "run",
    "controllers",
    "diagnose",
    "evaluate",
    "evaluate_files",
    "angular",
    "parameters",
    "squareness",
    "straightness",
    "plan",
    "read",
    "verify",
]

__version__: str = _axcheck.__version__

#: One reading in the long layout: target (mm or deg), direction (``up``/``down``), run,
#: deviation (µm or arcsec), time (s) or None.
Reading = Tuple[float, str, int, float, Optional[float]]


class Measurement:
    """A positioning test as read: the readings and what the file was recognised as."""

    def __init__(self, raw: Any) -> None:
        self._raw = raw

    @property
    def file(self) -> str:
        """The file's name as given (``<frame>`` for a DataFrame)."""
        return str(self._raw.file)

    @property
    def kind(self) -> str:
        """``linear`` (positions in mm, deviations in µm) or ``rotary`` (deg, arcsec)."""
        return str(self._raw.kind)

    @property
    def recognised(self) -> Dict[str, Any]:
        """What the file was read as: ``layout``, ``name``, ``notes`` (``eval --json``)."""
        value: Dict[str, Any] = json.loads(self._raw.recognised_json())
        return value

    @property
    def layout(self) -> str:
        """The layout recognised from the content (``long_csv``, ``xlsx``, ``renishaw`` …)."""
        return str(self.recognised["layout"])

    @property
    def notes(self) -> List[str]:
        """What the reader assumed or left out, in words."""
        return list(self.recognised.get("notes", []))

    def readings(self) -> List[Reading]:
        """The readings, one tuple per reading (see :data:`Reading`)."""
        return list(self._raw.readings())

    def to_frame(self) -> "pandas.DataFrame":
        """The readings as a DataFrame in the long layout the command line reads:
        ``target_mm`` (or ``target_deg``), ``direction``, ``run``, ``deviation_um`` (or
        ``deviation_arcsec``), ``time_s``."""
        import pandas

        position, deviation = _columns(self.kind)
        columns = [position, "direction", "run", deviation, "time_s"]
        return pandas.DataFrame.from_records(self.readings(), columns=columns)

    @classmethod
    def from_frame(cls, frame: Any, name: str = "<frame>") -> "Measurement":
        """A test from a pandas or polars DataFrame in the long layout (the columns named
        as a long CSV names them: ``target_mm``, ``direction``, ``run``,
        ``deviation_um``, optionally ``time_s`` and ``temp_NAME_c``), read by the same
        reader as a file, so that its checks and messages are the same."""
        if hasattr(frame, "write_csv"):  # polars
            text = frame.write_csv()
        else:
            text = frame.to_csv(index=False, float_format="%.17g")
        return cls(_axcheck.read_text(text, name))

    def __repr__(self) -> str:
        return f"Measurement({self.file!r}, {self.kind}, {self.layout})"


def _columns(kind: str) -> Tuple[str, str]:
    if kind == "rotary":
        return "target_deg", "deviation_arcsec"
    return "target_mm", "deviation_um"


def read(
    path: str, sheet: Optional[str] = None, reference: Optional[str] = None, angular: bool = False
) -> Measurement:
    """Reads a measurement file in any layout the command line reads (long or wide CSV,
    XLSX, ecmc, the ecmc ISO 230 app, Renishaw ``.rtl``/``.rta``), recognised by content.

    ``sheet`` names a workbook's sheet (the first by default); ``reference`` an ecmc ISO
    230 app file's reference (``1`` to ``5``, ``rbv``; the one it evaluated by default).
    ``angular`` reads an angular test of a linear axis (pitch, yaw, roll: angles at
    ``target_mm``, ``deviation_arcsec``/``_urad``/``_deg`` in a long table or
    ``up_1_arcsec``, ``down_1_urad``, … in a wide one, as CSV or an XLSX sheet).
    A file that cannot be read raises :class:`ReadError` naming file, line and field.
    """
    return Measurement(_axcheck.read(str(path), sheet, reference, angular))


class Evaluation:
    """The parameters of one test by one standard, as ``axcheck eval --json`` prints them."""

    def __init__(self, raw: Any) -> None:
        self._raw = raw
        self._json: Optional[Dict[str, Any]] = None

    @property
    def json(self) -> Dict[str, Any]:
        """The whole of ``eval --json``, and ``uncertainty`` (ISO/TR 230-9: U and each
        parameter's budget), parsed when first asked for."""
        if self._json is None:
            self._json = json.loads(self._raw.json())
        return self._json

    @property
    def standard(self) -> str:
        """The standard's key (``iso230-2``, ``gost27843`` …)."""
        return str(self.json["standard"])

    @property
    def unit(self) -> str:
        """The deviations' unit: ``um`` or ``arcsec``."""
        return str(self.json["unit"])

    @property
    def values(self) -> Dict[str, float]:
        """Each parameter's value by its key (``A``, ``E_up``, ``B_mean`` …), µm or arcsec."""
        return dict(self._raw.values())

    @property
    def parameters(self) -> List[Dict[str, Any]]:
        """Each parameter with its symbol (``label``), name, clause and value."""
        return list(self.json["details"])

    @property
    def expanded_uncertainty(self) -> Dict[str, float]:
        """U (k = 2) of each parameter, for the axis kind's usual instrument or the one
        asked (ISO/TR 230-9; the command line's budget without a campaign's conditions)."""
        return dict(self._raw.expanded())

    def targets(self) -> "pandas.DataFrame":
        """The per-target table in the layout of ISO 230-2 Table 2: for each target i its
        position, and for each direction the mean x̄ᵢ, sᵢ, x̄ᵢ ± 2sᵢ and Rᵢ, then Bᵢ and Rᵢ."""
        import pandas

        rows = []
        for t in self.json["targets"]:
            row: Dict[str, Any] = {"i": t["i"], "position": t["position"]}
            for d in ("up", "down"):
                side = t[d]
                for key in ("mean", "s", "upper", "lower", "repeatability"):
                    row[f"{key}_{d}"] = side.get(key)
            row["reversal"] = t["reversal"]
            row["repeatability"] = t["repeatability"]
            rows.append(row)
        return pandas.DataFrame(rows).set_index("i")

    def figures(self, family: str = "sans-serif") -> Dict[str, str]:
        """ISO 230-2 Fig. 2a (``bidirectional``) and Fig. 2b (``unidirectional``) as SVG,
        the scenes the axis report and ``summary.html`` draw (in a notebook:
        ``IPython.display.SVG(e.figures()["bidirectional"])``)."""
        both, each = self._raw.figures(family)
        return {"bidirectional": both, "unidirectional": each}

    def plot(self, ax: Any = None) -> Any:
        """ISO 230-2 Fig. 2a/2b: each direction's mean deviation and its ±2s band at each
        target; returns the matplotlib axes."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        targets = self.json["targets"]
        x = [t["position"] for t in targets]
        for d, mark in (("up", "^-"), ("down", "v-")):
            mean = [t[d]["mean"] for t in targets]
            ax.plot(x, mean, mark, label=f"x̄ {'↑' if d == 'up' else '↓'}")
            upper = [t[d].get("upper") for t in targets]
            lower = [t[d].get("lower") for t in targets]
            if all(v is not None for v in upper + lower):
                ax.fill_between(x, lower, upper, alpha=0.15)
        ax.set_xlabel(f"target ({self.json['position_unit']})")
        ax.set_ylabel(f"deviation ({self.unit})")
        ax.set_title(str(self.json["title"]))
        ax.legend()
        return ax

    def __repr__(self) -> str:
        shown = ", ".join(f"{k}={v:.2f}" for k, v in self.values.items())
        return f"Evaluation({self.standard}: {shown})"


def evaluate(
    m: Measurement,
    standard: str = "iso230-2",
    s_from_ranges: bool = False,
    instrument: Optional[str] = None,
) -> Evaluation:
    """The parameters of ``standard`` (``iso230-2``, ``gbt17421.2``, ``gost27843``,
    ``vdi3441``, ``nmtba``) and U per parameter; GOST 27843 with S from the ranges
    (formula 6) when ``s_from_ranges``."""
    return Evaluation(_axcheck.evaluate(m._raw, standard, s_from_ranges, instrument))


@overload
def evaluate_files(
    paths: Iterable[Union[str, "os.PathLike[str]"]],
    standard: str = ...,
    s_from_ranges: bool = ...,
    instrument: Optional[str] = ...,
    jobs: Optional[int] = ...,
    errors: Literal["raise"] = ...,
) -> List[Evaluation]: ...
@overload
def evaluate_files(
    paths: Iterable[Union[str, "os.PathLike[str]"]],
    standard: str = ...,
    s_from_ranges: bool = ...,
    instrument: Optional[str] = ...,
    jobs: Optional[int] = ...,
    *,
    errors: Literal["return"],
) -> List[Union[Evaluation, ReadError]]: ...
def evaluate_files(
    paths: Iterable[Union[str, "os.PathLike[str]"]],
    standard: str = "iso230-2",
    s_from_ranges: bool = False,
    instrument: Optional[str] = None,
    jobs: Optional[int] = None,
    errors: str = "raise",
) -> Union[List[Evaluation], List[Union[Evaluation, ReadError]]]:
    """Each file read and evaluated as ``evaluate(read(path), ...)`` would, in one call:
    the files are spread over ``jobs`` threads (default: one per core) with the GIL
    released once, which a Python loop or thread pool over small files cannot do.

    Returns one :class:`Evaluation` per path, in the paths' order. A file that cannot be
    read raises its :class:`ReadError` (the first in the paths' order, after all were
    tried) when ``errors="raise"``; with ``errors="return"`` the error takes the file's
    place in the list."""
    if errors not in ("raise", "return"):
        raise ValueError(f"errors: expected 'raise' or 'return', not {errors!r}")
    names = [os.fspath(p) for p in paths]
    done = _axcheck.evaluate_files(names, standard, s_from_ranges, instrument, jobs)
    if errors == "raise":
        for item in done:
            if isinstance(item, ReadError):
                raise item
    return [item if isinstance(item, ReadError) else Evaluation(item) for item in done]


def diagnose(m: Measurement, standard: str = "iso230-2", pitch: Optional[float] = None) -> Dict[str, Any]:
    """What the standard's model of the axis gets wrong, and why (``diagnose --json``):
    the effects found (Hemingray et al. 1971), the model checks and the parameters
    without each effect. ``pitch``: the lead screw's pitch (mm), for periodic error."""
    value: Dict[str, Any] = json.loads(_axcheck.diagnose(m._raw, standard, pitch))
    return value


#: An optics' accuracy for U: (percent of the value, fixed part, part per metre of travel[,
#: part per square metre]) in the result's unit (µm or arcsec), or a preset's name
#: (``"hp5528a_squareness_short"``, ``"hp5528a_squareness_long"``; see the README).
Optics = Union[Tuple[float, float, float], Tuple[float, float, float, float], str]


def straightness(
    m: Measurement,
    line: str = "least_squares",
    local: Optional[float] = None,
    direction: Optional[str] = None,
    optics: Optional[Optics] = None,
) -> Dict[str, Any]:
    """The straightness of a linear axis (ISO 230-1; ``eval --test straightness --json``):
    the range of the deviations (µm) about the reference straight line, fitted by least
    squares or through the end points (``line="end_point"``), both directions together and
    each, the slope removed (µm/m), the reversal and, with ``local`` (mm), the worst stretch
    of that length. ``direction``: the axis the deviation is along (``Y`` for EYX).
    ``uncertainty`` holds U (k = 2) and its budget; without ``optics`` it holds the
    scatter only, and says so."""
    value: Dict[str, Any] = json.loads(_axcheck.straightness(m._raw, line, local, direction, optics))
    return value


def angular(m: Measurement, direction: Optional[str] = None, optics: Optional[Optics] = None) -> Dict[str, Any]:
    """The angular deviation of a linear axis (pitch, yaw, roll; ``eval --test angular
    --json``) of a test read with ``read(path, angular=True)``: the range of the mean
    angular readings (arcsec), each direction's, the reversal and the repeatability.
    ``direction``: the axis of rotation (``B`` for EBX)."""
    value: Dict[str, Any] = json.loads(_axcheck.angular(m._raw, direction, optics))
    return value


def squareness(
    first: Measurement,
    second: Measurement,
    line: str = "least_squares",
    square_error: float = 0.0,
    convention: str = "over_90",
    square_u: Optional[float] = None,
    optics: Optional[Optics] = None,
) -> Dict[str, Any]:
    """The squareness of two linear axes from their straightness tests with an optical
    square (ISO 230-1 3.6.7; ``eval --test squareness --json``): θ₂ − θ₁ + the square's
    error in arcsec (HP 5528A User's Guide §21), positive when the included angle is larger
    than 90° (``convention="under_90"`` states it the other way); U from each line's
    inclination, the square's calibration (``square_u``, a standard uncertainty in arcsec)
    and the optics (``"hp5528a_short"``: the HP 5528A's short-range squareness optics)."""
    value: Dict[str, Any] = json.loads(
        _axcheck.squareness(first._raw, second._raw, line, square_error, convention, square_u, optics)
    )
    return value


def compensate(
    m: Measurement,
    controller: str,
    active: Optional[str] = None,
    active_backlash: Optional[float] = None,
    interval: Optional[float] = None,
    reference: Optional[float] = None,
    pitch: Optional[float] = None,
    axis: Optional[str] = None,
    standard: str = "iso230-2",
) -> Dict[str, Any]:
    """The controller's compensation table for the measurement (``compensate --json``) and
    the file's text (``file_text``): on the table active during the test (``active``, a
    file, or ``"none"``) and its backlash, else the state is unknown and a warning says so."""
    value: Dict[str, Any] = json.loads(
        _axcheck.compensate(
            m._raw, controller, active, active_backlash, interval, reference, pitch, axis, standard
        )
    )
    return value


def verify(
    before: Measurement,
    after: Measurement,
    controller: str,
    table: str,
    active: Optional[str] = None,
    active_backlash: Optional[float] = None,
    backlash: Optional[float] = None,
    axis: Optional[str] = None,
    standard: str = "iso230-2",
    others: Optional[Dict[str, str]] = None,
) -> Dict[str, Any]:
    """Whether the table loaded between ``before`` and ``after`` did what it predicted
    (``verify --json``), and if not what went wrong; ``others`` maps another axis of the
    machine to its table file, to tell a table loaded on the wrong axis (``--other``)."""
    pairs = sorted((others or {}).items())
    value: Dict[str, Any] = json.loads(
        _axcheck.verify(
            before._raw, after._raw, controller, table, active, active_backlash, backlash, axis, standard, pairs
        )
    )
    return value


def parameters(standard: str = "iso230-2") -> List[Dict[str, str]]:
    """The parameters ``standard`` defines, in its order, each with its ``key`` (as in
    :attr:`Evaluation.values`), ``symbol``, ``name`` and the ``clause`` that defines it:

    >>> [p["clause"] for p in axcheck.parameters() if p["key"] == "A"]
    ['ISO 230-2 2.23']
    """
    return [
        {"key": k, "symbol": s, "name": n, "clause": c}
        for k, s, n, c in _axcheck.parameters(standard)
    ]


def controllers() -> List[str]:
    """The controllers whose table formats :func:`compensate` writes."""
    return list(_axcheck.controller_names())


#: A summary-table cell: text, integer, number, boolean or None (empty).
Cell = Union[str, int, float, bool, None]


class Checked:
    """A campaign as ``axcheck check`` judges it: one row per axis test in the columns of
    ``summary.csv`` (a stable interface), and the gate."""

    def __init__(self, raw: Any) -> None:
        self._raw = raw
        #: The columns of ``summary.csv``, in order.
        self.columns: List[str] = list(raw.columns())
        #: One row per axis test, in the columns' order.
        self.rows: List[List[Cell]] = [list(r) for r in raw.rows()]

    @property
    def passed(self) -> bool:
        """Whether every axis passes (``check``'s exit status 0)."""
        return bool(self._raw.passed)

    @property
    def counts(self) -> str:
        """The verdicts counted, as the command line's summary line says them."""
        return str(self._raw.counts)

    def frame(self) -> "pandas.DataFrame":
        """The rows as a DataFrame with the columns of ``summary.csv``."""
        import pandas

        return pandas.DataFrame(self.rows, columns=self.columns)

    def __repr__(self) -> str:
        return f"Checked({len(self.rows)} tests: {self.counts})"


def check(campaign: str, diagnose: bool = False) -> Checked:
    """``axcheck check``: every axis of the campaign read, evaluated, checked against its
    test plan's rules and judged against its limits, in parallel; nothing written. With
    ``diagnose``, every test is diagnosed too (the ``diagnosis`` column). A campaign that
    cannot be read raises ``ValueError`` naming file, line and key."""
    return Checked(_axcheck.check(str(campaign), diagnose))


class Run:
    """A campaign run by the ``axcheck`` command line: its output folder and exit status."""

    def __init__(self, out: str, exit_status: int, console: str) -> None:
        #: The output folder.
        self.out = out
        #: 0: every axis passes; 1: some axis does not (see the command line's README).
        self.exit_status = exit_status
        #: What the command printed.
        self.console = console

    @property
    def results(self) -> Dict[str, Any]:
        """``results.json``: every axis test with everything the stages found."""
        import os

        with open(os.path.join(self.out, "results.json"), encoding="utf-8") as f:
            value: Dict[str, Any] = json.load(f)
        return value

    def frame(self) -> "pandas.DataFrame":
        """``summary.csv`` as a DataFrame (the columns of :meth:`Checked.frame`, the
        parameters' units in their headers)."""
        import os

        import pandas

        return pandas.read_csv(os.path.join(self.out, "summary.csv"), keep_default_na=False)


def run(campaign: str, out: str = "out", *args: str) -> Run:
    """``axcheck run CAMPAIGN --out OUT [ARGS…]``: every output written (PDF reports,
    summary.html, the workbook, tables, compensation tables). The PDF and Parquet writers
    are the command line's, not in this package: ``run`` calls the ``axcheck`` executable
    (``AXCHECK_BIN``, else the one on ``PATH``; ``cargo install --path .`` installs it).
    Exit status 2 (the campaign or an output could not be written) raises ``RuntimeError``
    with the command's message."""
    import os
    import shutil
    import subprocess

    exe = os.environ.get("AXCHECK_BIN") or shutil.which("axcheck")
    if not exe:
        raise FileNotFoundError(
            "axcheck.run needs the axcheck command line: set AXCHECK_BIN or put it on PATH "
            "(cargo install --path . in the repository)"
        )
    done = subprocess.run(
        [exe, "run", str(campaign), "--out", str(out), *args], capture_output=True, text=True
    )
    if done.returncode not in (0, 1):
        raise RuntimeError(done.stderr.strip() or f"axcheck run exited with {done.returncode}")
    return Run(str(out), done.returncode, done.stdout)


def plan(
    kind: str,
    travel: Union[float, Tuple[float, float]],
    standard: str = "iso230-2",
    pitch: Optional[float] = None,
    scale_pitch: Optional[float] = None,
    runs: Optional[int] = None,
    overrun: float = 5.0,
    dwell_s: float = 4.0,
    feed: float = 1000.0,
    seed: int = 1,
    targets: Optional[List[float]] = None,
) -> Dict[str, Any]:
    """A test plan before the laser is set up (``axcheck plan``): the standard's targets on
    an axis of ``travel`` (a length, or ``(start, end)``; mm or deg), spaced as ISO 230-2
    4.2 asks with offsets that sample the lead screw's ``pitch`` and the scale's, or the
    ``targets`` given; checked by the test-plan rules (``findings``, empty for a plan
    axcheck made). ``yaml`` is the plan file ``axcheck plan -o`` writes."""
    span = [float(travel)] if isinstance(travel, (int, float)) else [float(t) for t in travel]
    value: Dict[str, Any] = json.loads(
        _axcheck.plan(
            kind, span, standard, pitch, scale_pitch, runs, overrun, dwell_s, feed, seed, targets
        )
    )
    return value
