"""The worked example of ISO 230-2 (Table 2) evaluated from Python: the parameters the
command line's `axcheck eval --json tests/data/iso230-2_table2.csv` prints, and U."""

import sys

import axcheck

path = sys.argv[1] if len(sys.argv) > 1 else "tests/data/iso230-2_table2.csv"
m: axcheck.Measurement = axcheck.read(path)
e: axcheck.Evaluation = axcheck.evaluate(m)
u = e.expanded_uncertainty
unit = {"um": "µm", "arcsec": "″"}[e.unit]
print(f"{m.file}: {m.kind} axis, read as {m.layout}")
for key in ("A", "E", "M", "R", "B"):
    print(f"{key} = {e.values[key]:5.2f} {unit}   U = {u[key]:5.2f} {unit} (k = 2)")
