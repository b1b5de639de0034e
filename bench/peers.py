# SPDX-License-Identifier: MIT
"""peers.py: the planar peers of oi_sun_fraction, timed in the same run as the
runtime (make bench, bench/run_bench.py).

numpy Montenbruck & Gill: the conical shadow of Montenbruck, O. & Gill, E.
2000, Satellite Orbits, Springer, sec. 3.4.2 (eq. 3.85-3.87), written over
numpy arrays: apparent radii a = asin(R_sun / |s - r|), b = asin(R_E / |r|),
separation c = acos(-r . (s - r) / (|r| |s - r|)); lit when c >= a + b,
umbra when c <= b - a, else the planar two-circle overlap
A = a^2 acos(x / a) + b^2 acos((c - x) / b) - c y, x = (c^2 + a^2 - b^2) / (2 c),
y = sqrt(a^2 - x^2), fraction 1 - A / (pi a^2). The annular case (c < a - b)
does not occur at the benchmark's distances.

Orekit (Maven, org.orekit:orekit 12.2) and Basilisk (PyPI wheel bsk 2.12.1)
install on the benchmark machine, but no harness for them is written yet: not
timed here (docs/performance.md).
"""
import numpy as np

from timing import interleaved_seconds, tile_rows

R_SUN_KM = 695700.0
R_EARTH_KM = 6378.137


def mg_fraction(sun, r):
    """Visible fraction of the Sun, Montenbruck & Gill's conical model;
    sun, r: (n, 3) arrays (km). Returns (n,) fractions."""
    rel = sun - r
    d_rel = np.sqrt(np.einsum("ij,ij->i", rel, rel))
    d_r = np.sqrt(np.einsum("ij,ij->i", r, r))
    a = np.arcsin(R_SUN_KM / d_rel)
    b = np.arcsin(R_EARTH_KM / d_r)
    c = np.arccos(np.clip(-np.einsum("ij,ij->i", r, rel) / (d_r * d_rel), -1.0, 1.0))
    x = (c * c + a * a - b * b) / (2.0 * c)
    y = np.sqrt(np.maximum(a * a - x * x, 0.0))
    area = (a * a * np.arccos(np.clip(x / a, -1.0, 1.0))
            + b * b * np.arccos(np.clip((c - x) / b, -1.0, 1.0)) - c * y)
    frac = 1.0 - area / (np.pi * a * a)
    return np.where(c >= a + b, 1.0, np.where(c <= b - a, 0.0, frac))


def time_pair(f, g, n, reps=15, best=False):
    """Median (best=True: least) wall time per point (ns) of f() and of g(),
    their calls interleaved so that the machine's load falls on both alike.
    The least is the call other jobs on the cores disturbed least: on a
    loaded machine the medians carry the other jobs' time slices."""
    tf, tg = interleaved_seconds(f, g, reps)
    k = 0 if best else reps // 2
    return tf[k] * 1e9 / n, tg[k] * 1e9 / n


