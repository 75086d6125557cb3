"""The Python package in a notebook's loop against the pandas + numpy peer
(bench/peer_iso230_2.py): every file of a fleet read and evaluated one after the other in
one Python process, in pairs (the peer, then axcheck), and axcheck again in a thread pool
(the evaluation releases the GIL) and in one call (`axcheck.evaluate_files`, Rust's pool on
1 and N threads). Prints one Markdown row per measurement.

    axcheck simulate --fleet 10000 --seed 1 --out /tmp/fleet
    python3 bench/python_loop.py /tmp/fleet/data [--pairs 3] [--threads 2]

Needs the axcheck wheel (python/test.sh builds it), pandas and numpy.
"""

import glob
import os
import statistics
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from typing import Callable, List

import axcheck

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from peer_iso230_2 import LIMITS_UM  # noqa: E402
from peer_iso230_2 import evaluate as peer_evaluate  # noqa: E402


def ours(path: str) -> bool:
    """The peer's question (is any of A, E, R, B over its limit?) asked of axcheck; A and
    R are not defined for one run (no s), where the peer's are NaN, never over."""
    values = axcheck.evaluate(axcheck.read(path)).values
    return any(values.get(k, float("nan")) > v for k, v in LIMITS_UM.items())


def over(e: "axcheck.Evaluation") -> bool:
    """``ours`` for an evaluation made by ``evaluate_files``."""
    values = e.values
    return any(values.get(k, float("nan")) > v for k, v in LIMITS_UM.items())


def timed(work: Callable[[], int]) -> float:
    start = time.perf_counter()
    work()
    return time.perf_counter() - start


def main() -> None:
    data = sys.argv[1]
    pairs = int(sys.argv[sys.argv.index("--pairs") + 1]) if "--pairs" in sys.argv else 3
    threads = int(sys.argv[sys.argv.index("--threads") + 1]) if "--threads" in sys.argv else 2
    files: List[str] = sorted(glob.glob(os.path.join(data, "**", "*.csv"), recursive=True))
    # Both give the same answer before either is timed.
    assert sum(map(peer_evaluate, files[:200])) == sum(map(ours, files[:200]))
    peer_times, our_times, ratios = [], [], []
    for _ in range(pairs):
        p = timed(lambda: sum(map(peer_evaluate, files)))
        o = timed(lambda: sum(map(ours, files)))
        peer_times.append(p)
        our_times.append(o)
        ratios.append(p / o)
    with ThreadPoolExecutor(threads) as pool:
        pooled = timed(lambda: sum(pool.map(ours, files, chunksize=64)))
    # One call for all the files: the same answers, on 1 and N of Rust's threads.
    assert sum(map(ours, files)) == sum(map(over, axcheck.evaluate_files(files)))
    batch_1 = timed(lambda: sum(map(over, axcheck.evaluate_files(files, jobs=1))))
    batch_n = timed(lambda: sum(map(over, axcheck.evaluate_files(files, jobs=threads))))
    # The GIL released: the diagnosis (milliseconds a file) of 200 files on 1 and N threads.
    some = [axcheck.read(f) for f in files[:200]]
    alone = timed(lambda: len([axcheck.diagnose(m) for m in some]))
    with ThreadPoolExecutor(threads) as pool:
        shared = timed(lambda: len(list(pool.map(axcheck.diagnose, some))))
    print(
        f"| files | peer loop (s) | axcheck loop (s) | peer / axcheck, pair by pair | axcheck, {threads} threads (s) "
        f"| evaluate_files, 1 / {threads} threads (s) | diagnose 200 files, 1 / {threads} threads (s) |"
    )
    print("|---|---|---|---|---|---|---|")
    shown = ", ".join(f"{r:.0f}×" for r in ratios)
    print(
        f"| {len(files)} | {statistics.median(peer_times):.2f} | {statistics.median(our_times):.2f} "
        f"| {shown} | {pooled:.2f} | {batch_1:.2f} / {batch_n:.2f} | {alone:.2f} / {shared:.2f} |"
    )


if __name__ == "__main__":
    main()
