#!/usr/bin/python3
"""Measures what eikon's memory estimates stand for (core/memory_limit.h): the peak RSS of
`eikon render` / `eikon simulate` at two sizes of one thing (render voxels, image pixels, smoke
cells, photons), the slope between them, and the constant the limit check uses for it. Each
constant must be an upper bound of its slope and at most 4 times it (an estimate that refuses
work needing a quarter of the limit is as wrong as one that lets a crash through).

Usage: /usr/bin/python3 scripts/measure_memory.py [EIKON] [SCRATCH]
Exit status 1 when a constant is not within [slope, 4·slope]. Run by ctest as memory_estimates.
"""
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def constants():
    text = open(os.path.join(ROOT, "core", "memory_limit.h")).read()
    return {m.group(1): float(m.group(2))
            for m in re.finditer(r"constexpr double (k\w+) = ([0-9.]+);", text)}


def peak_rss(args):
    """Runs args and returns its peak resident set in bytes (Linux reports KiB)."""
    # Small pages: on transparent huge pages (eikon's default, apps/huge_page_malloc.h) the RSS
    # moves in 2 MiB steps, and the image's slope (3 MB between the two sizes) read 7.7 B a pixel
    # once, against 13 on small pages. The estimates are of the data, not of the page size.
    env = dict(os.environ, EIKON_NO_HUGE_PAGES="1")
    proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env)
    _, status, usage = os.wait4(proc.pid, 0)
    err = proc.stderr.read().decode(errors="replace")
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("measure_memory: %s failed: %s" % (" ".join(args), err.strip()))
    return usage.ru_maxrss * 1024.0


def write_scene(scratch, name, scene):
    path = os.path.join(scratch, name + ".json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


def fog_scene(resolution, width, height, per_side=None):
    scene = json.load(open(os.path.join(ROOT, "data", "scenes", "glass_sphere_fog.json")))
    scene["volume"]["resolution"] = resolution
    scene["render"] = {"width": width, "height": height}
    if per_side:
        scene["render"]["light_transport"] = {"method": "photons",
                                              "photons": {"per_side": per_side}}
    return scene


def smoke_scene(resolution):
    scene = json.load(open(os.path.join(ROOT, "data", "scenes", "smoke_plume.json")))
    scene["simulation"]["resolution"] = resolution
    return scene


def main():
    eikon = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "apps", "eikon")
    scratch = sys.argv[2] if len(sys.argv) > 2 else "/tmp/eikon_measure_memory"
    os.makedirs(scratch, exist_ok=True)
    k = constants()

    def render(name, scene):
        path = write_scene(scratch, name, scene)
        return peak_rss([eikon, "render", path, "-o", os.path.join(scratch, name)])

    def simulate(name, scene):
        path = write_scene(scratch, name, scene)
        return peak_rss([eikon, "simulate", path, "-o", os.path.join(scratch, name),
                         "--frames", "1-2"])

    cells = {}
    for n in (32, 80):  # smoke_plume's domain is 1 × 1.5 × 1: n × 1.5n × n cells
        cells[n] = n * round(1.5 * n) * n
    photons_side = (32, 256)
    # (what, constant, unit, (size, rss) at the small and the large setting)
    rows = [
        ("render volume", "kRenderBytesPerVoxel", "voxel",
         [(r ** 3, render("volume%d" % r, fog_scene(r, 64, 48))) for r in (32, 96)]),
        ("image", "kRenderBytesPerPixel", "pixel",
         [(w * h, render("image%d" % w, fog_scene(24, w, h))) for w, h in ((160, 120),
                                                                            (800, 600))]),
        ("smoke domain", "kSmokeBytesPerCell", "cell",
         [(cells[n], simulate("smoke%d" % n, smoke_scene(n))) for n in (32, 80)]),
        # glass_sphere_fog has one spot light: one grid of per_side² photons.
        ("photons", "kPhotonBytes", "photon",
         [(s * s, render("photons%d" % s, fog_scene(24, 64, 48, s))) for s in photons_side]),
    ]
    failed = False
    print("%-14s %12s %12s %10s %10s  %s" % ("what", "small RSS", "large RSS", "slope B",
                                            "constant", "verdict"))
    # Each thread that traces particles deposits into a volume of its own (core/memory_limit.h,
    # renderVolumeBytes): the render volume's estimate grows with the threads eikon runs.
    threads = len(os.sched_getaffinity(0))

    def render_volume_bytes(voxels):
        return voxels * k["kRenderBytesPerVoxel"] + min(
            (threads - 1) * voxels * k["kDepositBytesPerVoxel"], k["kThreadDepositBudget"])

    estimates = {"kRenderBytesPerVoxel": render_volume_bytes}
    for what, name, unit, ((n0, rss0), (n1, rss1)) in rows:
        slope = (rss1 - rss0) / (n1 - n0)
        constant = k[name]
        if name in estimates:  # the estimate's own slope between the two sizes
            constant = (estimates[name](n1) - estimates[name](n0)) / (n1 - n0)
        ok = slope <= constant <= 4.0 * max(slope, 1.0)
        failed |= not ok
        print("%-14s %10.1f M %10.1f M %10.1f %10.1f  %s per %s" % (
            what, rss0 / 2 ** 20, rss1 / 2 ** 20, slope, constant,
            "ok" if ok else "OUT OF [slope, 4 slope]", unit))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
