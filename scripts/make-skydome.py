#!/usr/bin/env python3
"""make-skydome.py - the dome picture of scenes/features/skydome_texture.yaml (sky.image), written
with the standard library only (zlib + struct), so it can be remade bit for bit:
python3 scripts/make-skydome.py [OUT.png] [SIZE]

The picture uses the renderer's dome projection (shaders/common.glsl, ww_dome_uv): the centre is
the zenith, the inscribed circle the horizon, the distance from the centre proportional to the
zenith angle; the top of the image is -z, its right +x. Each texel is the sky along its own
direction: a blue gradient paling toward the horizon, a warm glow toward a low sun in the
south-west, and fair-weather clouds from value noise on a plane overhead (flat, so they crowd
toward the horizon as real ones do). Outside the circle, the horizon's colour.
"""
import math
import os
import struct
import sys
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
SIZE = 256
SUN = (-0.55, 0.35, 0.76)  # toward the glow, unit after normalising


def write_png(path, w, h, rows):
    """rows: h lists of w (r, g, b) bytes; 8-bit RGB, each row filtered by 'Up' (type 2), which
    a smooth sky compresses well with"""
    raw, prev = [], bytes(3 * w)
    for row in rows:
        cur = bytes(c for px in row for c in px)
        raw.append(b"\x02" + bytes((a - b) & 0xFF for a, b in zip(cur, prev)))
        prev = cur

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(b"".join(raw), 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def hash2(i, j):
    """a lattice hash in [0, 1): positions only, no state"""
    h = (i * 374761393 + j * 668265263) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((h ^ (h >> 16)) & 0xFFFF) / 65536.0


def noise(x, y):
    """value noise with smoothstep weights"""
    i, j = math.floor(x), math.floor(y)
    fx, fy = x - i, y - j
    ux, uy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
    a, b = hash2(i, j), hash2(i + 1, j)
    c, d = hash2(i, j + 1), hash2(i + 1, j + 1)
    return (a + (b - a) * ux) * (1 - uy) + (c + (d - c) * ux) * uy


def fbm(x, y):
    s, w = 0.0, 0.5
    for _ in range(5):
        s += w * noise(x, y)
        x, y, w = 2.03 * x + 17.0, 2.03 * y + 29.0, w * 0.5
    return s


def smoothstep(a, b, x):
    t = min(max((x - a) / (b - a), 0.0), 1.0)
    return t * t * (3 - 2 * t)


def to_srgb(c):
    c = min(max(c, 0.0), 1.0)
    return round(255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055))


def sky(d):
    """linear RGB of the sky along unit d (d[1] >= 0)"""
    n = math.sqrt(sum(c * c for c in SUN))
    sun = [c / n for c in SUN]
    y = max(d[1], 0.0)
    zenith, horizon = (0.10, 0.24, 0.62), (0.55, 0.68, 0.85)
    t = math.sqrt(y)
    c = [h + (z - h) * t for z, h in zip(zenith, horizon)]
    mu = max(sum(a * b for a, b in zip(d, sun)), 0.0)
    glow = 0.35 * mu ** 8 + 0.25 * mu ** 64
    c = [c[0] + glow * 1.0, c[1] + glow * 0.75, c[2] + glow * 0.45]
    # clouds where the ray meets a plane overhead
    px, pz = d[0] / (y + 0.08) * 1.4, d[2] / (y + 0.08) * 1.4
    cover = smoothstep(0.48, 0.70, fbm(px, pz)) * smoothstep(0.0, 0.10, y)
    lit = 0.85 + 0.35 * mu
    cloud = (lit, lit * 0.97, lit * 0.93)
    return [a + (b - a) * cover for a, b in zip(c, cloud)]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "scenes", "sky", "dome.png")
    size = int(sys.argv[2]) if len(sys.argv) > 2 else SIZE
    rows = []
    for j in range(size):
        row = []
        for i in range(size):
            # texel centre -> offset from the image centre, in radii of the inscribed circle
            x, z = 2.0 * (i + 0.5) / size - 1.0, 2.0 * (j + 0.5) / size - 1.0
            r = min(math.hypot(x, z), 1.0)
            theta = r * 0.5 * math.pi  # zenith angle
            h = math.hypot(x, z)
            ax, az = (x / h, z / h) if h > 1e-9 else (0.0, 0.0)
            d = (math.sin(theta) * ax, math.cos(theta), math.sin(theta) * az)
            row.append(tuple(to_srgb(c) for c in sky(d)))
        rows.append(row)
    write_png(out, size, size, rows)


if __name__ == "__main__":
    main()
