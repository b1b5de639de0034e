# SPDX-License-Identifier: MIT
"""The Sun fraction's process peers (bench/peers.py, bench/peers/, bench/peers_basilisk.py)
compute the planar model they are named for: on points across the Earth's penumbra in
LEO and GEO, each harness's fractions against numpy Montenbruck & Gill (bench/peers.py's
mg_fraction) at the peer's own radii. The Orekit harness is built here when java and mvn
are found (skipped otherwise); the Basilisk one runs when `make peers` has made its venv.
"""
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))
import peers  # noqa: E402

BUILD = Path(os.environ.get("BUILDDIR", ROOT / "build"))
if not BUILD.is_absolute():
    BUILD = ROOT / BUILD
PEERS_DIR = BUILD / "peers"
TOL = 1e-7  # the two forms of the same planar formula, near the umbra's edge (fraction ~1e-5)


def penumbra_points():
    """The Sun at 1 AU on +x; targets on the night side at 7,000 km (LEO) and
    42,164 km (GEO), their distance from the shadow's axis stepped through
    the umbra, the penumbra and out into sunlight. Returns sun, r (km)."""
    rows = []
    for radius, offsets in ((7000.0, np.arange(6300.0, 6470.0, 10.0)),
                            (42164.0, np.arange(6100.0, 6700.0, 50.0))):
        for y in offsets:
            rows.append((-np.sqrt(radius * radius - y * y), y, 0.0))
    r = np.array(rows)
    sun = np.ascontiguousarray(np.broadcast_to([peers.AU_KM, 0.0, 0.0], r.shape))
    return sun, r


def check_covers(f):
    """The points reach the umbra, sunlight and the penumbra between."""
    assert (f == 0.0).any() and (f == 1.0).any()
    assert ((f > 0.05) & (f < 0.95)).sum() >= 8


def test_one_sun_keeps_the_geometry():
    rng = np.random.default_rng(3)
    s = rng.normal(size=(500, 3))
    s *= peers.AU_KM / np.linalg.norm(s, axis=1)[:, None]
    r = rng.normal(size=(500, 3))
    r *= rng.uniform(6500.0, 45000.0, (500, 1)) / np.linalg.norm(r, axis=1)[:, None]
    s1, r1 = peers.one_sun(s, r)
    assert np.all(s1 == [peers.AU_KM, 0.0, 0.0])
    np.testing.assert_allclose(np.linalg.norm(r1, axis=1), np.linalg.norm(r, axis=1), rtol=1e-13)
    cos0 = np.einsum("ij,ij->i", r, s) / (np.linalg.norm(r, axis=1) * peers.AU_KM)
    np.testing.assert_allclose(r1[:, 0] / np.linalg.norm(r1, axis=1), cos0, atol=1e-13)
    np.testing.assert_allclose(peers.mg_fraction(s1, r1), peers.mg_fraction(s, r), atol=1e-12)


def run_harness(cmd, sun, r):
    with tempfile.TemporaryDirectory() as tmp:
        frac, ns_med, ns_best = peers.run_peer(cmd, sun, r, tmp, reps=1)
    assert ns_med > 0.0 and ns_best > 0.0
    return frac


@pytest.mark.skipif(not (shutil.which("java") and shutil.which("mvn")), reason="java or mvn not found")
def test_orekit_harness_is_montenbruck_gill():
    # the target as the Makefile spells it (BUILDDIR as given, relative by default)
    target = os.path.join(os.environ.get("BUILDDIR", "build"), "peers", "orekit", "classpath.txt")
    p = subprocess.run(["make", "--no-print-directory", target],
                       cwd=ROOT, capture_output=True, text=True, timeout=900)
    assert p.returncode == 0, p.stdout + p.stderr
    cmd, why = peers.orekit_command(str(PEERS_DIR))
    assert cmd, why
    sun, r = penumbra_points()
    want = peers.mg_fraction(sun, r)
    check_covers(want)
    got = run_harness(cmd, sun, r)
    assert np.abs(got - want).max() <= TOL, np.abs(got - want).max()
    # the harness reads each row's own Sun: the same points turned elsewhere give the same
    rng = np.random.default_rng(5)
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    got_turned = run_harness(cmd, np.ascontiguousarray(sun @ q.T), np.ascontiguousarray(r @ q.T))
    assert np.abs(got_turned - want).max() <= TOL


@pytest.mark.skipif(not (PEERS_DIR.parent / "peers-venv" / ".deps").exists(),
                    reason="the Basilisk venv is not made (make peers)")
def test_basilisk_harness_is_montenbruck_gill():
    cmd, why = peers.basilisk_command(str(PEERS_DIR))
    assert cmd, why
    sun, r = penumbra_points()
    want = peers.mg_fraction(sun, r, peers.BASILISK_R_SUN_KM, peers.BASILISK_R_EARTH_KM)
    check_covers(want)
    got = run_harness(cmd, sun, r)
    assert np.abs(got - want).max() <= TOL, np.abs(got - want).max()
    # at orbillum's radii the module would differ by more than the tolerance: the radii matter
    assert np.abs(got - peers.mg_fraction(sun, r)).max() > 100 * TOL
