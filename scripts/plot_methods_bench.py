#!/usr/bin/python3
"""Plots `eikon bench methods`'s TSV: error against ms, one panel per analytic case, one marker
shape per light-transport method and one colour per named setting, the Pareto front (no other
point is both faster and more accurate) drawn as a line. Points without an error (a method that
shows no focus, or keeps no energy account) are listed under their panel instead of plotted.

Also plots `eikon bench integrators`'s TSV, whose methods are the integrators and settings the
steps; COLUMN picks the error plotted (default "error": there the integration error, against the
exact trace through the sampled field; "path_error": against the continuous field).

Usage: /usr/bin/python3 scripts/plot_methods_bench.py TSV [PNG [COLUMN]]   (PNG defaults to TSV's
name)
Needs matplotlib (Debian: python3-matplotlib, installed by scripts/install-deps.sh).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = ["o", "s", "^", "D", "v", "P", "X"]  # per method, in the TSV's order
COLOURS = {"coarse": "tab:orange", "default": "tab:blue", "fine": "tab:green"}
# Settings without a colour of their own (integrators, steps) take these in order of appearance.
MORE_COLOURS = ["tab:red", "tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan",
                "tab:gray"]
# Per TSV kind: `eikon bench methods` (False) or `eikon bench integrators` (True).
TITLE = {False: "eikon bench methods: {column} against time per light-transport method and setting",
         True: "eikon bench integrators: {column} against the photon march's time per integrator "
               "and step"}
XLABEL = {False: "ms (CPU twin, method + the stages it needs)",
          True: "ms (CPU twin, the photon march)"}
# Errors of exactly zero (or below it) sit on this floor of the log axis.
FLOOR = 1e-12


def pareto(points):
    """The points no other point beats in both time and error, fastest first."""
    front = []
    for ms, err in sorted(points):
        if not front or err < front[-1][1]:
            front.append((ms, err))
    return front


def main():
    if len(sys.argv) not in (2, 3, 4):
        sys.exit("usage: plot_methods_bench.py TSV [PNG [COLUMN]]")
    tsv = sys.argv[1]
    png = sys.argv[2] if len(sys.argv) >= 3 else os.path.splitext(tsv)[0] + ".png"
    column = sys.argv[3] if len(sys.argv) == 4 else "error"
    with open(tsv, newline="") as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    if not rows:
        sys.exit(f"eikon: {tsv}: no rows")
    if column not in rows[0]:
        sys.exit(f"eikon: {tsv}: no column '{column}'")
    integrators = "path_error" in rows[0]  # `eikon bench integrators`'s TSV
    cases = list(dict.fromkeys(r["case"] for r in rows))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    for setting in dict.fromkeys(r["setting"] for r in rows):
        if setting not in COLOURS:
            COLOURS[setting] = MORE_COLOURS[len([c for c in COLOURS if c not in
                                                 ("coarse", "default", "fine")]) %
                                            len(MORE_COLOURS)]
    cols = min(3, len(cases))
    lines = math.ceil(len(cases) / cols)
    fig, axes = plt.subplots(lines, cols, figsize=(5.2 * cols, 4.4 * lines), squeeze=False)
    for ax, case in zip(axes.flat, cases):
        mine = [r for r in rows if r["case"] == case]
        unit = mine[0]["error_unit"]
        points, missing = [], []
        for r in mine:
            ms, err = float(r["ms"]), float(r[column])
            label = f"{r['method']} {r['setting']}"
            if math.isnan(err):
                missing.append(label)
                continue
            err = max(err, FLOOR)
            points.append((ms, err))
            marker = MARKERS[methods.index(r["method"]) % len(MARKERS)]
            ax.scatter(ms, err, marker=marker, color=COLOURS.get(r["setting"], "tab:gray"),
                       s=55, zorder=3, label=label)
        front = pareto(points)
        if front:
            ax.plot([p[0] for p in front], [p[1] for p in front], color="black", lw=1,
                    ls="--", zorder=2, label="Pareto front")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(f"{case} (n = {mine[0]['resolution']})")
        ax.set_xlabel(XLABEL[integrators])
        ax.set_ylabel(f"{column.replace('_', ' ')} ({unit})")
        ax.grid(True, which="both", alpha=0.3)
        if missing:
            ax.text(0.02, 0.02, "no value: " + ", ".join(missing), transform=ax.transAxes,
                    fontsize=7, va="bottom", wrap=True)
        ax.legend(fontsize=7, loc="best", framealpha=0.6)
    for ax in list(axes.flat)[len(cases):]:
        ax.axis("off")
    fig.suptitle(TITLE[integrators].format(column=column.replace("_", " ")))
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
