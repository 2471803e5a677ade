#!/usr/bin/env python3
"""make-models.py - the underwater world's models (seed 003: a sunken ship, rocks, sea plants,
starfish and coral) as OBJ + MTL + PNG files in scenes/models/, made from code so they can be
read, changed and made again. Standard library only (PNG written with zlib + struct); fixed seeds,
so the output is the same bytes on every run.

    python3 scripts/make-models.py [OUT_DIR]      # default: scenes/models

Conventions: metres, y up, a model's base on y = 0 (plants and the ship's keel), so a scene sets
its height above the sand directly and the sway (`sway:` in objects.models) bends from the base.
Every vertex carries a normal: smooth where the surface is (shared between the faces around a
vertex), hard where it is not (planks, the jagged rock's facets). Triangle counts are printed.
"""
import math
import os
import random
import struct
import sys
import zlib

# ---- PNG ------------------------------------------------------------------------------------


def write_png(path, w, h, pixels):
    """pixels: rows of (r, g, b) bytes, top row first"""
    raw = bytearray()
    for row in pixels:
        raw.append(0)
        for r, g, b in row:
            raw += bytes((r, g, b))

    def chunk(kind, data):
        c = struct.pack(">I", len(data)) + kind + data
        return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def clamp8(x):
    return max(0, min(255, int(round(x * 255.0))))


def srgb(c):
    """linear [0, 1] -> sRGB byte (textures are sampled as sRGB)"""
    c = max(0.0, min(1.0, c))
    s = 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055
    return clamp8(s)


class Noise:
    """tileable value noise on a period x period lattice, smooth (cubic fade)"""

    def __init__(self, seed, period):
        rng = random.Random(seed)
        self.p = period
        self.v = [[rng.random() for _ in range(period)] for _ in range(period)]

    def at(self, x, y):
        p = self.p
        xi, yi = int(math.floor(x)), int(math.floor(y))
        fx, fy = x - xi, y - yi
        fx, fy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
        a = self.v[yi % p][xi % p]
        b = self.v[yi % p][(xi + 1) % p]
        c = self.v[(yi + 1) % p][xi % p]
        d = self.v[(yi + 1) % p][(xi + 1) % p]
        return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy


def fbm(n, x, y, octaves=4):
    s, a, t = 0.0, 0.5, 0.0
    for _ in range(octaves):
        s += a * n.at(x, y)
        t += a
        x, y, a = x * 2, y * 2, a * 0.5
    return s / t


def tex_wood(path, size=128, planks=8):
    """planks across v (one strake per 1/planks), grain along u, dark seams, green-grey growth"""
    rng = random.Random(3)
    tone = [0.75 + 0.5 * rng.random() for _ in range(planks)]
    shift = [rng.random() * 40 for _ in range(planks)]
    grain = Noise(11, 16)
    growth = Noise(12, 8)
    rows = []
    for y in range(size):
        row = []
        k = y * planks // size
        fv = (y * planks / size) - k
        for x in range(size):
            u = x / size
            g = fbm(grain, u * 4 + shift[k], fv * 0.7 + k * 3.1, 3)
            streak = 0.85 + 0.3 * math.sin((g * 9.0 + fv * 2.0) * math.pi)
            r, gg, b = 0.46, 0.26, 0.11
            m = tone[k] * streak
            r, gg, b = r * m, gg * m, b * m
            # butt joints: each strake's planks end at its own places
            joint = abs(((u * 2 + shift[k] / 40) % 1.0) - 0.5) < 0.006
            seam = fv < 0.07 or fv > 0.95 or joint
            if seam:
                r, gg, b = r * 0.3, gg * 0.3, b * 0.3
            a = fbm(growth, u * 8, y / size * 8, 3)
            w = max(0.0, min(1.0, (a - 0.55) * 2.5))
            r, gg, b = r * (1 - w) + 0.16 * w, gg * (1 - w) + 0.15 * w, b * (1 - w) + 0.07 * w
            row.append((srgb(r), srgb(gg), srgb(b)))
        rows.append(row)
    write_png(path, size, size, rows)


def tex_speckle(path, seed, base, dark, light, size=128, growth=None):
    """a stone's grain: fbm mottling, dark and light specks, optional patches of growth"""
    rng = random.Random(seed)
    n = Noise(seed, 16)
    g = Noise(seed + 1, 8)
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            m = fbm(n, x / size * 8, y / size * 8, 4)
            c = [base[i] * (0.7 + 0.6 * m) for i in range(3)]
            s = rng.random()
            if s < 0.05:
                c = list(dark)
            elif s > 0.97:
                c = list(light)
            if growth:
                w = max(0.0, min(1.0, (fbm(g, x / size * 8, y / size * 8, 3) - 0.55) * 4.0))
                c = [c[i] * (1 - w) + growth[i] * w for i in range(3)]
            row.append(tuple(srgb(v) for v in c))
        rows.append(row)
    write_png(path, size, size, rows)


def tex_blade(path, w, h, base, edge, rib):
    """a frond or blade: u across (0, 1 the edges), v along; a midrib, veins, darker edges"""
    n = Noise(21, 8)
    rows = []
    for y in range(h):
        row = []
        for x in range(w):
            u = (x + 0.5) / w
            d = abs(u - 0.5) * 2
            c = [base[i] * (1 - d * d) + edge[i] * d * d for i in range(3)]
            if d < 0.08:
                c = list(rib)
            vein = 0.9 + 0.1 * math.sin(u * 40.0 + y / h * 6.0)
            m = 0.8 + 0.4 * fbm(n, u * 4, y / h * 8, 3)
            row.append(tuple(srgb(v * vein * m) for v in c))
        rows.append(row)
    write_png(path, w, h, rows)


