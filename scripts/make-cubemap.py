#!/usr/bin/env python3
"""make-cubemap.py - the procedural skybox of scenes/features/skybox.yaml and the small images of
tests/data/, written with the standard library only (zlib + struct), so the inputs can be remade
bit for bit: python3 scripts/make-cubemap.py

Faces follow GL's cubemap convention (OpenGL 3.3 core spec, table 3.21 "selection of cube map
images"): face +x at texel (s, t), t = 0 the file's top row, looks along (1, -(2t-1), -(2s-1)).
Each texel is the sky along its own direction, so the six faces meet without seams whatever the
convention's mirroring: a pale sky with banded clouds, a ring of distant islands on the horizon
and the dark sea below (the renderer draws the sun on top).
"""
import math
import os
import struct
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
SIDE = 128  # texels per face side
AA = 3  # samples per texel side


def write_png(path, w, h, rows):
    """rows: h lists of w (r, g, b) bytes; 8-bit RGB, no filter"""
    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in rows)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def write_tga(path, w, h, rows):
    """uncompressed 24-bit TGA, top row first (descriptor bit 5)"""
    head = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, w, h, 24, 0x20)
    body = b"".join(bytes((b, g, r)) for row in rows for (r, g, b) in row)
    with open(path, "wb") as f:
        f.write(head + body)


def face_dir(face, s, t):
    sc, tc = 2.0 * s - 1.0, 2.0 * t - 1.0
    return [(1.0, -tc, -sc), (-1.0, -tc, sc), (sc, 1.0, tc),
            (sc, -1.0, -tc), (sc, -tc, 1.0), (-sc, -tc, -1.0)][face]


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
    return sum(noise(x * 2 ** o, y * 2 ** o) / 2 ** (o + 1) for o in range(4))


def mix(a, b, u):
    return tuple(a[k] + (b[k] - a[k]) * u for k in range(3))


def sky(d):
    """sRGB colour (0..1) along unit direction d"""
    x, y, z = d
    az = math.atan2(z, x)
    if y < 0.0:  # the sea, darker toward the nadir
        return mix((0.16, 0.27, 0.33), (0.05, 0.10, 0.14), min(1.0, -y * 3.0))
    # islands: peaks where the noise around the ring (periodic in the azimuth) rises above a
    # level, open sea between them
    ridge = 0.22 * max(0.0, fbm(4.0 * math.cos(az) + 7.0, 4.0 * math.sin(az) + 7.0) - 0.5)
    if y < ridge:
        haze = y / ridge
        return mix((0.42, 0.50, 0.50), (0.30, 0.40, 0.36), haze)
    base = mix((0.78, 0.85, 0.90), (0.22, 0.45, 0.78), math.sqrt(y))
    # clouds on a plane above: coordinates x/y, z/y
    u, v = x / (y + 0.08), z / (y + 0.08)
    cover = fbm(u * 1.5 + 11.0, v * 1.5 + 3.0)
    cloud = max(0.0, min(1.0, (cover - 0.48) * 4.0)) * min(1.0, y * 6.0)
    return mix(base, (0.97, 0.97, 0.96), cloud * 0.9)


def to8(c):
    return tuple(max(0, min(255, int(round(v * 255.0)))) for v in c)


def skybox(folder):
    os.makedirs(folder, exist_ok=True)
    for face, name in enumerate(["px", "nx", "py", "ny", "pz", "nz"]):
        rows = []
        for j in range(SIDE):
            row = []
            for i in range(SIDE):
                # 3x3 samples per texel: the islands' hard edge without stairs
                acc = [0.0, 0.0, 0.0]
                for a in range(AA):
                    for b in range(AA):
                        d = face_dir(face, (i + (a + 0.5) / AA) / SIDE, (j + (b + 0.5) / AA) / SIDE)
                        n = math.sqrt(sum(c * c for c in d))
                        col = sky(tuple(c / n for c in d))
                        acc = [acc[k] + col[k] / (AA * AA) for k in range(3)]
                row.append(to8(acc))
            rows.append(row)
        write_png(os.path.join(folder, name + ".png"), SIDE, SIDE, rows)


def solid(w, h, rgb):
    return [[rgb] * w for _ in range(h)]


def test_data(folder):
    os.makedirs(folder, exist_ok=True)
    # six distinct colours for the face-orientation test: red, cyan, green, magenta, blue, yellow
    colours = [(255, 0, 0), (0, 255, 255), (0, 255, 0), (255, 0, 255), (0, 0, 255), (255, 255, 0)]
    for name, c in zip(["px", "nx", "py", "ny", "pz", "nz"], colours):
        write_png(os.path.join(folder, "cube_%s.png" % name), 8, 8, solid(8, 8, c))
    write_png(os.path.join(folder, "cube_wrong_size.png"), 8, 4, solid(8, 4, (128, 128, 128)))
    # a 2x2 texture: top row red, green; bottom row blue, white (as a TGA and a PNG)
    quad = [[(255, 0, 0), (0, 255, 0)], [(0, 0, 255), (255, 255, 255)]]
    write_png(os.path.join(folder, "checker.png"), 2, 2, quad)
    write_tga(os.path.join(folder, "checker.tga"), 2, 2, quad)
    with open(os.path.join(folder, "corrupt.png"), "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + b"not really a png at all")


if __name__ == "__main__":
    skybox(os.path.join(ROOT, "scenes", "cubemap"))
    test_data(os.path.join(ROOT, "tests", "data"))
