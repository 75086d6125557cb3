"""The tests name files relative to the repository, as the command line is given them."""

import os
from pathlib import Path

import pytest


@pytest.fixture(autouse=True)
def in_the_repository(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(Path(__file__).resolve().parents[2])
