#!/usr/bin/python3
"""Plots `eikon bench advection`'s TSV: L1 error against ms per step, one panel per problem, one
line per scheme + limiter through its resolutions.

Usage: /usr/bin/python3 scripts/plot_advection_bench.py TSV [PNG]   (PNG defaults to TSV's name)
Needs matplotlib (Debian: python3-matplotlib, installed by scripts/install-deps.sh).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FormatStrFormatter  # noqa: E402

STYLE = {  # (scheme, limiter) -> colour, marker
    ("semi-Lagrangian", "none"): ("tab:gray", "o"),
    ("MacCormack", "clamp"): ("tab:blue", "s"),
    ("MacCormack", "revert"): ("tab:cyan", "D"),
    ("BFECC", "clamp"): ("tab:red", "^"),
    ("BFECC", "revert"): ("tab:orange", "v"),
    ("MacCormack", "none"): ("tab:purple", "x"),
    ("BFECC", "none"): ("tab:brown", "+"),
}


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    tsv = sys.argv[1]
    png = sys.argv[2] if len(sys.argv) == 3 else os.path.splitext(tsv)[0] + ".png"
    with open(tsv, newline="") as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    if not rows:
        sys.exit(f"{tsv}: no rows")
    problems = list(dict.fromkeys(r["problem"] for r in rows))
    fig, axes = plt.subplots(1, len(problems), figsize=(5.5 * len(problems), 4.5), squeeze=False)
    for ax, problem in zip(axes[0], problems):
        mine = [r for r in rows if r["problem"] == problem]
        configs = list(dict.fromkeys((r["scheme"], r["limiter"]) for r in mine))
        for config in configs:
            pts = sorted((int(r["resolution"]), float(r["ms_per_step"]), float(r["l1"]))
                         for r in mine if (r["scheme"], r["limiter"]) == config)
            colour, marker = STYLE.get(config, ("black", "."))
            label = config[0] if config[1] == "none" else f"{config[0]} + {config[1]}"
            # The OpenVDB peer (--peer openvdb) dashed, coloured as our matching scheme.
            peer = config[0].startswith("OpenVDB ")
            if peer:
                ours = {"SEMI": "semi-Lagrangian", "MID": "semi-Lagrangian", "MAC": "MacCormack",
                        "BFECC": "BFECC"}[config[0].split()[1]]
                colour = STYLE.get((ours, config[1] if ours != "semi-Lagrangian" else "none"),
                                   ("black", "."))[0]
                marker = "." if config[0].endswith("SEMI") else "*"
            ax.plot([p[1] for p in pts], [p[2] for p in pts], color=colour, marker=marker,
                    linestyle="--" if peer else "-", label=label)
            for n, ms, l1 in pts:
                ax.annotate(str(n), (ms, l1), textcoords="offset points", xytext=(4, 3),
                            fontsize=7, color=colour)
        # Time spans decades (n³ cells); errors rarely span one, so their axis stays linear.
        ax.set_xscale("log")
        ax.xaxis.set_major_formatter(FormatStrFormatter("%.3g"))
        ax.xaxis.set_minor_formatter(FormatStrFormatter("%.3g"))
        ax.set_ylim(bottom=0)
        ax.set_xlabel("ms per step (advectField of one scalar)")
        ax.set_ylabel("L1 error  Σ|φ−φ₀| / Σφ₀")
        ax.set_title(problem + " (labels: resolution n)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