def tex_dots(path, size, base, dot, seed):
    """a starfish's back: pale tubercles on the base colour"""
    rng = random.Random(seed)
    pts = [(rng.random(), rng.random(), 0.02 + 0.025 * rng.random()) for _ in range(45)]
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            u, v = x / size, y / size
            c = list(base)
            for px, py, r in pts:
                dx = min(abs(u - px), 1 - abs(u - px))
                dy = min(abs(v - py), 1 - abs(v - py))
                if dx * dx + dy * dy < r * r:
                    c = list(dot)
                    break
            row.append(tuple(srgb(v) for v in c))
        rows.append(row)
    write_png(path, size, size, rows)


def tex_brain(path, size=128):
    """brain coral: meandering ridges (a pale crest, dark valleys)"""
    n = Noise(31, 8)
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            u, v = x / size, y / size
            p = math.sin((u * 10 + 1.5 * fbm(n, u * 4, v * 4, 3) * 4) * 2 * math.pi)
            p = 0.5 + 0.5 * p
            c = (0.45 * (0.5 + 0.6 * p), 0.42 * (0.5 + 0.6 * p), 0.16 * (0.6 + 0.5 * p))
            row.append(tuple(srgb(c_) for c_ in c))
        rows.append(row)
    write_png(path, size, size, rows)


# ---- meshes ---------------------------------------------------------------------------------


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a):
    d = math.sqrt(dot(a, a))
    return (a[0] / d, a[1] / d, a[2] / d) if d > 0 else (0.0, 1.0, 0.0)


class Mesh:
    """triangles grouped by material; each vertex has a position, uv and normal. smooth groups:
    the vertices of one `grid`/`surface` call share normals (the mean of their faces'),
    vertices of separate calls never do (hard edges between parts)"""

    def __init__(self):
        self.v, self.vt, self.vn = [], [], []
        self.faces = {}  # material -> [(i, j, k)] vertex indices (0-based, into v/vt/vn)
        self.order = []

    def vertex(self, p, uv, n=(0.0, 1.0, 0.0)):
        self.v.append(p)
        self.vt.append(uv)
        self.vn.append(n)
        return len(self.v) - 1

    def tri(self, mat, a, b, c):
        if mat not in self.faces:
            self.faces[mat] = []
            self.order.append(mat)
        self.faces[mat].append((a, b, c))

    def smooth(self, idx, tris, flat=False):
        """normals of vertices idx from the triangles tris (area weighted), or flat per face"""
        acc = {i: (0.0, 0.0, 0.0) for i in idx}
        for a, b, c in tris:
            n = cross(sub(self.v[b], self.v[a]), sub(self.v[c], self.v[a]))
            for i in (a, b, c):
                if i in acc:
                    acc[i] = add(acc[i], n)
        for i in idx:
            self.vn[i] = norm(acc[i])

    def grid(self, mat, rows, uvs=None, closed_u=False):
        """a surface from rows of points (rows[j][i]); quads between neighbours; smooth normals
        within it. uvs: same shape, or None for (i / n, j / m)"""
        m, n = len(rows), len(rows[0])
        idx = []
        for j in range(m):
            line = []
            for i in range(n):
                uv = uvs[j][i] if uvs else (i / max(1, n - 1), j / max(1, m - 1))
                line.append(self.vertex(rows[j][i], uv))
            idx.append(line)
        tris = []
        cols = n if closed_u else n - 1
        for j in range(m - 1):
            for i in range(cols):
                i2 = (i + 1) % n
                a, b, c, d = idx[j][i], idx[j][i2], idx[j + 1][i2], idx[j + 1][i]
                tris += [(a, b, c), (a, c, d)]
        self.smooth([k for line in idx for k in line], tris)
        for t in tris:
            self.tri(mat, *t)
        return idx

    def flat_tri(self, mat, p, q, r, uvs):
        n = norm(cross(sub(q, p), sub(r, p)))
        a, b, c = (self.vertex(x, u, n) for x, u in zip((p, q, r), uvs))
        self.tri(mat, a, b, c)

    def box(self, mat, lo, hi, uvscale=1.0, frame=None):
        """an axis-aligned box (optionally through frame(p) -> p), hard edges, uv by face"""
        x0, y0, z0 = lo
        x1, y1, z1 = hi
        faces = [((x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)),
                 ((x0, y0, z1), (x0, y1, z1), (x0, y1, z0), (x0, y0, z0)),
                 ((x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)),
                 ((x0, y0, z1), (x0, y0, z0), (x1, y0, z0), (x1, y0, z1)),
                 ((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)),
                 ((x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0))]
        for f in faces:
            pts = [frame(p) if frame else p for p in f]
            e0, e1 = sub(pts[1], pts[0]), sub(pts[3], pts[0])
            l0, l1 = math.sqrt(dot(e0, e0)), math.sqrt(dot(e1, e1))
            uv = [(0, 0), (0, l0 * uvscale), (l1 * uvscale, l0 * uvscale), (l1 * uvscale, 0)]
            n = norm(cross(sub(pts[1], pts[0]), sub(pts[2], pts[0])))
            k = [self.vertex(p, u, n) for p, u in zip(pts, uv)]
            self.tri(mat, k[0], k[1], k[2])
            self.tri(mat, k[0], k[2], k[3])

    def tube(self, mat, path, radii, sides=6, cap_end=True, uvlen=1.0, jag=None):
        """a tube along path (points) with radius per point; smooth around, hard end caps.
        jag(i) -> y offset of ring vertex i at the end (a snapped end)"""
        rows = []
        ref = (1.0, 0.0, 0.0)
        for k, p in enumerate(path):
            t = norm(sub(path[min(k + 1, len(path) - 1)], path[max(k - 1, 0)]))
            if abs(dot(t, ref)) > 0.9:
                ref = (0.0, 0.0, 1.0)
            a = norm(cross(t, ref))
            b = cross(t, a)
            ring = []
            for i in range(sides + 1):
                ang = 2 * math.pi * i / sides
                off = add(mul(a, math.cos(ang) * radii[k]), mul(b, math.sin(ang) * radii[k]))
                q = add(p, off)
                if jag and k == len(path) - 1:
                    q = add(q, mul(t, jag(i % sides)))
                ring.append(q)
            rows.append(ring)
        uvs = [[(i / sides, k * uvlen) for i in range(sides + 1)] for k in range(len(path))]
        idx = self.grid(mat, rows, uvs)
        # the seam's two columns are one: give them the same normal
        for line in idx:
            n = norm(add(self.vn[line[0]], self.vn[line[-1]]))
            self.vn[line[0]] = self.vn[line[-1]] = n
        if cap_end:
            c = path[-1]
            ring = rows[-1][:-1]
            cen = add(c, mul(norm(sub(path[-1], path[-2])), 0.0))
            for i in range(sides):
                p, q = ring[i], ring[(i + 1) % sides]
                self.flat_tri(mat, cen, p, q, [(0.5, 0.5), (0.5, 0), (0.6, 0)])

    def triangles(self):
        return sum(len(f) for f in self.faces.values())

    def bounds(self):
        lo = [min(p[a] for p in self.v) for a in range(3)]
        hi = [max(p[a] for p in self.v) for a in range(3)]
        return lo, hi

    def write(self, path, mtl, name):
        """OBJ with v, vt and vn each written once per distinct value (3 decimals: 1 mm),
        faces v/vt/vn by material"""
        f4 = lambda x: ("%.3f" % x).rstrip("0").rstrip(".") if abs(x) >= 5e-4 else "0"
        pools = ({}, {}, {})
        lines = ([], [], [])
        keys = ("v", "vt", "vn")

        def ref(kind, val):
            text = " ".join(f4(x) for x in val)
            pool = pools[kind]
            if text not in pool:
                pool[text] = len(pool) + 1
                lines[kind].append("%s %s" % (keys[kind], text))
            return pool[text]
        corner = {}
        for i in range(len(self.v)):
            corner[i] = "%d/%d/%d" % (ref(0, self.v[i]), ref(1, self.vt[i]), ref(2, self.vn[i]))
        out = ["# %s - made by scripts/make-models.py (do not edit by hand)" % name,
               "mtllib %s" % mtl, "o %s" % name]
        out += lines[0] + lines[1] + lines[2]
        for mat in self.order:
            out.append("usemtl %s" % mat)
            for a, b, c in self.faces[mat]:
                out.append("f %s %s %s" % (corner[a], corner[b], corner[c]))
        with open(path, "w") as fh:
            fh.write("\n".join(out) + "\n")


