"""The compiled core (Rust, PyO3). Use the functions of :mod:`axcheck` instead."""

from typing import List, Optional, Sequence, Tuple, Union

__version__: str

class Measurement:
    @property
    def file(self) -> str: ...
    @property
    def kind(self) -> str: ...
    def recognised_json(self) -> str: ...
    def readings(self) -> List[Tuple[float, str, int, float, Optional[float]]]: ...

class Evaluated:
    def values(self) -> List[Tuple[str, float]]: ...
    def expanded(self) -> List[Tuple[str, float]]: ...
    def figures(self, family: str = "sans-serif") -> Tuple[str, str]: ...
    def json(self) -> str: ...

class Checked:
    def columns(self) -> List[str]: ...
    def rows(self) -> List[List[Union[str, int, float, bool, None]]]: ...
    @property
    def passed(self) -> bool: ...
    @property
    def counts(self) -> str: ...

def read(
    path: str, sheet: Optional[str] = None, reference: Optional[str] = None, angular: bool = False
) -> Measurement: ...
def straightness(
    m: Measurement,
    line: str = "least_squares",
    local: Optional[float] = None,
    direction: Optional[str] = None,
    optics: Union[Tuple[float, float, float], Tuple[float, float, float, float], str, None] = None,
) -> str: ...
def angular(
    m: Measurement, direction: Optional[str] = None, optics: Union[Tuple[float, float, float], Tuple[float, float, float, float], str, None] = None
) -> str: ...
def squareness(
    first: Measurement,
    second: Measurement,
    line: str = "least_squares",
    square_error: float = 0.0,
    convention: str = "over_90",
    square_u: Optional[float] = None,
    optics: Union[Tuple[float, float, float], Tuple[float, float, float, float], str, None] = None,
) -> str: ...
def read_text(text: str, name: str) -> Measurement: ...
def evaluate(
    m: Measurement,
    standard_key: str = "iso230-2",
    s_from_ranges: bool = False,
    instrument: Optional[str] = None,
) -> Evaluated: ...
def evaluate_files(
    paths: Sequence[str],
    standard_key: str = "iso230-2",
    s_from_ranges: bool = False,
    instrument: Optional[str] = None,
    jobs: Optional[int] = None,
) -> List[Union[Evaluated, ValueError]]: ...
def diagnose(m: Measurement, standard_key: str = "iso230-2", pitch: Optional[float] = None) -> str: ...
def compensate(
    m: Measurement,
    controller_name: str,
    active: Optional[str] = None,
    active_backlash: Optional[float] = None,
    interval: Optional[float] = None,
    reference: Optional[float] = None,
    pitch: Optional[float] = None,
    axis: Optional[str] = None,
    standard_key: str = "iso230-2",
) -> str: ...
def verify(
    before: Measurement,
    after: Measurement,
    controller_name: str,
    table: str,
    active: Optional[str] = None,
    active_backlash: Optional[float] = None,
    backlash: Optional[float] = None,
    axis: Optional[str] = None,
    standard_key: str = "iso230-2",
    others: List[Tuple[str, str]] = ...,
) -> str: ...
def controller_names() -> List[str]: ...
def parameters(standard_key: str = "iso230-2") -> List[Tuple[str, str, str, str]]: ...
def check(campaign: str, diagnose: bool = False) -> Checked: ...
def plan(
    kind: str,
    travel: List[float],
    standard_key: str = "iso230-2",
    pitch: Optional[float] = None,
    scale_pitch: Optional[float] = None,
    runs: Optional[int] = None,
    overrun: float = 5.0,
    dwell_s: float = 4.0,
    feed: float = 1000.0,
    seed: int = 1,
    targets: Optional[List[float]] = None,
    continuous: bool = False,
) -> str: ...
