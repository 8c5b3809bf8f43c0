#!/usr/bin/python3
"""A glass ball's floor caustic: Eikon (`eikon bench caustic`), POV-Ray (the peer's focus sweep,
../shared/peers/povray_caustic_peer.sh) and an exact Snell's-law trace, measured alike.

Set-up (the peer's povray_caustic.pov, TOPVIEW): sphere of radius 1, n 1.5, centre D above a
diffuse floor y = 0, a point light of intensity I at (0, 100, 0); the floor square [-1.2, 1.2]^2.
Measures, as the peer's povray_caustic_focus.py defines them:
  base  the lit floor's irradiance (I / 100^2 at the centre; POV-Ray's images: --pov-base)
  peak  the largest 3x3-texel box mean of the irradiance, divided by base
  r50   the radius around the axis that holds half the excess (E - base outside the shadow disk
        r > 1, E inside it)
  dev   Eikon's RMS relative deviation from the exact trace on the same grid and filter, over the
        texels inside the shadow's disk (r < 0.95): ripples, rings and noise; dark texels weigh
        as much as bright ones
  L1    sum |Eikon - exact| / sum exact over the same texels: the share of the disk's light that
        lies in the wrong place, weighted as a picture shows it
The exact trace refracts rays from the light through the sphere (no reflection, as the peer's
scene), spread over the floor as Eikon spreads photons (bilinear, then the 3-tap binomial filter
of the receiver map) on Eikon's texel grid, and also binned on POV-Ray's 480 px grid.

usage: compare_caustic.py --eikon DIR [--povray DIR] [--pov-base B] [--rays N] [--plot PNG]
                          [--before DIR --maps PNG]
--before: maps of an earlier run (e.g. `eikon bench caustic --edge-filter box`), shown beside
--eikon's and the exact map in --maps, at the heights both runs hold (at most three).
"""
import argparse
import glob
import math
import os
import re
import sys

import numpy as np

HALF = 1.2
LIGHT_Y = 100.0
IOR = 1.5


def read_ppm(path):
    """A 16-bit linear PPM as the mean of its channels in [0, 1] (row 0 first)."""
    data = open(path, "rb").read()
    tokens, pos = [], 0
    while len(tokens) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        tokens.append(data[pos:end])
        pos = end
    pos += 1
    w, h, mx = int(tokens[1]), int(tokens[2]), int(tokens[3])
    dt = ">u2" if mx > 255 else "u1"
    img = np.frombuffer(data[pos:pos + w * h * 3 * (2 if mx > 255 else 1)], dtype=dt)
    return img.reshape(h, w, 3).astype(np.float64).mean(axis=2) / mx


def radii(n):
    c = (np.arange(n) + 0.5) / n * 2 * HALF - HALF
    x, z = np.meshgrid(c, c, indexing="ij")
    return np.hypot(x, z)


def measure(e, base):
    """peak (3x3 box mean / base) and r50 of the excess, as povray_caustic_focus.py."""
    n = e.shape[0]
    r = radii(n)
    excess = np.clip(np.where(r > 1.0, e - base, e), 0, None)
    order = np.argsort(r.ravel())
    cum = np.cumsum(excess.ravel()[order])
    r50 = float(r.ravel()[order][np.searchsorted(cum, 0.5 * cum[-1])])
    p = np.pad(e, 1, mode="edge")
    box = sum(p[i:i + n, j:j + n] for i in range(3) for j in range(3)) / 9.0
    return float(box.max() / base), r50


def refract(d, nrm, eta):
    """Refracts unit d at unit normal nrm (against d) with eta = n1/n2; None where TIR."""
    cos_i = -np.sum(d * nrm, axis=1, keepdims=True)
    k = 1 - eta * eta * (1 - cos_i * cos_i)
    return eta * d + (eta * cos_i - np.sqrt(np.clip(k, 0, None))) * nrm, k[:, 0] >= 0


def exact_hits(d_centre, rays, rng):
    """Floor hits (x, z) and flux per ray of rays from the light through the sphere, I = 1."""
    light = np.array([0.0, LIGHT_Y, 0.0])
    c = np.array([0.0, d_centre, 0.0])
    dist = LIGHT_Y - d_centre
    cos_max = math.sqrt(1 - 1 / dist ** 2)
    # Stratified in solid angle over the cone that holds the sphere.
    u = (np.arange(rays) + rng.random(rays)) / rays
    cos_t = 1 - u * (1 - cos_max)
    phi = rng.random(rays) * 2 * math.pi
    sin_t = np.sqrt(1 - cos_t ** 2)
    d = np.stack([sin_t * np.cos(phi), -cos_t, sin_t * np.sin(phi)], axis=1)
    flux = 2 * math.pi * (1 - cos_max) / rays
    oc = light - c
    b = d @ oc
    disc = b * b - (oc @ oc - 1)
    hit = disc > 0
    d, b, disc = d[hit], b[hit], disc[hit]
    p1 = light + (-b - np.sqrt(disc))[:, None] * d
    n1 = p1 - c
    t1, ok1 = refract(d, n1, 1 / IOR)
    t1 = t1 / np.linalg.norm(t1, axis=1, keepdims=True)
    # The second intersection from inside: p1 + s t1 with |p - c| = 1, s = -2 (p1 - c)·t1.
    s = -2 * np.sum(n1 * t1, axis=1)
    p2 = p1 + s[:, None] * t1
    n2 = -(p2 - c)
    t2, ok2 = refract(t1, n2, IOR)
    keep = ok1 & ok2 & (t2[:, 1] < 0)
    p2, t2 = p2[keep], t2[keep]
    s = -p2[:, 1] / t2[:, 1]
    floor = p2 + s[:, None] * t2
    return floor[:, 0], floor[:, 2], flux