def write_mtl(path, mats):
    """mats: [(name, Kd, Ks, Ns, map_Kd or None)]"""
    out = ["# made by scripts/make-models.py"]
    for name, kd, ks, ns, tex in mats:
        out += ["", "newmtl %s" % name, "Kd %.3f %.3f %.3f" % kd, "Ks %.3f %.3f %.3f" % ks,
                "Ns %g" % ns, "d 1"]
        if tex:
            out.append("map_Kd %s" % tex)
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")


# ---- the wreck ------------------------------------------------------------------------------
# The ship's frame: keel along z (bow toward -z) on y = 0, beam along x, gunwale at y = DEPTH.
# Three files share it (hull; deck and cabin; mast stump), and a fourth, the snapped-off top of
# the mast, has its own frame so a scene can lay it leaning against the hull with a tight box.

LENGTH, BEAM, DEPTH = 10.0, 3.2, 2.0
STRAKES = 8


def hull_half_beam(z):
    """half the beam at station z: full amidships, narrowing to the stem (bow) and the
    transom (stern, cut square at 85% of the half length)"""
    s = z / (LENGTH / 2)
    if s < 0:  # bow: fine entry
        return BEAM / 2 * max(0.0, 1 - abs(s) ** 2.2)
    return BEAM / 2 * (1 - 0.55 * s ** 2)


def hull_point(z, a):
    """a point of the hull at station z, a in [-1, 1] from port gunwale through the keel to
    starboard; the section is a rounded V (y up from the keel)"""
    b = hull_half_beam(z)
    s = abs(z) / (LENGTH / 2)
    sheer = DEPTH + 0.35 * s ** 2  # the gunwale rises toward bow and stern
    th = a * math.pi / 2
    x = b * math.sin(th)
    keel = 0.08 * (s ** 3)  # the keel rises a little at the ends
    y = keel + (sheer - keel) * (1 - math.cos(th) ** 1.4)
    return (x, y, z)


