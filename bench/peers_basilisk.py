# SPDX-License-Identifier: MIT
"""peers_basilisk.py: Basilisk's eclipse module (bsk 2.12.1, Basilisk.simulation.eclipse)
over the points of a file, in one batch call: every row a spacecraft state message
subscribed to one Eclipse module, one Sun and the Earth, and one UpdateState computing
the shadow factor of every row. The module takes the Earth's radius from the planet's
name (6378.1366 km) and the Sun's as 695,000 km: bench/peers.py compares it with numpy
Montenbruck & Gill at those radii.
Run by bench/peers.py under the peers' own venv (build/peers-venv, from
bench/peers/requirements-basilisk.txt: Basilisk pins matplotlib, sgp4 and tqdm below
the project's requirements.lock).

Usage: build/peers-venv/bin/python bench/peers_basilisk.py POINTS FRACTIONS [--reps 15]
  [--warmup 2]
POINTS: little-endian doubles, 6 a row (Sun x, y, z, target x, y, z, km, the Earth at the
origin); the module takes one Sun a call, so every row must have the same Sun (bench/peers.py
turns each row about the Earth's centre so that its Sun lies on the same vector).
FRACTIONS: written, one little-endian double a row (shadowFactor). Prints "rows N",
"ns_median X", "ns_best X": ns per row of one UpdateState over all rows (reading the
messages, the shadow factors, writing the output messages).
"""
import argparse
import gc
import sys
import time

import numpy as np
from Basilisk.architecture import messaging
from Basilisk.simulation import eclipse

def setup(pts):
    """The module with one state message per row; returns (module, messages kept alive)."""
    sun = pts[0, 0:3]
    if not np.all(pts[:, 0:3] == sun):
        raise SystemExit("peers_basilisk: the rows do not share one Sun")
    mod = eclipse.Eclipse()
    keep = []
    sun_pl = messaging.SpicePlanetStateMsgPayload()
    sun_pl.PositionVector = [float(x) * 1e3 for x in sun]
    sun_pl.PlanetName = "sun"
    sun_msg = messaging.SpicePlanetStateMsg().write(sun_pl)
    mod.sunInMsg.subscribeTo(sun_msg)
    earth = messaging.SpicePlanetStateMsgPayload()
    earth.PositionVector = [0.0, 0.0, 0.0]
    earth.PlanetName = "earth"
    earth.J20002Pfix = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    earth_msg = messaging.SpicePlanetStateMsg().write(earth)
    mod.addPlanetToModel(earth_msg)
    keep += [sun_pl, sun_msg, earth, earth_msg]
    st = messaging.SCStatesMsgPayload()
    for r in pts[:, 3:6] * 1e3:
        st.r_BN_N = [float(r[0]), float(r[1]), float(r[2])]
        m = messaging.SCStatesMsg().write(st)
        mod.addSpacecraftToModel(m)
        keep.append(m)
    mod.Reset(0)
    return mod, keep


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("points")
    ap.add_argument("fractions")
    ap.add_argument("--reps", type=int, default=15)
    ap.add_argument("--warmup", type=int, default=2)
    args = ap.parse_args()
    pts = np.fromfile(args.points, dtype="<f8").reshape(-1, 6)
    n = len(pts)
    mod, keep = setup(pts)
    # no collection of Python's cycles inside the passes (the kept messages are 2 objects a
    # row: a full collection would add a pass over them to one pass's time and count)
    gc.collect()
    gc.disable()
    for _ in range(args.warmup):
        mod.UpdateState(0)
    t = []
    for _ in range(args.reps):
        t0 = time.perf_counter()
        mod.UpdateState(0)
        t.append((time.perf_counter() - t0) * 1e9 / n)
    gc.enable()
    t.sort()
    out = np.array([mod.eclipseOutMsgs[i].read().shadowFactor for i in range(n)], dtype="<f8")
    out.tofile(args.fractions)
    print("rows %d" % n)
    print("ns_median %.3f" % t[len(t) // 2])
    print("ns_best %.3f" % t[0])
    del keep
    return 0


if __name__ == "__main__":
    sys.exit(main())
