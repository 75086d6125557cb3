"""Writes the geometry test files of this folder and prints what numpy computes from them
(np.polyfit for the least-squares lines, written apart from axcheck's Rust), the values
tests/it/geometry.rs asserts. Run: python3 tests/data/geometry/make.py > tests/data/geometry/EXPECTED.md

Known effects: X's straightness in Y is a bow of 8 µm (0 at the ends, 8 µm in the middle)
on a slope of 15 µm/m; X's pitch a 20″ trend over 1000 mm; Y's straightness in X has a
slope making the two axes 40 µm/m out of square. Noise: a fixed list of ±0.3 µm (±0.3″),
so the files are the same on every machine. The HP 5528A files are the worked example of
its User's Guide §21 (one run, the same readings both ways).
"""

import math
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ARCSEC = 648000 / math.pi
# A fixed noise sequence (a linear congruential generator, so that numpy's own random
# generator, which may change between versions, is not needed).
state = 12345


def noise(scale: float) -> float:
    global state
    state = (1103515245 * state + 12345) % 2**31
    return (state / 2**31 - 0.5) * 2 * scale


def write(name: str, unit: str, targets, f, runs: int, scale: float) -> None:
    rows = []
    for run in range(1, runs + 1):
        for direction, order in (("up", targets), ("down", targets[::-1])):
            for t in order:
                rows.append(f"{t:g},{direction},{run},{f(t) + noise(scale):.3f}")
    with open(os.path.join(HERE, name), "w") as out:
        out.write(f"target_mm,direction,run,{unit}\n" + "\n".join(rows) + "\n")


def table(name: str):
    data = np.genfromtxt(os.path.join(HERE, name), delimiter=",", names=True, dtype=None, encoding="utf-8")
    value = data.dtype.names[3]
    targets = np.unique(data["target_mm"])
    means = {d: np.array([data[value][(data["target_mm"] == t) & (data["direction"] == d)].mean() for t in targets]) for d in ("up", "down")}
    return targets, means


def straightness(name: str, local: float = 0.0):
    p, m = table(name)
    mean = (m["up"] + m["down"]) / 2
    slope, offset = np.polyfit(p, mean, 1)
    both = np.concatenate([m["up"] - (offset + slope * p), m["down"] - (offset + slope * p)])
    end = (mean[-1] - mean[0]) / (p[-1] - p[0])
    eline = mean[0] + end * (p - p[0])
    eboth = np.concatenate([m["up"] - eline, m["down"] - eline])
    print(f"| {name} | least squares | {np.ptp(both):.3f} µm | {slope * 1000:.3f} µm/m |")
    print(f"| {name} | end points | {np.ptp(eboth):.3f} µm | {end * 1000:.3f} µm/m |")
    return slope * 1000


def main() -> None:
    x = [float(t) for t in range(0, 1001, 100)]
    y = [float(t) for t in range(0, 601, 60)]
    write("x-straightness-y.csv", "deviation_um", x, lambda t: 32 * (t / 1000) * (1 - t / 1000) + 0.015 * t, 5, 0.3)
    write("x-pitch.csv", "deviation_arcsec", x, lambda t: 0.02 * t, 5, 0.3)
    write("y-straightness-x.csv", "deviation_um", y, lambda t: -0.025 * t, 5, 0.3)
    hp1 = [-0.3, 0.9, 1.5, 2.5, 2.9, 3.6, 4.2, 5.1, 5.9, 7.2]
    hp2 = [-0.5, -1.2, -2.5, -3.8, -4.0, -4.8, -5.9, -6.2, -7.4, -8.8]
    write("hp5528a-axis-1.csv", "deviation_um", [100.0 * k for k in range(10)], lambda t: hp1[round(t / 100)], 1, 0.0)
    write("hp5528a-axis-2.csv", "deviation_um", [50.0 * k for k in range(10)], lambda t: hp2[round(t / 50)], 1, 0.0)
    print("# What numpy computes from these files (make.py)\n")
    print("| file | reference line | bidirectional straightness | slope |")
    print("|---|---|---|---|")
    sx = straightness("x-straightness-y.csv")
    sy = straightness("y-straightness-x.csv")
    straightness("hp5528a-axis-1.csv")
    straightness("hp5528a-axis-2.csv")
    p, m = table("x-pitch.csv")
    both = np.concatenate([m["up"], m["down"]])
    print(f"\nx-pitch.csv: angular deviation (range of both directions' means) {np.ptp(both):.3f}″")
    th1, th2 = math.atan(sx * 1e-6) * ARCSEC, math.atan(sy * 1e-6) * ARCSEC
    sq = th2 - th1
    print(f"\nsquareness of x-straightness-y.csv (first) and y-straightness-x.csv (second), least squares, square 0″: "
          f"θ₁ {th1:.3f}″, θ₂ {th2:.3f}″, θ₂ − θ₁ = {sq:.3f}″ = {math.tan(sq / ARCSEC) * 1e6:.3f} µm/m")


if __name__ == "__main__":
    main()