def make_wreck(out):
    rng = random.Random(7)
    hull = Mesh()
    zs = [-LENGTH / 2 + LENGTH * k / 28 for k in range(29)]
    zs[0] += 0.02  # the stem: a sliver of beam
    zs[-1] = LENGTH / 2 * 0.85  # the transom
    # strakes: each plank its own strip, so the light breaks at every seam (lapstrake)
    hole = lambda side, k, j: side > 0 and 2 <= k <= 5 and 9 <= j <= 15 and not (
        k == 2 and j in (9, 15))
    for side in (-1, 1):
        for k in range(STRAKES):
            a0, a1 = k / STRAKES, (k + 1) / STRAKES
            # each strake overlaps the one below by a few centimetres, stepped out
            rows, uvs = [], []
            for j, z in enumerate(zs):
                p0 = hull_point(z, side * a0)
                # its upper edge tucks under the next strake's stepped-out lower edge: no crack
                p1 = hull_point(z, side * min(1.0, a1 + 0.25 / STRAKES))
                lap = 0.03 * (1 - a0)
                out_dir = norm((p0[0], 0.4 * (p0[1] - DEPTH) / DEPTH - 0.2, 0.0)) if k > 0 else (0, -1, 0)
                p0 = add(p0, mul(out_dir, lap))
                rows.append([p0, p1])
                v0, v1 = k / STRAKES, (k + 1) / STRAKES - 0.001
                uvs.append([(z / 4.0 + 0.5, v0), (z / 4.0 + 0.5, v1)])
            # the broken side: strakes missing over a stretch of starboard amidships
            if side > 0 and 2 <= k <= 5:
                cut = [j for j in range(len(zs)) if not hole(side, k, j)]
                runs, cur = [], [cut[0]]
                for j in cut[1:]:
                    if j == cur[-1] + 1:
                        cur.append(j)
                    else:
                        runs.append(cur)
                        cur = [j]
                runs.append(cur)
                for r in runs:
                    if len(r) < 2:
                        continue
                    # ragged ends: the plank broke, not sawn
                    rr = [[rows[j][0], rows[j][1]] for j in r]
                    if r[-1] < 12:
                        e = rr[-1]
                        rr[-1] = [add(e[0], (0, 0, rng.uniform(0.05, 0.3))), e[1]]
                    if r[0] > 12:
                        e = rr[0]
                        rr[0] = [e[0], add(e[1], (0, 0, -rng.uniform(0.05, 0.3)))]
                    hull.grid("planks", [list(x) for x in zip(*rr)], [list(x) for x in zip(*[uvs[j] for j in r])])
                continue
            hull.grid("planks", [list(x) for x in zip(*rows)], [list(x) for x in zip(*uvs)])
    # transom: a flat board closing the stern
    zt = zs[-1]
    ring = [hull_point(zt, -1 + 2 * i / 16) for i in range(17)]
    top = max(p[1] for p in ring)
    for i in range(16):
        p, q = ring[i], ring[i + 1]
        hull.flat_tri("planks", p, (q[0], top, zt), q, [(p[0], p[1] / 2), (q[0], 1), (q[0], q[1] / 2)])
        hull.flat_tri("planks", p, (p[0], top, zt), (q[0], top, zt), [(p[0], p[1] / 2), (p[0], 1), (q[0], 1)])
    # the stem: a post up the bow, covering where the two sides' strakes meet
    z0 = zs[0]
    stem = [(0.0, hull_point(z0, a / 6)[1] if a else 0.02, z0 + 0.02) for a in range(7)]
    stem = [(0.0, -0.2, zs[1])] + stem
    hull.tube("timber", stem, [0.08] * len(stem), sides=4, uvlen=0.3)
    # keel: a timber under the hull, stem to stern
    hull.box("timber", (-0.09, -0.22, -LENGTH / 2 + 0.1), (0.09, 0.05, zt), 0.5)
    # ribs (frames): bent timbers inside the planking, seen through the broken side
    for j in range(2, len(zs) - 2, 2):
        z = zs[j]
        path = [add(hull_point(z, -1 + 2 * i / 12), (0, 0, 0)) for i in range(13)]
        path = [(p[0] * 0.94, p[1] * 0.98 + 0.05, p[2]) for p in path]
        if j == 12:  # one frame snapped where the side is gone
            path = path[:11]
        hull.tube("timber", path, [0.07] * len(path), sides=4, cap_end=True, uvlen=0.3)
    # gunwale rails
    for side in (-1, 1):
        path = [hull_point(z, side) for z in zs if not (side > 0 and 11 <= zs.index(z) <= 14)]
        path = [add(p, (0, 0.04, 0)) for p in path]
        hull.tube("timber", path[: len(path)], [0.06] * len(path), sides=4, uvlen=0.25)
    hull.write(os.path.join(out, "wreck_hull.obj"), "wreck.mtl", "wreck_hull")

    # ---- deck and cabin ----
    deck = Mesh()
    ydeck = DEPTH - 0.12
    nplank = 18
    for k in range(nplank):
        x0 = -BEAM / 2 + BEAM * k / nplank
        x1 = x0 + BEAM / nplank - 0.012
        # each plank runs as far as the hull is wide there
        zlo, zhi = None, None
        for j in range(200):
            z = -LENGTH / 2 + LENGTH * j / 199
            if z > zt:
                break
            if hull_half_beam(z) * 0.97 >= max(abs(x0), abs(x1)):
                zlo = z if zlo is None else zlo
                zhi = z
        if zlo is None:
            continue
        # the deck broke in over the hole: the starboard planks there are gone
        pieces = [(zlo, zhi)]
        if x0 > 0.4:
            cut0 = -1.2 + 0.25 * rng.random()
            cut1 = 1.1 + 0.3 * rng.random()
            pieces = [(zlo, cut0), (cut1, zhi)]
        for a, b in pieces:
            if b - a > 0.1:
                deck.box("deck", (x0, ydeck, a), (x1, ydeck + 0.05, b), 0.25)
    # beams under the broken deck
    for z in (-1.3, 1.25):
        deck.box("timber", (-BEAM / 2 * 0.95, ydeck - 0.14, z - 0.07), (BEAM / 2 * 0.95, ydeck, z + 0.07), 0.5)
    # the cabin at the stern: walls of planks, a door gap, a roof with a slant
    cz0, cz1, cx = 2.0, 3.6, 0.85
    ch = 1.25
    yb = ydeck + 0.05
    deck.box("planks", (-cx, yb, cz0), (cx, yb + ch, cz0 + 0.06), 0.25)          # front
    deck.box("planks", (-cx, yb, cz1 - 0.06), (-0.25, yb + ch, cz1), 0.25)        # back, door
    deck.box("planks", (0.35, yb, cz1 - 0.06), (cx, yb + ch, cz1), 0.25)
    deck.box("planks", (-0.25, yb + 0.9, cz1 - 0.06), (0.35, yb + ch, cz1), 0.25)
    deck.box("planks", (-cx, yb, cz0), (-cx + 0.06, yb + ch, cz1), 0.25)          # sides
    deck.box("planks", (cx - 0.06, yb, cz0), (cx, yb + ch, cz1), 0.25)
    # a window in each side: a dark pane
    for sx in (-1, 1):
        deck.box("dark", (sx * cx - 0.035, yb + 0.55, cz0 + 0.5), (sx * cx + 0.035, yb + 0.9, cz0 + 1.0))
    roof = lambda p: (p[0], p[1] + 0.12 * p[0] / cx, p[2])
    deck.box("timber", (-cx - 0.1, yb + ch, cz0 - 0.1), (cx + 0.1, yb + ch + 0.07, cz1 + 0.1), 0.5, roof)
    deck.write(os.path.join(out, "wreck_deck.obj"), "wreck.mtl", "wreck_deck")

    # ---- mast stump: snapped 2.2 m above the deck, splinters at the break ----
    mast = Mesh()
    mz = -1.6
    path = [(0.0, ydeck + 0.05 - 0.2, mz), (0.0, ydeck + 1.2, mz), (0.0, ydeck + 2.2, mz)]
    jag = lambda i: [0.0, 0.32, 0.08, 0.45, 0.05, 0.22, 0.0, 0.15][i]
    mast.tube("timber", path, [0.16, 0.15, 0.14], sides=8, uvlen=0.6, jag=jag)
    # the partners: a collar on the deck
    mast.box("timber", (-0.3, ydeck + 0.05, mz - 0.3), (0.3, ydeck + 0.17, mz + 0.3), 0.5)
    mast.write(os.path.join(out, "wreck_mast.obj"), "wreck.mtl", "wreck_mast")

    # ---- the snapped top: along +y from its broken foot (y = 0) to its head, with a yard ----
    spar = Mesh()
    top_len = 5.0
    jag2 = lambda i: -[0.0, 0.3, 0.1, 0.42, 0.02, 0.25, 0.05, 0.18][i]
    pts = [(0.0, top_len - top_len * k / 4, 0.0) for k in range(5)]
    spar.tube("timber", pts, [0.07 + 0.065 * k / 4 for k in range(5)], sides=8, uvlen=0.6, jag=jag2)
    # the yard, still lashed across it
    ypath = [(-1.5 + 3.0 * k / 4, top_len * 0.8, 0.12) for k in range(5)]
    spar.tube("timber", ypath, [0.05, 0.065, 0.07, 0.065, 0.05], sides=6, uvlen=0.6)
    spar.write(os.path.join(out, "wreck_spar.obj"), "wreck.mtl", "wreck_spar")

    write_mtl(os.path.join(out, "wreck.mtl"), [
        ("planks", (1.0, 1.0, 1.0), (0.04, 0.04, 0.04), 12, "wood.png"),
        ("deck", (0.85, 0.85, 0.8), (0.04, 0.04, 0.04), 12, "wood.png"),
        ("timber", (0.75, 0.7, 0.65), (0.03, 0.03, 0.03), 8, "wood.png"),
        ("dark", (0.02, 0.025, 0.03), (0.1, 0.1, 0.1), 40, None)])
    tex_wood(os.path.join(out, "wood.png"))
    return {"wreck_hull": hull, "wreck_deck": deck, "wreck_mast": mast, "wreck_spar": spar}