def direct(n, d_centre):
    """The light's direct irradiance on the floor texels' centres, 0 in the sphere's shadow."""
    cc = (np.arange(n) + 0.5) / n * 2 * HALF - HALF
    x, z = np.meshgrid(cc, cc, indexing="ij")
    p = np.stack([x, np.zeros_like(x), z], axis=-1)
    to_light = np.array([0.0, LIGHT_Y, 0.0]) - p
    dist = np.linalg.norm(to_light, axis=-1)
    e = LIGHT_Y / dist ** 3  # I cos / r², I = 1
    u = to_light / dist[..., None]
    oc = p - np.array([0.0, d_centre, 0.0])
    b = np.sum(u * oc, axis=-1)
    disc = b * b - (np.sum(oc * oc, axis=-1) - 1)
    shadow = (disc > 0) & (-b - np.sqrt(np.clip(disc, 0, None)) > 0)
    return np.where(shadow, 0.0, e)


def splat(x, z, flux, n, bilinear):
    """Irradiance on an n x n grid over the floor square from hits carrying `flux` each."""
    texel = 2 * HALF / n
    acc = np.zeros((n, n))
    if not bilinear:
        i = np.floor((x + HALF) / texel).astype(int)
        k = np.floor((z + HALF) / texel).astype(int)
        ok = (i >= 0) & (i < n) & (k >= 0) & (k < n)
        np.add.at(acc, (i[ok], k[ok]), flux)
        return acc / texel ** 2
    fx = (x + HALF) / texel - 0.5
    fz = (z + HALF) / texel - 0.5
    i0, k0 = np.floor(fx).astype(int), np.floor(fz).astype(int)
    ax, az = fx - i0, fz - k0
    for di, wi in ((0, 1 - ax), (1, ax)):
        for dk, wk in ((0, 1 - az), (1, az)):
            i, k = i0 + di, k0 + dk
            ok = (i >= 0) & (i < n) & (k >= 0) & (k < n)
            np.add.at(acc, (i[ok], k[ok]), flux * (wi * wk)[ok])
    return acc / texel ** 2


def binomial(e):
    """The receiver map's 3-tap binomial filter [1, 2, 1] / 4 along both axes, edges clamped."""
    for axis in (0, 1):
        p = np.pad(e, [(1, 1) if a == axis else (0, 0) for a in (0, 1)], mode="edge")
        sl = [slice(None), slice(None)]
        parts = []
        for o in range(3):
            sl[axis] = slice(o, o + e.shape[axis])
            parts.append(p[tuple(sl)])
        e = (parts[0] + 2 * parts[1] + parts[2]) / 4
    return e


def read_maps(folder):
    """{D: irradiance map} of the caustic_D*.f32 files `eikon bench caustic` wrote to folder."""
    maps = {}
    for path in glob.glob(os.path.join(folder, "caustic_D*.f32")):
        d = float(re.search(r"caustic_D([0-9.]+)\.f32$", path).group(1))
        e = np.fromfile(path, dtype=np.float32).astype(np.float64)
        n = int(round(math.sqrt(e.size)))
        if n * n != e.size:
            sys.exit(f"eikon: {path}: not a square map")
        maps[d] = e.reshape(n, n)
    if not maps:
        sys.exit(f"eikon: {folder}: no caustic_D*.f32 maps")
    return maps


