#!/usr/bin/python3
"""Plots `eikon bench soak`'s CSV: memory against frame (VmRSS, RssAnon, the heap malloc has
handed out), with the RSS at the warm-up and the bound above it; below, the smoke's total density
(does the scene stay a plume, or fill up, or empty?) and ms per frame.

Usage: /usr/bin/python3 scripts/plot_soak.py CSV [PNG] [--warmup 100] [--bound-mib 16]
  (PNG defaults to CSV's name; --warmup and --bound-mib as the bench was run)
Needs matplotlib (Debian: python3-matplotlib, installed by scripts/install-deps.sh).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png", nargs="?")
    parser.add_argument("--warmup", type=int, default=100)
    parser.add_argument("--bound-mib", type=float, default=16.0)
    args = parser.parse_args()
    png = args.png or os.path.splitext(args.csv)[0] + ".png"
    with open(args.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{args.csv}: no rows")
    frame = [int(r["frame"]) for r in rows]

    def mib(key):
        return [int(r[key]) / 1024.0 for r in rows]

    fig, (top, middle, bottom) = plt.subplots(3, 1, figsize=(9, 8), sharex=True,
                                              gridspec_kw={"height_ratios": [3, 1, 1]})
    top.plot(frame, mib("rss_kib"), color="tab:blue", label="VmRSS")
    top.plot(frame, mib("rss_anon_kib"), color="tab:cyan", label="RssAnon")
    top.plot(frame, mib("heap_in_use_kib"), color="tab:green", label="heap in use (malloc)")
    warm = [r for r in rows if int(r["frame"]) == args.warmup]
    if warm:
        base = int(warm[0]["rss_kib"]) / 1024.0
        top.axvline(args.warmup, color="gray", linestyle=":", linewidth=1)
        top.axhspan(base, base + args.bound_mib, color="tab:blue", alpha=0.08,
                    label=f"RSS at frame {args.warmup} + {args.bound_mib:g} MiB bound")
    top.set_ylim(bottom=0)
    top.set_ylabel("MiB")
    gl = [int(r["gl_objects"]) for r in rows]
    title = f"eikon bench soak: {frame[-1]} frames"
    if gl[-1] >= 0:
        title += f", GL objects alive {gl[0]} at frame {frame[0]}, {gl[-1]} at the end"
    top.set_title(title)
    top.grid(True, alpha=0.3)
    top.legend(fontsize=8, loc="lower right")
    middle.plot(frame, [float(r["density_total"]) for r in rows], color="tab:gray")
    middle.set_ylim(bottom=0)
    middle.set_ylabel("∫ density dV")
    middle.grid(True, alpha=0.3)
    # The first sample holds the start-up (shader compilation): left out of the time panel.
    bottom.plot(frame[1:], [float(r["ms_per_frame"]) for r in rows[1:]], color="tab:red")
    bottom.set_ylim(bottom=0)
    bottom.set_ylabel("ms per frame")
    bottom.set_xlabel("frame")
    bottom.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
