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

Orekit 12.2 (Maven; bench/peers/, ConicallyShadowedLightFluxModel's lighting
ratio in one Java loop) and Basilisk bsk 2.12.1 (PyPI, in build/peers-venv;
bench/peers_basilisk.py, its eclipse module in one UpdateState over every row):
each runs in its own process on the points written here, and
oi_sun_fraction_batch is timed on the same points in this process right after
it. Both are the same planar model; each is compared with mg_fraction at its
own radii (the harness check) and with orbillum's exact fraction. `make
bench-peers` builds both; a peer that is not built is reported unavailable
with the reason.
"""
import os
import subprocess
import tempfile
import time

import numpy as np

from timing import interleaved_seconds, tile_rows

R_SUN_KM = 695700.0
R_EARTH_KM = 6378.137
AU_KM = 149597870.7
# Basilisk's eclipse module's radii (its planet name "earth" and the Sun): mg_fraction at
# these agrees with the module to 6e-10 on the bench's points
BASILISK_R_SUN_KM = 695000.0
BASILISK_R_EARTH_KM = 6378.1366


def mg_fraction(sun, r, r_sun_km=R_SUN_KM, r_earth_km=R_EARTH_KM):
    """Visible fraction of the Sun, Montenbruck & Gill's conical model;
    sun, r: (n, 3) arrays (km). Returns (n,) fractions."""
    rel = sun - r
    d_rel = np.sqrt(np.einsum("ij,ij->i", rel, rel))
    d_r = np.sqrt(np.einsum("ij,ij->i", r, r))
    a = np.arcsin(r_sun_km / d_rel)
    b = np.arcsin(r_earth_km / d_r)
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


def run(points, out, n=100000, peers_dir=None):
    """points: rows (light, sun[3], target[3], orbillum fraction) from
    `bench points`; the mix tiled to n points. Puts the peer's ns per point,
    its largest difference from orbillum's exact fraction, and its cost over
    oi_sun_fraction_batch's (outputs mask 0) on the same n points, the two
    timed in turn in this process (through the binding's library): the
    ratio the goal reads. Also over the in-cache medians of bench/bench.c.
    peers_dir (make's $(BUILDDIR)/peers): the process peers (Orekit,
    Basilisk) on the mix and on the orbit points, when built there."""
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
    if peers_dir:
        def ours(sun_x, r_x):
            m = len(r_x)
            s_c, r_c = np.ascontiguousarray(sun_x), np.ascontiguousarray(r_x)
            sh_x = np.empty(m, dtype=np.dtype(L.oi_shadow))
            st_x = np.empty(m, dtype=np.intc)

            def call():
                lib.oi_sun_fraction_batch(m, s_c.ctypes.data, r_c.ctypes.data, None, 0,
                                          sh_x.ctypes.data, st_x.ctypes.data)
            call()
            return time_alone(call, m), sh_x["fraction"].astype(float)

        process_peers({"same_rows": (tile_rows(sun, n), tile_rows(r, n)), "orbits": (sun_o, r_o)},
                      ours, out, peers_dir)
    for cfg in ("sun_fraction_batch", "sun_fraction"):
        d = out.data.get("bench.double.%s.ns_median" % cfg)
        if d:
            out.put("peer.numpy_mg.over.%s_in_cache" % cfg, "%.2f" % (ns_peer / float(d["value"])),
                    "x", "peer ns / bench.c's in-cache median over the 72-scene mix (another "
                    "harness: indicative only)")


def one_sun(sun, r):
    """The rows turned about the Earth's centre (a reflection per row, which keeps
    every distance and angle from the centre) so that each Sun lies on +x, and
    every Sun put at 1 AU: one Sun for all rows, as Basilisk's eclipse module
    takes it. Exact where the Sun is at 1 AU (the orbit points); the mix's Suns
    (0.98-1.02 AU) move along their line. Returns sun, r: (n, 3) km."""
    a = sun / np.linalg.norm(sun, axis=1)[:, None]
    v = a - np.array([1.0, 0.0, 0.0])
    vv = np.einsum("ij,ij->i", v, v)
    k = np.where(vv > 0.0, 2.0 * np.einsum("ij,ij->i", v, r) / np.where(vv > 0.0, vv, 1.0), 0.0)
    r1 = np.ascontiguousarray(r - k[:, None] * v)
    sun1 = np.ascontiguousarray(np.broadcast_to(np.array([AU_KM, 0.0, 0.0]), r.shape))
    return sun1, r1


def orekit_command(peers_dir):
    """The Java command of the Orekit harness, or (None, why not)."""
    d = os.path.join(peers_dir, "orekit")
    cp_file = os.path.join(d, "classpath.txt")
    if not os.path.isfile(cp_file):
        return None, "not built (%s missing: make bench-peers, needs java and mvn)" % cp_file
    with open(cp_file) as f:
        cp = f.read().strip()
    return ["java", "-cp", os.path.join(d, "classes") + os.pathsep + cp,
            "org.orbillum.peers.OrekitLighting"], None


def basilisk_command(peers_dir):
    """The command of the Basilisk harness under its venv, or (None, why not)."""
    venv = os.path.normpath(os.path.join(peers_dir, "..", "peers-venv"))
    if not os.path.isfile(os.path.join(venv, ".deps")):
        return None, "not installed (%s: make bench-peers)" % venv
    return [os.path.abspath(os.path.join(venv, "bin", "python")), os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                              "peers_basilisk.py")], None


def run_peer(cmd, sun, r, tmp, reps=15):
    """Runs a peer's harness on the rows (sun, r): its fractions and its ns per
    row (median, least of reps passes)."""
    src = os.path.join(tmp, "points.bin")
    dst = os.path.join(tmp, "fractions.bin")
    np.hstack([sun, r]).astype("<f8").tofile(src)
    res = subprocess.run(cmd + [src, dst] + (["--reps", str(reps)] if cmd[-1].endswith(".py")
                                             else [str(reps)]),
                         check=True, capture_output=True, text=True, timeout=900)
    got = dict(line.split(None, 1) for line in res.stdout.splitlines() if " " in line)
    frac = np.fromfile(dst, dtype="<f8")
    if len(frac) != len(r) or int(got["rows"]) != len(r):
        raise RuntimeError("peer wrote %d fractions for %d rows" % (len(frac), len(r)))
    return frac, float(got["ns_median"]), float(got["ns_best"])


def time_alone(f, n, reps=15):
    """ns per point of f() over n points, reps calls (unsorted)."""
    t = []
    for _ in range(reps):
        t0 = time.perf_counter()
        f()
        t.append((time.perf_counter() - t0) * 1e9 / n)
    return t


# the process peers: name, what they run, the radii of their model (for the check
# against mg_fraction), whether they take one Sun for all rows
PROCESS_PEERS = (
    ("orekit", "Orekit 12.2 ConicallyShadowedLightFluxModel lighting ratio, one Java loop "
     "(JIT warmed by 5 passes)", orekit_command, (R_SUN_KM, R_EARTH_KM), False),
    ("basilisk", "Basilisk bsk 2.12.1 eclipse module, one UpdateState over every row",
     basilisk_command, (BASILISK_R_SUN_KM, BASILISK_R_EARTH_KM), True),
)


def process_peers(sets, ours, out, peers_dir):
    """Each process peer on the sets {name: (sun, r)} (n rows each): its ns per
    point and its cost over oi_sun_fraction_batch's (ours(sun, r) -> 15 times
    in ns and the exact fractions), timed on the same rows just before and just
    after the peer's process (the median and the least of those 30 calls, so
    that a change of the machine's load falls on both sides alike); its
    largest difference from mg_fraction at its own radii and from orbillum's
    exact fraction."""
    for name, what, command, radii, single_sun in PROCESS_PEERS:
        cmd, why = command(peers_dir)
        if cmd is None:
            out.put("peer.%s.same_rows" % name, "unavailable", "-", why)
            continue
        with tempfile.TemporaryDirectory() as tmp:
            for set_name, (sun, r) in sets.items():
                if single_sun:
                    sun, r = one_sun(sun, r)
                t_before, exact = ours(sun, r)
                try:
                    frac, ns_med, ns_best = run_peer(cmd, sun, r, tmp)
                except (OSError, subprocess.SubprocessError, RuntimeError, KeyError, ValueError) as e:
                    out.put("peer.%s.%s" % (name, set_name), "unavailable", "-",
                            "%s: %s" % (what, str(e).strip().splitlines()[-1] if str(e).strip() else e))
                    continue
                t_ours = sorted(t_before + ours(sun, r)[0])
                o_med, o_best = 0.5 * (t_ours[14] + t_ours[15]), t_ours[0]
                suffix = "" if set_name == "same_rows" else "_" + set_name
                label = ("the mix tiled to %d points (a third in the penumbra)" % len(r)
                         if set_name == "same_rows" else
                         "%d points along LEO/MEO/GEO orbits uniform in time" % len(r))
                if single_sun:
                    label += ", each row turned so that its Sun is at 1 AU on +x"
                out.put("peer.%s.sun_fraction%s.ns_per_point" % (name, suffix), "%.1f" % ns_med,
                        "ns", "%s; %s, median of 15 passes (least %.1f)" % (what, label, ns_best))
                out.put("peer.%s.over.sun_fraction_batch_%s" % (name, set_name),
                        "%.2f" % (ns_med / o_med), "x",
                        "peer ns / oi_sun_fraction_batch (mask 0) ns on the same rows, medians: "
                        "peer %.1f ns, orbillum %.1f ns (15 calls before it, 15 after); > 1: "
                        "orbillum faster"
                        % (ns_med, o_med))
                out.put("peer.%s.over.sun_fraction_batch_%s_best" % (name, set_name),
                        "%.2f" % (ns_best / o_best), "x",
                        "the same, least of the peer's 15 passes and of orbillum's 30 calls: "
                        "peer %.1f ns, orbillum %.1f ns" % (ns_best, o_best))
                mg = mg_fraction(sun, r, *radii)
                out.put("peer.%s.sun_fraction%s.max_diff_vs_numpy_mg" % (name, suffix),
                        "%.2g" % float(np.abs(frac - mg).max()), "1",
                        "|peer - mg_fraction at the peer's radii (Sun %.1f km, Earth %.4f km)|: "
                        "the harness computes the model it names" % radii)
                out.put("peer.%s.sun_fraction%s.max_diff_vs_orbillum" % (name, suffix),
                        "%.2g" % float(np.abs(frac - exact).max()), "1",
                        "|peer - oi_sun_fraction_batch| on the same rows (planar model, "
                        "the peer's radii)")
