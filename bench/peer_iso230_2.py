"""The peer of `axcheck check` in bench/fleet.sh: the ISO 230-2 evaluation of a fleet's
measurement files as a plant engineer would script it with pandas and numpy.

For every long CSV under DATA (target_mm|target_deg, direction, run, deviation_um|
deviation_arcsec, …): the mean and the standard deviation (n − 1) of the deviations at
each target and direction (ISO 230-2 2.10, 2.15), then B (2.13), R (2.18), E (2.20),
M (2.21) and A (2.23); the axes whose value exceeds a limit are counted. Writes nothing
but a one-line count, as `check` writes only its verdicts.

    python3 bench/peer_iso230_2.py FLEET/data [--jobs N]
"""

import glob
import os
import sys
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pandas as pd

# The fleet's general spec for a linear axis up to 2000 mm, as a plant would type it.
LIMITS_UM = {"A": 30.0, "E": 25.0, "R": 10.0, "B": 8.0}


def evaluate(path):
    df = pd.read_csv(path, comment="#")
    value = "deviation_um" if "deviation_um" in df.columns else "deviation_arcsec"
    target = "target_mm" if "target_mm" in df.columns else "target_deg"
    g = df.groupby([target, "direction"])[value].agg(["mean", "std"]).unstack("direction")
    up_mean, down_mean = g[("mean", "up")], g[("mean", "down")]
    up_s, down_s = g[("std", "up")], g[("std", "down")]
    b_i = up_mean - down_mean
    r_i = np.maximum.reduce([2 * up_s + 2 * down_s + b_i.abs(), 4 * up_s, 4 * down_s])
    means = np.concatenate([up_mean.values, down_mean.values])
    x_i = (up_mean + down_mean) / 2
    hi = np.maximum(up_mean + 2 * up_s, down_mean + 2 * down_s).max()
    lo = np.minimum(up_mean - 2 * up_s, down_mean - 2 * down_s).min()
    result = {
        "A": hi - lo,
        "E": means.max() - means.min(),
        "M": x_i.max() - x_i.min(),
        "R": r_i.max(),
        "B": b_i.abs().max(),
    }
    return any(result[k] > v for k, v in LIMITS_UM.items())


def main():
    data = sys.argv[1]
    jobs = int(sys.argv[sys.argv.index("--jobs") + 1]) if "--jobs" in sys.argv else os.cpu_count()
    files = sorted(glob.glob(os.path.join(data, "**", "*.csv"), recursive=True))
    if jobs > 1:
        with ProcessPoolExecutor(jobs) as pool:
            failing = sum(pool.map(evaluate, files, chunksize=64))
    else:
        failing = sum(map(evaluate, files))
    print(f"{len(files)} axes, {failing} over a limit")


if __name__ == "__main__":
    main()
