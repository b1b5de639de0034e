# SPDX-License-Identifier: MIT
"""python -m bake: bake the earthshine tables into tables/ (generated C).

  python -m bake                       default table (bake/config/default.json)
  python -m bake --scene FILE          only a mission's altitude band and goal
  python -m bake --all                 default table and every bake/config/scene_*.json
  python -m bake --out DIR             write somewhere else (check-tables)
  python -m bake --method photon       photon mapping (bake/photon.py) for the node values
"""

import argparse
import glob
import os
import sys
import time

from . import scene

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DEFAULT_CFG = os.path.join(HERE, "config", "default.json")


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m bake", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "tables"), help="output folder (tables/)")
    ap.add_argument("--scene", action="append", default=[], metavar="FILE",
                    help="bake a scene configuration (repeatable)")
    ap.add_argument("--all", action="store_true", help="default table and every config/scene_*.json")
    ap.add_argument("--config", default=DEFAULT_CFG, help="default table configuration")
    ap.add_argument("--method", choices=("quadrature", "photon"), default="quadrature")
    ap.add_argument("--photons", type=int, default=None, help="photon count (--method photon)")
    ap.add_argument("--seed", type=int, default=None, help="photon random seed (--method photon)")
    ap.add_argument("--progress", action="store_true", default=None,
                    help="force the progress bar (default: when stderr is a terminal)")
    ap.add_argument("-q", "--quiet", action="store_true")
    a = ap.parse_args(argv)

    log = (lambda *x: None) if a.quiet else (lambda s: print(s, flush=True))
    photon_args = {}
    if a.photons is not None:
        photon_args["n_photons"] = a.photons
    if a.seed is not None:
        photon_args["seed"] = a.seed

    t0 = time.monotonic()
    default_cfg = scene.load(a.config)
    jobs = []
    if a.all or not a.scene:
        jobs.append(("default", default_cfg))
    scenes = list(a.scene)
    if a.all:
        scenes += sorted(glob.glob(os.path.join(HERE, "config", "scene_*.json")))
    for path in scenes:
        jobs.append((path, scene.load(path)))

    default_bytes = None
    for label, cfg in jobs:
        _, meta = scene.bake(cfg, a.out, a.method, log, a.progress, photon_args)
        if label == "default":
            default_bytes = meta["payload_bytes"]
        else:
            ref_bytes = default_bytes
            if ref_bytes is None:
                g = default_cfg["grid"]
                ref_bytes = 8 * (g["n_lit"] + g["n_term"]) * g["n_alt"]
            log("  %s: %d bytes instead of %d for the default table: %d bytes saved (%.0f %%)" % (
                cfg["name"], meta["payload_bytes"], ref_bytes, ref_bytes - meta["payload_bytes"],
                100.0 * (ref_bytes - meta["payload_bytes"]) / ref_bytes))
    log("baked %d table(s) into %s in %.1f s" % (len(jobs), a.out, time.monotonic() - t0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
