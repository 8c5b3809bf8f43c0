#!/usr/bin/python3
"""Writes data/environments/studio.exr: a small photographic studio as an equirectangular HDR
environment (linear RGB, half floats, uncompressed scanlines), made procedurally so that the
repository holds its recipe, not a download. Radiances span four orders of magnitude, as a
captured studio HDRI's do: a dim room (0.02-0.4), two softboxes (12), an overhead strip (8) and a
small key lamp (400), so that a dispersive crystal shows its fire, the coloured sparks of small
bright sources split by its per-channel index, and tone mapping has something to compress.

Mapping (docs/scene-format.md, "environment"): u = 0.5 + atan2(d.x, -d.z) / 2pi, v = acos(d.y) / pi,
row 0 at the top; the middle column looks along -z.

Usage: /usr/bin/python3 scripts/make-studio-hdr.py [OUT.exr] [WIDTH]   (default 256, height W/2)
"""
import struct
import sys

import numpy as np


def studio(width):
    height = width // 2
    u = (np.arange(width) + 0.5) / width
    v = (np.arange(height) + 0.5) / height
    uu, vv = np.meshgrid(u, v)
    azimuth = (uu - 0.5) * 2.0 * np.pi  # 0 along -z, +pi/2 along +x
    elevation = 0.5 * np.pi - vv * np.pi  # +pi/2 straight up
    deg_az, deg_el = np.degrees(azimuth), np.degrees(elevation)
    rgb = np.zeros((height, width, 3))
    # The room: warm grey walls, lighter toward the ceiling; a dark floor.
    wall = 0.15 + 0.25 * np.clip(np.sin(elevation), 0.0, 1.0)
    rgb[...] = (wall * 1.0)[..., None] * np.array([1.0, 0.95, 0.88])
    floor = elevation < 0.0
    rgb[floor] = np.array([0.02, 0.02, 0.022])

    def box(az0, az1, el0, el1, radiance):
        inside = (deg_az >= az0) & (deg_az <= az1) & (deg_el >= el0) & (deg_el <= el1)
        rgb[inside] = radiance

    box(-65.0, -35.0, 10.0, 40.0, np.array([12.0, 12.0, 12.5]))  # softbox left, cool white
    box(30.0, 60.0, 5.0, 30.0, np.array([12.5, 11.8, 10.5]))  # softbox right, warmer
    box(-80.0, 80.0, 62.0, 66.0, np.array([8.0, 8.0, 8.0]))  # overhead strip
    box(118.0, 124.0, 25.0, 31.0, np.array([420.0, 390.0, 340.0]))  # small key lamp, behind right
    return rgb.astype(np.float16)


def attribute(name, kind, value):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value


def write_exr(path, image):
    height, width, _ = image.shape
    channels = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", 1, 0, 1, 1) for c in "BGR")
    window = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (
        struct.pack("<ii", 20000630, 2)
        + attribute("channels", "chlist", channels + b"\0")
        + attribute("compression", "compression", b"\0")
        + attribute("dataWindow", "box2i", window)
        + attribute("displayWindow", "box2i", window)
        + attribute("lineOrder", "lineOrder", b"\0")
        + attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0))
        + attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0))
        + attribute("screenWindowWidth", "float", struct.pack("<f", 1.0))
        + b"\0"
    )
    line_bytes = 8 + width * 3 * 2
    first = len(header) + 8 * height
    table = b"".join(struct.pack("<Q", first + y * line_bytes) for y in range(height))
    lines = []
    for y in range(height):
        row = image[y]
        data = b"".join(row[:, c].astype("<f2").tobytes() for c in (2, 1, 0))  # B, G, R
        lines.append(struct.pack("<ii", y, len(data)) + data)
    with open(path, "wb") as f:
        f.write(header + table + b"".join(lines))


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "data/environments/studio.exr"
    width = int(sys.argv[2]) if len(sys.argv) > 2 else 256
    write_exr(out, studio(width))
    print("wrote", out)
