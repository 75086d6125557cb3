#!/usr/bin/env python3
"""Compares the outputs of one campaign run on Linux and on Windows (.ci/windows).

Every file must be byte-identical, with two stated exceptions (README "Windows"):
- `.axcheck.lock` stays in a Windows output folder (emptied), and only there;
- in results.json, summary.html and summary.xlsx, a number written with all its 17
  digits may differ in its last binary digits (at most MAX_ULPS units in the last
  place): exp, ln, sin, cos and powf come from the platform's maths library (glibc on
  Linux, mingw-w64's on Windows), which round a few results the other way. Every rounded
  value (the CSV, Markdown, JUnit, Parquet, compensation tables and PDFs) is identical.
"""
import re
import struct
import sys
import zipfile
from io import BytesIO
from pathlib import Path

MAX_ULPS = 8
WINDOWS_ONLY = {".axcheck.lock"}
NUMBERS_MAY_DIFFER = {"results.json", "summary.html", "summary.xlsx"}
NUMBER = re.compile(rb"-?\d+\.\d+(?:[eE][-+]?\d+)?")


def ulps(a: float, b: float) -> int:
    """Units in the last place between two finite doubles of one sign."""
    ia = struct.unpack("<q", struct.pack("<d", a))[0]
    ib = struct.unpack("<q", struct.pack("<d", b))[0]
    return abs(ia - ib)


def compare_numbers(a: bytes, b: bytes, where: str) -> int:
    """The texts equal but for numbers within MAX_ULPS; returns how many numbers differ."""
    if NUMBER.sub(b"#", a) != NUMBER.sub(b"#", b):
        sys.exit(f"{where}: differs in more than its numbers")
    differ = 0
    for x, y in zip(NUMBER.findall(a), NUMBER.findall(b)):
        if x == y:
            continue
        d = ulps(float(x), float(y))
        if d > MAX_ULPS:
            sys.exit(f"{where}: {x.decode()} and {y.decode()} differ by {d} ulps")
        differ += 1
    return differ


def compare_file(name: str, a: bytes, b: bytes) -> int:
    if a == b:
        return 0
    if Path(name).name not in NUMBERS_MAY_DIFFER:
        sys.exit(f"{name}: differs between Linux and Windows")
    if not name.endswith(".xlsx"):
        return compare_numbers(a, b, name)
    za, zb = zipfile.ZipFile(BytesIO(a)), zipfile.ZipFile(BytesIO(b))
    if za.namelist() != zb.namelist():
        sys.exit(f"{name}: the workbooks hold different parts")
    return sum(
        compare_numbers(za.read(part), zb.read(part), f"{name}:{part}")
        for part in za.namelist()
    )


def main() -> None:
    linux, windows = Path(sys.argv[1]), Path(sys.argv[2])
    files = lambda root: {str(p.relative_to(root)) for p in root.rglob("*") if p.is_file()}
    on_linux, on_windows = files(linux), files(windows)
    if on_linux != on_windows - WINDOWS_ONLY:
        sys.exit(f"different files: {sorted(on_linux ^ (on_windows - WINDOWS_ONLY))}")
    identical = 0
    for name in sorted(on_linux):
        differ = compare_file(name, (linux / name).read_bytes(), (windows / name).read_bytes())
        if differ:
            print(f"  {name}: {differ} numbers differ in their last digits (≤ {MAX_ULPS} ulps)")
        else:
            identical += 1
    print(f"  {identical} of {len(on_linux)} files byte-identical")


main()