def orbit_points(n, seed=7):
    """n points along orbits sampled uniformly in time (what a catalogue's
    epochs are): circular LEO (400-1,500 km, any inclination) and GEO, a
    tenth of them each in MEO, the Sun at 1 AU in a random direction per
    orbit. Returns sun, r: (n, 3) km. Most points are lit, some in the
    umbra, a few tenths of a per cent in the penumbra."""
    rng = np.random.default_rng(seed)
    per = 1000
    m = -(-n // per)
    a = np.where(rng.uniform(size=m) < 0.8, R_EARTH_KM + rng.uniform(400, 1500, m),
                 np.where(rng.uniform(size=m) < 0.5, 42164.0, 26560.0))
    inc = rng.uniform(0, np.pi, m)
    raan = rng.uniform(0, 2 * np.pi, m)
    u = rng.uniform(0, 2 * np.pi, (m, 1)) + np.linspace(0, 2 * np.pi, per, endpoint=False)
    x, y = np.cos(u), np.sin(u)
    ci, si, cr, sr = np.cos(inc)[:, None], np.sin(inc)[:, None], np.cos(raan)[:, None], np.sin(raan)[:, None]
    r = np.stack([cr * x - sr * ci * y, sr * x + cr * ci * y, si * y], axis=-1) * a[:, None, None]
    s = rng.normal(size=(m, 3))
    s /= np.linalg.norm(s, axis=1)[:, None]
    sun = np.broadcast_to((s * 149597870.7)[:, None, :], r.shape)
    return (np.ascontiguousarray(sun.reshape(-1, 3)[:n]),
            np.ascontiguousarray(r.reshape(-1, 3)[:n]))


def run(points, out, n=100000):
    """points: rows (light, sun[3], target[3], orbillum fraction) from
    `bench points`; the mix tiled to n points. Puts the peer's ns per point,
    its largest difference from orbillum's exact fraction, and its cost over
    oi_sun_fraction_batch's (outputs mask 0) on the same n points, the two
    timed in turn in this process (through the binding's library): the
    ratio the goal reads. Also over the in-cache medians of bench/bench.c."""
    sun = np.array([p[1] for p in points], dtype=float)
    r = np.array([p[2] for p in points], dtype=float)
    ours = np.array([p[3] for p in points], dtype=float)
    diff = float(np.abs(mg_fraction(sun, r) - ours).max())
    sun_n = tile_rows(sun, n)
    r_n = tile_rows(r, n)
    out.put("peer.numpy_mg.sun_fraction.max_diff_vs_orbillum", "%.2g" % diff, "1",
            "|M&G - oi_sun_fraction| over the mix (the planar approximation)")
    try:
        import orbillum
    except Exception as e:  # the binding is built by `make binding`
        out.put("peer.numpy_mg.same_rows", "unavailable", "-", "import orbillum: %s" % e)
        return
    lib, L = orbillum._lib, orbillum.L
    sh = np.empty(n, dtype=np.dtype(L.oi_shadow))
    st = np.empty(n, dtype=np.intc)

    def ours_batch():
        lib.oi_sun_fraction_batch(n, sun_n.ctypes.data, r_n.ctypes.data, None, 0,
                                  sh.ctypes.data, st.ctypes.data)

    ns_peer, ns_ours = time_pair(lambda: mg_fraction(sun_n, r_n), ours_batch, n)
    out.put("peer.numpy_mg.sun_fraction.ns_per_point", "%.1f" % ns_peer, "ns",
            "numpy Montenbruck & Gill conical (planar), %d points, median of 15 calls" % n)
    out.put("peer.orbillum.sun_fraction_batch.ns_per_point", "%.1f" % ns_ours, "ns",
            "oi_sun_fraction_batch, outputs mask 0, the same %d points, calls interleaved" % n)
    out.put("peer.numpy_mg.over.sun_fraction_batch_same_rows", "%.2f" % (ns_peer / ns_ours), "x",
            "peer ns / orbillum ns on the same points (a third in the penumbra); > 1: "
            "orbillum faster")
    # the same without the penumbra third (a catalogue's epochs are almost all lit or
    # in the umbra: the penumbra lasts seconds of an orbit)
    keep = np.array([p[0] != "penumbra" for p in points])
    sun_n[:] = tile_rows(sun[keep], n)
    r_n[:] = tile_rows(r[keep], n)
    ns_peer2, ns_ours2 = time_pair(lambda: mg_fraction(sun_n, r_n), ours_batch, n)
    out.put("peer.numpy_mg.over.sun_fraction_batch_lit_umbra", "%.2f" % (ns_peer2 / ns_ours2),
            "x", "the same on the lit and umbra points only: peer %.1f ns, orbillum %.1f ns"
            % (ns_peer2, ns_ours2))
    # the same pairs, the least of the 15 calls of each (the least disturbed by
    # other jobs on a shared machine)
    sun_n[:] = tile_rows(sun, n)
    r_n[:] = tile_rows(r, n)
    b_peer, b_ours = time_pair(lambda: mg_fraction(sun_n, r_n), ours_batch, n, best=True)
    out.put("peer.numpy_mg.over.sun_fraction_batch_same_rows_best", "%.2f" % (b_peer / b_ours),
            "x", "the mix, least of 15 calls each: peer %.1f ns, orbillum %.1f ns"
            % (b_peer, b_ours))
    sun_n[:] = tile_rows(sun[keep], n)
    r_n[:] = tile_rows(r[keep], n)
    b_peer, b_ours = time_pair(lambda: mg_fraction(sun_n, r_n), ours_batch, n, best=True)
    out.put("peer.numpy_mg.over.sun_fraction_batch_lit_umbra_best", "%.2f" % (b_peer / b_ours),
            "x", "lit and umbra points, least of 15 calls each: peer %.1f ns, orbillum %.1f ns"
            % (b_peer, b_ours))
    # points along orbits, uniform in time
    sun_o, r_o = orbit_points(n)
    sun_n[:] = sun_o
    r_n[:] = r_o
    ours_batch()
    pen = float(np.mean(sh["region"] == 1))
    m_peer, m_ours = time_pair(lambda: mg_fraction(sun_n, r_n), ours_batch, n)
    b_peer, b_ours = time_pair(lambda: mg_fraction(sun_n, r_n), ours_batch, n, best=True)
    out.put("peer.numpy_mg.over.sun_fraction_batch_orbits", "%.2f" % (m_peer / m_ours), "x",
            "%d points along LEO/MEO/GEO orbits uniform in time (%.2f %% penumbra), medians: "
            "peer %.1f ns, orbillum %.1f ns" % (n, 100 * pen, m_peer, m_ours))
    out.put("peer.numpy_mg.over.sun_fraction_batch_orbits_best", "%.2f" % (b_peer / b_ours), "x",
            "the same, least of 15 calls each: peer %.1f ns, orbillum %.1f ns" % (b_peer, b_ours))
    for cfg in ("sun_fraction_batch", "sun_fraction"):
        d = out.data.get("bench.double.%s.ns_median" % cfg)
        if d:
            out.put("peer.numpy_mg.over.%s_in_cache" % cfg, "%.2f" % (ns_peer / float(d["value"])),
                    "x", "peer ns / bench.c's in-cache median over the 72-scene mix (another "
                    "harness: indicative only)")
