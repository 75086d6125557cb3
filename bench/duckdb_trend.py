"""The trend table in SQL (bench/trend.sql, run by DuckDB) against `axcheck trend --json`.

    python3 bench/duckdb_trend.py HISTORY [AXCHECK]

Runs the query on HISTORY (a history folder: year=YYYY/*.parquet), runs `axcheck trend
HISTORY --json`, and compares every series' slope per year. Needs `pip install duckdb`.
Prints the series counted by each, how many differ by more than 1e-9, and the query's time.
"""

import json
import pathlib
import subprocess
import sys
import time

import duckdb

history = pathlib.Path(sys.argv[1])
axcheck = sys.argv[2] if len(sys.argv) > 2 else "axcheck"
query = (pathlib.Path(__file__).parent / "trend.sql").read_text()
query = query.replace("history/**/*.parquet", str(history / "**" / "*.parquet"))

start = time.perf_counter()
rows = duckdb.sql(query).fetchall()
seconds = time.perf_counter() - start

out = subprocess.run([axcheck, "trend", str(history), "--json"], capture_output=True, text=True, check=True)
ours = {
    (a["machine"], a.get("serial") or "", a["axis"], a["parameter"]): a.get("slope_per_year")
    for a in json.loads(out.stdout)["axes"]
}
theirs = {tuple(r[:4]): r[4] for r in rows}
differ = [k for k, v in theirs.items() if ours.get(k) is None or abs(v - ours[k]) > 1e-9]
only_axcheck = [k for k, v in ours.items() if v is not None and k not in theirs]
print(f"axcheck: {len(ours)} series; SQL: {len(theirs)} series in {seconds:.2f} s")
print(f"differ by more than 1e-9: {len(differ)}; with a slope in axcheck only: {len(only_axcheck)}")
sys.exit(1 if differ or only_axcheck else 0)