def plot_maps(path, rows, before, base):
    """Before, after and exact maps (log irradiance / lit floor) at up to three heights."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    picked = [r for r in rows if r[0] in before and before[r[0]].shape == r[9].shape]
    picked = picked[-3:]
    if not picked:
        sys.exit("eikon: compare_caustic.py: --before holds none of --eikon's heights")
    fig, ax = plt.subplots(len(picked), 3, figsize=(11, 3.7 * len(picked)), squeeze=False)
    for i, r in enumerate(picked):
        for j, (m, title) in enumerate(((before[r[0]], "before (--before)"),
                                        (r[9], "Eikon"), (r[10], "exact Snell trace"))):
            im = ax[i][j].imshow(np.log10(np.maximum(m / base, 1e-2)).T, origin="lower",
                                 extent=[-HALF, HALF, -HALF, HALF], vmin=-1, vmax=1.5,
                                 cmap="inferno")
            ax[i][j].set_title(f"{title}, D = {r[0]:g}", fontsize=9)
            ax[i][j].set_xticks([])
            ax[i][j].set_yticks([])
        fig.colorbar(im, ax=ax[i].tolist(), shrink=0.8, label="log10 irradiance / lit floor")
    fig.savefig(path, dpi=64, bbox_inches="tight")
    print(f"wrote {path}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--eikon", required=True)
    ap.add_argument("--povray")
    ap.add_argument("--pov-base", type=float, default=0.0003)
    ap.add_argument("--rays", type=int, default=4000000)
    ap.add_argument("--plot")
    ap.add_argument("--before")
    ap.add_argument("--maps")
    a = ap.parse_args()
    if bool(a.before) != bool(a.maps):
        sys.exit("eikon: compare_caustic.py: --before and --maps go together")
    maps = read_maps(a.eikon)
    before = read_maps(a.before) if a.before else {}
    pov = {}
    if a.povray:
        for path in glob.glob(os.path.join(a.povray, "focus_D*.ppm")):
            d = float(re.search(r"focus_D([0-9.]+)\.ppm$", path).group(1))
            pov[d] = read_ppm(path)
    rng = np.random.default_rng(1)
    base = LIGHT_Y / LIGHT_Y ** 3  # I / 100² at the floor's centre
    rows = []
    print("# D: centre height / R. peak: 3x3 box mean / lit floor; r50 / R. exact: Snell trace "
          f"({a.rays} rays), on Eikon's grid (bilinear + binomial) and on POV-Ray's 480 px grid")
    print(f"{'D':>5} | {'eikon peak':>10} {'r50':>6} | {'exact peak':>10} {'r50':>6} | "
          f"{'ratio':>6} {'dev':>6} {'L1':>6} | {'exact480 peak':>13} {'r50':>6} | {'POV peak':>8} {'r50':>6}")
    for d in sorted(maps):
        e = maps[d]
        n = e.shape[0]
        x, z, flux = exact_hits(d, a.rays, rng)
        ex = binomial(direct(n, d) + splat(x, z, flux, n, True))
        ex480 = direct(480, d) + splat(x, z, flux, 480, False)
        pe, re_ = measure(e, base)
        px, rx = measure(ex, base)
        p4, r4 = measure(ex480, base)
        inner = (radii(n) < 0.95) & (ex > 0)
        dev = float(np.sqrt(np.mean(((e - ex)[inner] / ex[inner]) ** 2)))
        l1 = float(np.sum(np.abs(e - ex)[inner]) / np.sum(ex[inner]))
        line = (f"{d:5.2f} | {pe:10.1f} {re_:6.3f} | {px:10.1f} {rx:6.3f} | {pe / px:6.2f} "
                f"{dev:6.3f} {l1:6.3f} | "
                f"{p4:13.1f} {r4:6.3f} |")
        pp = rp = float("nan")
        if d in pov:
            pp, rp = measure(pov[d], a.pov_base)
            line += f" {pp:8.1f} {rp:6.3f}"
        print(line)
        rows.append((d, pe, re_, px, rx, p4, r4, pp, rp, e, ex))
    if a.maps:
        plot_maps(a.maps, rows, before, base)
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        ds = [r[0] for r in rows]
        fig, ax = plt.subplots(1, 3, figsize=(15, 4.4))
        ax[0].plot(ds, [r[1] for r in rows], "o-", label="Eikon")
        ax[0].plot(ds, [r[3] for r in rows], "s--", label="exact, Eikon's grid and filter")
        ax[0].plot(ds, [r[5] for r in rows], "^:", label="exact, POV-Ray's 480 px")
        if pov:
            ax[0].plot(ds, [r[7] for r in rows], "d-.", label="POV-Ray")
        ax[0].set_xlabel("centre height D / R")
        ax[0].set_ylabel("peak / lit floor")
        ax[0].set_yscale("log")
        ax[0].legend(fontsize=8)
        ax[1].plot(ds, [r[2] for r in rows], "o-", label="Eikon")
        ax[1].plot(ds, [r[4] for r in rows], "s--", label="exact")
        if pov:
            ax[1].plot(ds, [r[8] for r in rows], "d-.", label="POV-Ray")
        ax[1].set_xlabel("centre height D / R")
        ax[1].set_ylabel("r50 / R")
        ax[1].legend(fontsize=8)
        last = rows[len(rows) // 2]
        n = last[9].shape[0]
        c = n // 2
        xs = (np.arange(n) + 0.5) / n * 2 * HALF - HALF
        ax[2].plot(xs, last[9][:, c] / base, label="Eikon")
        ax[2].plot(xs, last[10][:, c] / base, "--", label="exact (same grid and filter)")
        ax[2].set_yscale("log")
        ax[2].set_xlabel("x / R (through the axis)")
        ax[2].set_ylabel("irradiance / lit floor")
        ax[2].set_title(f"D = {last[0]:g}")
        ax[2].legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=110)
        print(f"wrote {a.plot}")


if __name__ == "__main__":
    main()
