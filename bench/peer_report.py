"""The peer of `axcheck run --no-diagnose` (its per-axis PDF reports) for issue 48: the
ISO 230-2 report of every measurement file of a fleet, as a plant engineer would script it
with pandas, numpy and matplotlib's PDF backend.

For every long CSV under DATA (target_mm|target_deg, direction, run, deviation_um|
deviation_arcsec, …) a worker of a multiprocessing pool reads the file with pandas, computes
the per-target statistics and the parameters with numpy, and writes OUT/MACHINE/AXIS.pdf
with matplotlib (PdfPages, one figure per A4 page, no raster backend):

  page 1  header (machine, model, type, axis and kind, campaign, test date, measurement
          file and its SHA-256, measurement travel, spec band, n and m, verdict); the
          parameters table (A, A↑, A↓, E, E↑, E↓, M, R, R↑, R↓, B, B̄: symbol, name, value
          in µm or arcsec, limit, status; A and R are "n/a" when n = 1, ISO 230-2 5.2);
          the per-target table (i, Pi, x̄i↑, x̄i↓, Si↑, Si↓, Bi, Ri, x̄i).
  page 2  the ISO 230-2 Fig. 2a style chart (mean positional deviation per target for each
          direction, x̄ ± 2S bands, the readings as dots, the bidirectional mean, A, E, M
          noted) and the Fig. 2b style charts (the same per direction, A↑/E↑, A↓/E↓).

The statistics are those of bench/peer_iso230_2.py (mean and S with n − 1 per target and
direction, ISO 230-2 2.10 to 2.23). Its `evaluate` returns only a verdict, so its lines are
repeated here and extended to the unidirectional parameters and the per-target table.

Header fields come from the campaign YAML (DATA/../campaign.yaml, or --campaign): machine
id, model, type, axis name and kind, campaign name and date. Limits come from the spec the
campaign (or the axis) names, read from specs/NAME.yaml next to the campaign or in this
repository (specs/general.yaml for `axcheck simulate --fleet`); the band is chosen by the
measurement travel, and the verdict is the simple decision rule (value ≤ limit), which is
the rule `axcheck run` applies to the simulated fleet. Not in the peer's report (axcheck's
has them): the uncertainty budget and U per parameter, the ISO 14253-1 decision-zone chart,
the clause 7.1 test-conditions table, the test-plan findings and the raw readings table.
Without a campaign, machine and axis are taken from the file path and no limits are shown.

    python3 bench/peer_report.py DATA_DIR OUT_DIR [--jobs N] [--campaign FILE]

bench/fleet.sh would call it in turn with `axcheck run` on the same fleet, e.g.

    measure 1 "$BIN" run "$WORK/f$n/campaign.yaml" --no-diagnose --no-html --out "$WORK/out" --jobs "$CORES"
    measure 1 python3 bench/peer_report.py "$WORK/f$n/data" "$WORK/peer-out" --jobs "$CORES"

(with `python3 -m pip install pandas numpy matplotlib pyyaml` next to the existing pip line).
Written and measured with Python 3.11.7, pandas 3.1.1, numpy 2.4.6, matplotlib 3.11.2,
PyYAML 6.0.4 (with libyaml).
"""

import argparse
import glob
import hashlib
import os
import sys
import time
from multiprocessing import Pool

import matplotlib

matplotlib.use("pdf")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import yaml  # noqa: E402
from matplotlib.backends.backend_pdf import PdfPages  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
A4 = (8.27, 11.69)
UP_COLOUR, DOWN_COLOUR, MEAN_COLOUR = "#1f3a93", "#b03a2e", "#333333"

# Parameters in the report's order: key (as specs/*.yaml spell it), symbol, name.
PARAMETERS = [
    ("A", "A", "bidirectional accuracy of positioning"),
    ("A_up", "A↑", "unidirectional accuracy of positioning ↑"),
    ("A_down", "A↓", "unidirectional accuracy of positioning ↓"),
    ("E", "E", "bidirectional systematic positional deviation"),
    ("E_up", "E↑", "unidirectional systematic positional deviation ↑"),
    ("E_down", "E↓", "unidirectional systematic positional deviation ↓"),
    ("M", "M", "range of the mean bidirectional positional deviation"),
    ("R", "R", "bidirectional repeatability of positioning"),
    ("R_up", "R↑", "unidirectional repeatability of positioning ↑"),
    ("R_down", "R↓", "unidirectional repeatability of positioning ↓"),
    ("B", "B", "reversal value of the axis"),
    ("B_mean", "B̄", "mean reversal value of the axis"),
]


