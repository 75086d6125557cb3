"""The compiled core (Rust, PyO3). Use the functions of :mod:`axcheck` instead."""

from typing import List, Optional, Tuple

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
    def json(self) -> str: ...

def read(path: str, sheet: Optional[str] = None, reference: Optional[str] = None) -> Measurement: ...
def read_text(text: str, name: str) -> Measurement: ...
def evaluate(
    m: Measurement,
    standard_key: str = "iso230-2",
    s_from_ranges: bool = False,
    instrument: Optional[str] = None,
) -> Evaluated: ...
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
) -> str: ...
def controller_names() -> List[str]: ...
