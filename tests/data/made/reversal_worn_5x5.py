"""Writes reversal_worn_5x5.csv: 5 targets x 5 runs whose reversal values Bi are those of
issue 43 (+1.24, +4.37, -7.28, -2.31, -13.43 um, a worn section, not a line) with the
standard errors of Bi it quotes (0.26-0.54 um, so s = se / sqrt(2/5) per target).

Each cell's five readings are its mean plus five normal draws centred and scaled to the
cell's s, so X-up - X-down is Bi and the sample standard deviation of each cell is s, to
the rounding of the readings (0.001 um).
Run: python3 reversal_worn_5x5.py > reversal_worn_5x5.csv
"""
import random

targets = [15.0, 25.0, 35.0, 45.0, 55.0]
b = [1.24, 4.37, -7.28, -2.31, -13.43]
se = [0.26, 0.54, 0.33, 0.47, 0.40]
mean = [2.10, -0.80, 1.50, 0.30, -1.20]
runs = 5
rng = random.Random(43)


def unit():
    """Five normal draws with mean 0 and sample standard deviation 1."""
    z = [rng.gauss(0, 1) for _ in range(runs)]
    m = sum(z) / runs
    sd = (sum((v - m) ** 2 for v in z) / (runs - 1)) ** 0.5
    return [(v - m) / sd for v in z]

rows = []
for i, p in enumerate(targets):
    s = se[i] / (2 / runs) ** 0.5
    for direction, sign in (("up", 1), ("down", -1)):
        dealt = unit()
        for run in range(runs):
            x = mean[i] + sign * b[i] / 2 + s * dealt[run]
            rows.append((run + 1, direction, p, x))
print("# made for issue 43: a reversal that varies from target to target (reversal_worn_5x5.py)")
print("target_mm,direction,run,deviation_um")
for run in range(1, runs + 1):
    for direction in ("up", "down"):
        order = targets if direction == "up" else targets[::-1]
        for p in order:
            x = next(r[3] for r in rows if r[0] == run and r[1] == direction and r[2] == p)
            print(f"{p},{direction},{run},{x:.3f}")