# ---------------------------------------------------------------------------------------
# Reading and evaluation (ISO 230-2), as bench/peer_iso230_2.py


def read_axis(path):
    df = pd.read_csv(path, comment="#")
    rotary = "target_deg" in df.columns
    target = "target_deg" if rotary else "target_mm"
    value = "deviation_arcsec" if rotary else "deviation_um"
    return df.rename(columns={target: "P", value: "x"}), rotary


def evaluate(df):
    """Per-target table (index: target position) and the parameters of ISO 230-2."""
    g = df.groupby(["P", "direction"])["x"].agg(["mean", "std", "count"]).unstack("direction")
    t = pd.DataFrame(
        {
            "mean_up": g[("mean", "up")],
            "mean_down": g[("mean", "down")],
            "s_up": g[("std", "up")],
            "s_down": g[("std", "down")],
        }
    )
    n = int(g[("count", "up")].min())
    t["B"] = t.mean_up - t.mean_down  # 2.12
    t["R_up"] = 4 * t.s_up  # 2.16
    t["R_down"] = 4 * t.s_down
    t["R"] = np.maximum.reduce([2 * t.s_up + 2 * t.s_down + t.B.abs(), t.R_up, t.R_down])  # 2.17
    t["mean"] = (t.mean_up + t.mean_down) / 2  # 2.11
    up_hi, up_lo = t.mean_up + 2 * t.s_up, t.mean_up - 2 * t.s_up
    down_hi, down_lo = t.mean_down + 2 * t.s_down, t.mean_down - 2 * t.s_down
    means = np.concatenate([t.mean_up.values, t.mean_down.values])
    p = {
        "A": np.maximum(up_hi, down_hi).max() - np.minimum(up_lo, down_lo).min(),  # 2.23
        "A_up": up_hi.max() - up_lo.min(),  # 2.22
        "A_down": down_hi.max() - down_lo.min(),
        "E": means.max() - means.min(),  # 2.20
        "E_up": t.mean_up.max() - t.mean_up.min(),  # 2.19
        "E_down": t.mean_down.max() - t.mean_down.min(),
        "M": t["mean"].max() - t["mean"].min(),  # 2.21
        "R": t.R.max(),  # 2.18
        "R_up": t.R_up.max(),
        "R_down": t.R_down.max(),
        "B": t.B.abs().max(),  # 2.13
        "B_mean": t.B.mean(),  # 2.14
    }
    if n < 2:  # S, R and A are not applicable with one approach (5.2)
        for k in ("A", "A_up", "A_down", "R", "R_up", "R_down"):
            p[k] = np.nan
    return t, p, n


# ---------------------------------------------------------------------------------------
# Campaign and spec