# ---- rocks ----------------------------------------------------------------------------------


def icosphere(level):
    t = (1 + math.sqrt(5)) / 2
    v = [norm(p) for p in [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                            (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
         (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        mid = {}

        def m(a, b):
            k = (min(a, b), max(a, b))
            if k not in mid:
                v.append(norm(mul(add(v[a], v[b]), 0.5)))
                mid[k] = len(v) - 1
            return mid[k]
        nf = []
        for a, b, c in f:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    return v, f


def lumpy(seed, level, scale, amp, freq, flat_bottom, facets=False):
    """a displaced icosphere: random low-frequency lobes (sums of directional cosines), scaled,
    its underside flattened so it sits on the sand (base y = 0)"""
    rng = random.Random(seed)
    v, f = icosphere(level)
    lobes = [(norm((rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))), rng.uniform(0, 6.28),
              freq * rng.uniform(0.6, 1.6)) for _ in range(9)]
    pts = []
    for p in v:
        d = 1.0
        for k, (dirv, ph, fr) in enumerate(lobes):
            d += amp / (1 + 0.5 * k) * math.cos(fr * dot(p, dirv) * math.pi + ph)
        q = (p[0] * d * scale[0], p[1] * d * scale[1], p[2] * d * scale[2])
        pts.append(q)
    ymin = min(p[1] for p in pts)
    cut = ymin + flat_bottom * (max(p[1] for p in pts) - ymin)
    pts = [(p[0], max(p[1], cut) - cut, p[2]) for p in pts]
    return pts, f


def rock_mesh(pts, f, mat, facets):
    """box-mapped uvs (each face by its dominant axis), smooth or faceted normals"""
    m = Mesh()
    vn = [(0.0, 0.0, 0.0)] * len(pts)
    for a, b, c in f:
        n = cross(sub(pts[b], pts[a]), sub(pts[c], pts[a]))
        for i in (a, b, c):
            vn[i] = add(vn[i], n)
    vn = [norm(n) for n in vn]
    for a, b, c in f:
        fn = norm(cross(sub(pts[b], pts[a]), sub(pts[c], pts[a])))
        ax = max(range(3), key=lambda k: abs(fn[k]))
        uvf = lambda p: ((p[2], p[1]) if ax == 0 else (p[0], p[2]) if ax == 1 else (p[0], p[1]))
        ids = []
        for i in (a, b, c):
            u = uvf(pts[i])
            ids.append(m.vertex(pts[i], (u[0] * 0.6, u[1] * 0.6), fn if facets else vn[i]))
        m.tri(mat, *ids)
    return m


def make_rocks(out):
    meshes = {}
    pts, f = lumpy(101, 3, (1.0, 0.75, 0.9), 0.09, 1.3, 0.12)
    meshes["rock_boulder"] = rock_mesh(pts, f, "rock", False)
    pts, f = lumpy(202, 3, (1.6, 0.45, 1.1), 0.07, 1.1, 0.2)
    meshes["rock_slab"] = rock_mesh(pts, f, "rock_pale", False)
    pts, f = lumpy(303, 2, (0.6, 1.8, 0.55), 0.16, 2.1, 0.05)
    meshes["rock_spire"] = rock_mesh(pts, f, "rock_dark", True)
    for name, m in meshes.items():
        m.write(os.path.join(out, name + ".obj"), "rocks.mtl", name)
    write_mtl(os.path.join(out, "rocks.mtl"), [
        ("rock", (1.0, 1.0, 1.0), (0.05, 0.05, 0.05), 20, "rock.png"),
        ("rock_pale", (1.15, 1.1, 1.0), (0.05, 0.05, 0.05), 20, "rock.png"),
        ("rock_dark", (0.7, 0.7, 0.72), (0.06, 0.06, 0.06), 24, "rock.png")])
    tex_speckle(os.path.join(out, "rock.png"), 41, (0.32, 0.29, 0.25), (0.08, 0.08, 0.08),
                (0.7, 0.68, 0.6), growth=(0.12, 0.2, 0.08))
    return meshes


# ---- plants ---------------------------------------------------------------------------------


def blade(m, mat, base, up, side, length, width, segs, curl, ruffle=0.0, seed=0, taper=0.85):
    """a ribbon from base along up (bent by curl toward its side's normal), width across side;
    u across, v along; normals smooth across the ribbon's grid"""
    rng = random.Random(seed)
    up, side = norm(up), norm(side)
    out_n = norm(cross(side, up))
    rows, uvs = [], []
    p, d = base, up
    for k in range(segs + 1):
        t = k / segs
        w = width * (0.25 + 0.75 * math.sin(math.pi * min(1.0, 0.15 + t)) if taper else 1) * (1 - taper * t ** 3)
        ruf = ruffle * math.sin(t * 23 + rng.random()) * t
        a = add(add(p, mul(side, -w / 2)), mul(out_n, ruf))
        b = add(add(p, mul(side, w / 2)), mul(out_n, -ruf))
        mid = add(p, mul(out_n, 0.2 * w))
        rows.append([a, mid, b])
        uvs.append([(0.0, t), (0.5, t), (1.0, t)])
        d = norm(add(d, mul(out_n, curl / segs)))
        p = add(p, mul(d, length / segs))
    m.grid(mat, [list(x) for x in zip(*rows)], [list(x) for x in zip(*uvs)])


def make_kelp(out):
    """giant kelp (Macrocystis): a thin stipe rising 3.6 m with long blades on alternating sides,
    each at a gas bladder, and a few blades at the top"""
    rng = random.Random(5)
    m = Mesh()
    H = 3.6
    stipe = [(0.04 * math.sin(k * 0.9), H * k / 12, 0.03 * math.cos(k * 0.7)) for k in range(13)]
    m.tube("stipe", stipe, [0.018 - 0.006 * k / 12 for k in range(13)], sides=5, uvlen=0.5)
    # the holdfast: a small lumpy cone of roots at the base
    for k in range(7):
        a = 2 * math.pi * k / 7 + rng.random() * 0.4
        path = [(0.14 * math.cos(a), 0.0, 0.14 * math.sin(a)), (0.06 * math.cos(a), 0.06, 0.06 * math.sin(a)),
                (0.0, 0.12, 0.0)]
        m.tube("stipe", path, [0.018, 0.02, 0.02], sides=4, cap_end=False)
    n = 11
    for k in range(n):
        y = 0.35 + (H - 0.5) * k / (n - 1)
        p = stipe[min(12, int(y / H * 12))]
        p = (p[0], y, p[2])
        az = k * 2.4 + rng.uniform(-0.3, 0.3)  # golden angle: blades all around
        out_d = (math.cos(az), 0.0, math.sin(az))
        up = norm(add(mul(out_d, 0.5), (0, 1.0, 0)))
        side = cross(up, out_d)
        side = norm(cross(out_d, (0, 1, 0))) if dot(side, side) < 1e-6 else norm(side)
        # the bladder (pneumatocyst): where the blade joins the stipe
        bl = add(p, mul(out_d, 0.03))
        m.tube("bladder", [add(bl, (0, -0.03, 0)), bl, add(bl, (0, 0.04, 0))], [0.006, 0.022, 0.004], sides=5,
               cap_end=False)
        L = rng.uniform(0.55, 0.85)
        blade(m, "blade", add(bl, (0, 0.03, 0)), up, side, L, rng.uniform(0.09, 0.13), 8,
              -0.6 + 0.3 * rng.random(), ruffle=0.012, seed=k)
    # the crown: a few blades trailing from the top
    for k in range(3):
        az = 1.0 + 2.1 * k
        out_d = (math.cos(az), 0.0, math.sin(az))
        up = norm(add(mul(out_d, 0.7), (0, 1.0, 0)))
        blade(m, "blade", stipe[-1], up, norm(cross(up, out_d)), 0.5, 0.08, 6, -0.8, ruffle=0.01,
              seed=20 + k)
    m.write(os.path.join(out, "kelp.obj"), "plants.mtl", "kelp")
    return m


def make_seaweed(out):
    """a clump of eelgrass-like blades, 0.4 to 0.75 m, curving outward from a common base"""
    rng = random.Random(9)
    m = Mesh()
    for k in range(11):
        az = 2 * math.pi * k / 11 + rng.uniform(-0.3, 0.3)
        r = rng.uniform(0.0, 0.08)
        base = (r * math.cos(az), 0.0, r * math.sin(az))
        out_d = (math.cos(az), 0.0, math.sin(az))
        up = norm(add(mul(out_d, rng.uniform(0.1, 0.35)), (0, 1, 0)))
        side = norm(cross(up, out_d))
        # curl toward the outside: the blade's own normal turned to face out
        blade(m, "weed", base, up, side, rng.uniform(0.4, 0.75), rng.uniform(0.035, 0.05), 7,
              rng.uniform(-0.9, -0.4), seed=100 + k, taper=0.9)
    m.write(os.path.join(out, "seaweed.obj"), "plants.mtl", "seaweed")
    return m


# ---- starfish and coral ---------------------------------------------------------------------


def make_starfish(out, name, mat):
    """five arms (R = 0.16 m), flat underside on y = 0, a domed back that thins to the tips"""
    m = Mesh()
    R, r_in, H = 0.16, 0.045, 0.035
    na, nr = 60, 5
    rows, uvs = [], []
    for j in range(nr + 1):
        t = j / nr
        row, uv = [], []
        for i in range(na + 1):
            ph = 2 * math.pi * i / na
            arm = ((1 + math.cos(5 * ph)) / 2) ** 1.6
            rad = (r_in + (R - r_in) * arm) * t
            wig = 0.012 * math.sin(ph * 5 + 1.3) * t * arm  # arms curl a little
            y = H * (1 - t ** 2) ** 0.7 * (0.45 + 0.55 * arm) * (1 - 0.55 * t) + 0.002
            x, z = rad * math.cos(ph + wig), rad * math.sin(ph + wig)
            row.append((x, y if j < nr else 0.002, z))
            uv.append((x * 3 + 0.5, z * 3 + 0.5))
        rows.append(row)
        uvs.append(uv)
    idx = m.grid("top", rows, uvs)
    for line in idx:  # the seam column shares its normal
        nn = norm(add(m.vn[line[0]], m.vn[line[-1]]))
        m.vn[line[0]] = m.vn[line[-1]] = nn
    for k in idx[0]:  # the centre, one point in every column: straight up
        m.vn[k] = (0.0, 1.0, 0.0)
    # the underside: a flat fan (seen from below only through the sand, cheap)
    c = m.vertex((0.0, 0.0, 0.0), (0.5, 0.5), (0, -1, 0))
    edge = [m.vertex((p[0], 0.0, p[2]), (0.5, 0.5), (0, -1, 0)) for p in rows[-1][:-1]]
    for i in range(na):
        m.tri("under", c, edge[(i + 1) % na], edge[i])
    m.write(os.path.join(out, name + ".obj"), name + ".mtl", name)
    return m


def make_coral_branch(out):
    """branching (staghorn-like) coral: a short trunk splitting three times, tapering tubes
    with rounded tips; about 0.8 m tall"""
    rng = random.Random(13)
    m = Mesh()

    def grow(p, d, length, radius, depth):
        n = 2
        path, radii = [p], [radius]
        for k in range(1, n + 1):
            d = norm(add(d, (rng.uniform(-0.15, 0.15), 0.12, rng.uniform(-0.15, 0.15))))
            p = add(p, mul(d, length / n))
            path.append(p)
            radii.append(radius * (1 - 0.25 * k / n))
        if depth == 0:  # a rounded tip
            path.append(add(p, mul(d, radius * 0.6)))
            radii.append(radius * 0.35)
        m.tube("coral", path, radii, sides=5, cap_end=depth == 0, uvlen=0.3)
        if depth == 0:
            return
        for b in range(rng.choice((2, 2, 3))):
            az = rng.uniform(0, 2 * math.pi)
            nd = norm(add(d, (0.8 * math.cos(az), 0.15, 0.8 * math.sin(az))))
            grow(path[-1], nd, length * rng.uniform(0.65, 0.85), radii[-1] * 0.9, depth - 1)

    for k in range(3):
        az = 2 * math.pi * k / 3 + 0.4
        base = (0.08 * math.cos(az), 0.0, 0.08 * math.sin(az))
        grow(base, norm((0.35 * math.cos(az), 1.0, 0.35 * math.sin(az))), 0.28, 0.04, 3)
    m.write(os.path.join(out, "coral_branch.obj"), "coral.mtl", "coral_branch")
    return m


def make_coral_fan(out):
    """a sea fan (gorgonian): a short stem splitting again and again in one plane (x, y) into a
    fan of thin twigs, about 0.9 m tall and 1 m wide; flexible, so it may sway"""
    rng = random.Random(17)
    m = Mesh()

    def grow(p, ang, length, radius, depth):
        d = (math.sin(ang), math.cos(ang), 0.0)
        path, radii = [p], [radius]
        for k in range(1, 4):
            wob = (0.0, 0.0, rng.uniform(-0.015, 0.015))
            p = add(add(p, mul(d, length / 3)), wob)
            path.append(p)
            radii.append(radius * (1 - 0.2 * k / 3))
        m.tube("fan", path, radii, sides=3, cap_end=depth == 0, uvlen=0.3)
        if depth == 0:
            return
        spread = 0.35 + 0.1 * rng.random()
        for side in (-1, 1):
            grow(p, ang + side * spread * rng.uniform(0.7, 1.1), length * rng.uniform(0.75, 0.9),
                 radius * 0.75, depth - 1)

    grow((0.0, 0.0, 0.0), 0.0, 0.22, 0.025, 4)
    m.write(os.path.join(out, "coral_fan.obj"), "coral.mtl", "coral_fan")
    return m


def make_coral_brain(out):
    """brain coral: a squat dome (0.9 m across) whose surface folds in meandering ridges"""
    m = Mesh()
    n = Noise(31, 8)
    nu, nv = 44, 14
    rows, uvs = [], []
    for j in range(nv + 1):
        th = (math.pi / 2) * j / nv  # 0 at the rim, pi/2 at the top
        row, uv = [], []
        for i in range(nu + 1):
            ph = 2 * math.pi * i / nu
            x, y, z = math.cos(th) * math.cos(ph), math.sin(th), math.cos(th) * math.sin(ph)
            u, v = x * 0.5 + 0.5, z * 0.5 + 0.5
            ridge = math.sin((u * 10 + 1.5 * fbm(n, u * 4, v * 4, 3) * 4) * 2 * math.pi)
            d = 1 + 0.03 * ridge * (1 if j > 0 else 0)
            row.append((0.45 * x * d, 0.32 * y * d, 0.45 * z * d))
            uv.append((u, v))
        rows.append(row)
        uvs.append(uv)
    idx = m.grid("brain", rows, uvs)
    for line in idx:
        nn = norm(add(m.vn[line[0]], m.vn[line[-1]]))
        m.vn[line[0]] = m.vn[line[-1]] = nn
    top = idx[-1]  # the pole: all one normal
    for k in top:
        m.vn[k] = (0.0, 1.0, 0.0)
    m.write(os.path.join(out, "coral_brain.obj"), "coral.mtl", "coral_brain")
    return m


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "models")
    os.makedirs(out, exist_ok=True)
    meshes = {}
    meshes.update(make_wreck(out))
    meshes.update(make_rocks(out))
    meshes["kelp"] = make_kelp(out)
    meshes["seaweed"] = make_seaweed(out)
    write_mtl(os.path.join(out, "plants.mtl"), [
        ("stipe", (0.55, 0.45, 0.2), (0.03, 0.03, 0.03), 10, None),
        ("bladder", (0.6, 0.5, 0.18), (0.2, 0.2, 0.2), 40, None),
        ("blade", (1.0, 1.0, 1.0), (0.06, 0.06, 0.05), 16, "kelp.png"),
        ("weed", (0.6, 1.0, 0.55), (0.05, 0.05, 0.05), 16, "kelp.png")])
    tex_blade(os.path.join(out, "kelp.png"), 32, 128, (0.42, 0.32, 0.07), (0.25, 0.2, 0.04),
              (0.5, 0.42, 0.12))
    meshes["starfish"] = make_starfish(out, "starfish", "top")
    write_mtl(os.path.join(out, "starfish.mtl"), [
        ("top", (1.0, 1.0, 1.0), (0.15, 0.12, 0.1), 30, "starfish.png"),
        ("under", (0.8, 0.55, 0.4), (0.0, 0.0, 0.0), 1, None)])
    tex_dots(os.path.join(out, "starfish.png"), 64, (0.85, 0.1, 0.02), (0.95, 0.4, 0.15), 17)
    meshes["starfish_purple"] = make_starfish(out, "starfish_purple", "top")
    write_mtl(os.path.join(out, "starfish_purple.mtl"), [
        ("top", (1.0, 1.0, 1.0), (0.15, 0.12, 0.1), 30, "starfish_purple.png"),
        ("under", (0.6, 0.45, 0.55), (0.0, 0.0, 0.0), 1, None)])
    tex_dots(os.path.join(out, "starfish_purple.png"), 64, (0.32, 0.06, 0.35), (0.75, 0.5, 0.8), 18)
    meshes["coral_branch"] = make_coral_branch(out)
    meshes["coral_brain"] = make_coral_brain(out)
    meshes["coral_fan"] = make_coral_fan(out)
    write_mtl(os.path.join(out, "coral.mtl"), [
        ("coral", (0.95, 0.42, 0.38), (0.08, 0.08, 0.08), 20, None),
        ("brain", (1.0, 1.0, 1.0), (0.06, 0.06, 0.06), 16, "brain.png"),
        ("fan", (0.55, 0.12, 0.6), (0.05, 0.05, 0.05), 16, None)])
    tex_brain(os.path.join(out, "brain.png"))
    for name in sorted(meshes):
        lo, hi = meshes[name].bounds()
        print("%-16s %6d triangles  bounds [%s] .. [%s]" % (
            name, meshes[name].triangles(), ", ".join("%.2f" % x for x in lo),
            ", ".join("%.2f" % x for x in hi)))


if __name__ == "__main__":
    main()