def load_campaign(path):
    """{absolute data path: header fields}, the campaign's name and date, its specs."""
    with open(path, encoding="utf-8") as f:
        doc = yaml.load(f, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    base = os.path.dirname(os.path.abspath(path))
    camp = doc.get("campaign", {})
    default_spec = camp.get("spec")
    axes = {}
    spec_names = {default_spec} if default_spec else set()
    for m in doc.get("machines", []):
        for a in m.get("axes", []):
            if "data" not in a:
                continue
            spec = a.get("spec", default_spec)
            spec_names.add(spec)
            axes[os.path.normpath(os.path.join(base, a["data"]))] = {
                "machine": str(m.get("id", "")),
                "model": str(m.get("model", "–")),
                "type": str(m.get("type", "–")),
                "axis": str(a.get("name", "")),
                "kind": a.get("kind"),
                "file": a["data"],
                "spec": spec,
            }
    specs = {}
    for name in filter(None, spec_names):
        for candidate in (os.path.join(base, "specs", f"{name}.yaml"), os.path.join(base, name),
                          os.path.join(HERE, "..", "specs", f"{name}.yaml")):
            if os.path.isfile(candidate):
                with open(candidate, encoding="utf-8") as f:
                    specs[name] = yaml.safe_load(f)
                break
    return axes, str(camp.get("name", "")), str(camp.get("date", "")), specs


def spec_band(spec, rotary, travel):
    """The spec's band for this axis: (tolerances, description) or ({}, None)."""
    if not spec:
        return {}, None
    unit = "deg" if rotary else "mm"
    for band in spec.get("rotary" if rotary else "linear", []):
        up_to = band.get(f"up_to_{unit}")
        if up_to is None or travel <= up_to + 1e-9:
            where = f"{'rotary' if rotary else 'linear'} ≤ {up_to:g} {unit}" if up_to is not None \
                else f"{'rotary' if rotary else 'linear'}, longer"
            label = f"{spec.get('name', '')} ({where})"
            if spec.get("example"):
                label += " — example limits, not from a standard"
            return band.get("tolerances", {}), label
    return {}, None


# ---------------------------------------------------------------------------------------
# Report


def fmt(v, digits=2):
    return "n/a" if v is None or not np.isfinite(v) else f"{v:.{digits}f}".replace("-", "−")


def table(ax, rows, columns, widths, fontsize, align=None, emphasis=None):
    """A ruled table as text on `ax`: each cell one `ax.text`, the rules two line
    collections (`ax.table`'s cell objects cost 45 % of a report's time; an engineer who
    minds the time draws the text). `emphasis(row, column)` marks a cell in red."""
    ax.axis("off")
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    count = len(rows) + 1
    h = 1.0 / count
    edges = np.concatenate([[0.0], np.cumsum(widths) / sum(widths)])
    ax.add_patch(Rectangle((0, 1 - h), 1, h, facecolor="#e8ecf4", edgecolor="none"))
    ax.hlines(1 - h * np.arange(count + 1), 0, 1, lw=0.3, color="#999999")
    ax.vlines(edges, 0, 1, lw=0.3, color="#999999")
    for r, row in enumerate([columns] + rows):
        y = 1 - (r + 0.5) * h
        for c, text in enumerate(row):
            ha = align[c] if align else "right"
            x = {"left": edges[c] + 0.006, "right": edges[c + 1] - 0.006,
                 "center": (edges[c] + edges[c + 1]) / 2}[ha]
            style = {"weight": "bold"} if r == 0 else {}
            if r > 0 and emphasis and emphasis(r - 1, c):
                style = {"weight": "bold", "color": "#c62828"}
            ax.text(x, y, text, ha=ha, va="center", fontsize=fontsize, **style)


def footer(fig, meta, campaign, page, pages):
    fig.text(0.07, 0.025, f"{meta['machine']} — axis {meta['axis']} · {campaign}", fontsize=7,
             color="#555555")
    fig.text(0.93, 0.025, f"Page {page} of {pages}", fontsize=7, color="#555555", ha="right")


def page_tables(meta, campaign, date, rotary, t, p, n, limits, band, sha, verdict):
    unit = "arcsec" if rotary else "µm"
    punit = "°" if rotary else " mm"
    fig = plt.figure(figsize=A4)
    fig.text(0.07, 0.955, "Positioning accuracy and repeatability test report (ISO 230-2)",
             fontsize=13, weight="bold")
    colour = {"PASS": "#1e7d32", "FAIL": "#c62828"}.get(verdict, "#555555")
    fig.text(0.93, 0.955, verdict, fontsize=13, weight="bold", color=colour, ha="right")
    fig.text(0.07, 0.93, f"{meta['machine']} — axis {meta['axis']}", fontsize=11)
    header = [
        ("Machine", meta["machine"], "Model", meta["model"]),
        ("Type", meta["type"], "Axis", f"{meta['axis']} ({'rotary' if rotary else 'linear'})"),
        ("Campaign", campaign or "–", "Test date", date or "–"),
        ("Measurement file", meta["file"], "File SHA-256", sha[:16] + "…"),
        ("Measurement travel", f"{fmt(t.index.min(), 3)}{punit} … {fmt(t.index.max(), 3)}{punit}",
         "Approaches", f"n = {n} at each of {len(t)} targets"),
    ]
    y = 0.90
    for k1, v1, k2, v2 in header:
        fig.text(0.07, y, k1, fontsize=8, color="#555555")
        fig.text(0.22, y, v1, fontsize=8)
        fig.text(0.50, y, k2, fontsize=8, color="#555555")
        fig.text(0.63, y, v2, fontsize=8)
        y -= 0.018
    fig.text(0.07, y, "Standard", fontsize=8, color="#555555")
    fig.text(0.22, y, "ISO 230-2:1997", fontsize=8)
    fig.text(0.07, y - 0.018, "Acceptance spec", fontsize=8, color="#555555")
    fig.text(0.22, y - 0.018, band or "none in the campaign (values only)", fontsize=8)

    fig.text(0.07, 0.745, f"Results (values in {unit})", fontsize=10, weight="bold")
    rows = []
    for key, symbol, name in PARAMETERS:
        v, lim = p[key], limits.get(key)
        if not np.isfinite(v):
            status = "n/a"
        elif lim is None:
            status = "–"
        else:
            status = "pass" if v <= lim else "FAIL"
        rows.append([symbol, name, fmt(v), "–" if lim is None else fmt(float(lim)),
                     "–" if lim is None or not np.isfinite(v) else fmt(lim - v), status])
    ax = fig.add_axes([0.07, 0.505, 0.86, 0.23])
    table(ax, rows, ["Symbol", "Parameter", f"Value ({unit})", f"Limit ({unit})",
                     "Margin", "Status"], [0.07, 0.5, 0.12, 0.12, 0.1, 0.09], 7.5,
          align=["left", "left", "right", "right", "right", "center"],
          emphasis=lambda r, c: c == 5 and rows[r][5] == "FAIL")
    if n < 2:
        fig.text(0.07, 0.49, "Note: n = 1: S, R and A are not applicable (ISO 230-2 clause 5.2)",
                 fontsize=7, color="#555555")

    fig.text(0.07, 0.465, f"Per-target results ({unit}; positions in {punit.strip()})",
             fontsize=10, weight="bold")
    rows = [[str(i), fmt(pos, 3), fmt(r.mean_up), fmt(r.mean_down), fmt(r.s_up), fmt(r.s_down),
             fmt(r.B), fmt(r.R), fmt(r["mean"])]
            for i, (pos, r) in enumerate(t.iterrows(), start=1)]
    height = min(0.40, 0.0155 * (len(rows) + 1))
    ax = fig.add_axes([0.07, 0.455 - height, 0.86, height])
    table(ax, rows, ["i", "Pi", "x̄i↑", "x̄i↓", "Si↑", "Si↓", "Bi", "Ri", "x̄i"],
          [0.06, 0.14] + [0.1] * 7, 7 if len(rows) <= 28 else 6)
    return fig


def page_charts(meta, rotary, df, t, p, n):
    unit = "arcsec" if rotary else "µm"
    xlabel = "Target position Pi / " + ("°" if rotary else "mm")
    ylabel = f"Positional deviation / {unit}"
    fig = plt.figure(figsize=A4)
    pos = t.index.values
    up, down = df[df.direction == "up"], df[df.direction == "down"]

    def direction(ax, mean, s, readings, colour, style, marker, arrow):
        ax.plot(pos, mean, style, color=colour, marker=marker, ms=4, lw=1.3,
                label=f"mean x̄i{arrow}")
        if n > 1:
            ax.plot(pos, mean + 2 * s, style, color=colour, lw=0.7, alpha=0.8,
                    label=f"x̄ ± 2S {arrow}")
            ax.plot(pos, mean - 2 * s, style, color=colour, lw=0.7, alpha=0.8)
        ax.plot(readings.P, readings.x, marker, color=colour, ms=2.5, ls="none", alpha=0.6,
                mfc="none" if marker == "^" else colour, label=f"readings {arrow}")

    def finish(ax, values):
        ax.axhline(0, color="#888888", lw=0.6)
        ax.grid(True, lw=0.3, color="#dddddd")
        ax.set_ylabel(ylabel, fontsize=8)
        ax.tick_params(labelsize=7)
        ax.text(1.03, 0.5, "\n".join(f"{k} = {fmt(v)}" for k, v in values), fontsize=8,
                transform=ax.transAxes, va="center",
                bbox=dict(boxstyle="round", fc="white", ec="#999999", lw=0.5))

    fig.text(0.07, 0.955, "Bidirectional accuracy and repeatability (like ISO 230-2 Fig. 2a)",
             fontsize=10, weight="bold")
    ax = fig.add_axes([0.11, 0.60, 0.70, 0.305])
    direction(ax, t.mean_up, t.s_up, up, UP_COLOUR, "-", "o", "↑")
    direction(ax, t.mean_down, t.s_down, down, DOWN_COLOUR, "--", "^", "↓")
    ax.plot(pos, t["mean"], "-.", color=MEAN_COLOUR, lw=1, label="mean x̄i (bidirectional)")
    ax.set_xlabel(xlabel, fontsize=8)
    ax.legend(fontsize=6.5, ncol=4, loc="lower center", bbox_to_anchor=(0.5, 1.0), frameon=False)
    finish(ax, [("A", p["A"]), ("E", p["E"]), ("M", p["M"])])

    fig.text(0.07, 0.515, "Unidirectional accuracy and repeatability (like ISO 230-2 Fig. 2b)",
             fontsize=10, weight="bold")
    for bottom, (mean, s, readings, colour, style, marker, arrow, key) in zip((0.29, 0.07), [
        (t.mean_up, t.s_up, up, UP_COLOUR, "-", "o", "↑", "up"),
        (t.mean_down, t.s_down, down, DOWN_COLOUR, "--", "^", "↓", "down"),
    ]):
        ax = fig.add_axes([0.11, bottom, 0.70, 0.165])
        direction(ax, mean, s, readings, colour, style, marker, arrow)
        ax.set_title(f"Approach {arrow}", fontsize=8, loc="left", color=colour)
        ax.legend(fontsize=6.5, ncol=3, loc="lower right", bbox_to_anchor=(1.0, 1.0),
                  frameon=False)
        finish(ax, [(f"A{arrow}", p[f"A_{key}"]), (f"E{arrow}", p[f"E_{key}"])])
    ax.set_xlabel(xlabel, fontsize=8)
    return fig


def report(task):
    path, meta, out = task
    df, rotary = read_axis(path)
    t, p, n = evaluate(df)
    with open(path, "rb") as f:
        sha = hashlib.sha256(f.read()).hexdigest()
    limits, band = spec_band(SPECS.get(meta.get("spec")), rotary, t.index.max() - t.index.min())
    checked = [p[k] <= v for k, v in limits.items() if k in p and np.isfinite(p[k])]
    verdict = ("PASS" if all(checked) else "FAIL") if checked else "NO LIMITS"
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with PdfPages(out, metadata={"Title": f"{meta['machine']} {meta['axis']} ISO 230-2 report",
                                 "Creator": "bench/peer_report.py"}) as pdf:
        for page, make in enumerate([
            lambda: page_tables(meta, CAMPAIGN, DATE, rotary, t, p, n, limits, band, sha, verdict),
            lambda: page_charts(meta, rotary, df, t, p, n),
        ], start=1):
            fig = make()
            footer(fig, meta, CAMPAIGN, page, 2)
            pdf.savefig(fig)
            plt.close(fig)
    return 1


SPECS, CAMPAIGN, DATE = {}, "", ""


def init(specs, campaign, date):
    global SPECS, CAMPAIGN, DATE
    SPECS, CAMPAIGN, DATE = specs, campaign, date


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("data")
    ap.add_argument("out")
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    ap.add_argument("--campaign", help="campaign YAML (default: DATA/../campaign.yaml)")
    args = ap.parse_args()
    start = time.perf_counter()

    data = os.path.abspath(args.data)
    campaign_file = args.campaign or os.path.join(os.path.dirname(data), "campaign.yaml")
    axes, campaign, date, specs = ({}, "", "", {})
    if os.path.isfile(campaign_file):
        axes, campaign, date, specs = load_campaign(campaign_file)
    tasks = []
    for path in sorted(glob.glob(os.path.join(data, "**", "*.csv"), recursive=True)):
        rel = os.path.relpath(path, data)
        meta = axes.get(os.path.normpath(path)) or {
            "machine": os.path.dirname(rel) or "–", "model": "–", "type": "–",
            "axis": os.path.splitext(os.path.basename(rel))[0].upper(), "kind": None,
            "file": rel, "spec": None}
        out = os.path.join(args.out, meta["machine"], f"{meta['axis']}.pdf")
        tasks.append((path, meta, out))

    if args.jobs > 1:
        pool = Pool(args.jobs, initializer=init, initargs=(specs, campaign, date))
        written = sum(pool.imap_unordered(report, tasks, chunksize=4))
        pool.close()
        pool.join()
    else:
        init(specs, campaign, date)
        written = sum(map(report, tasks))
    print(f"{written} reports in {args.out} in {time.perf_counter() - start:.2f} s wall")


if __name__ == "__main__":
    sys.exit(main())
