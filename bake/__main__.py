# SPDX-License-Identifier: MIT
"""python -m bake: bake the committed tables (generated C + JSON sidecars).

  python -m bake all                   every table below
  python -m bake earthshine            oi_earth_diffuse (bake/config/default.json), every
                                       mission scene bake/config/scene_*.json and the angular
                                       table oi_earth_angular (bake/earthshine/angular_table.py)
  python -m bake atmosphere            oi_atm_vband and oi_atm_total, the V and the total band
                                       (bake/config/atmosphere.json)
  python -m bake skylight              oi_sky_vband (bake/config/skylight.json): the sunlight the
                                       atmosphere scatters towards a target (bake/skylight/)
  python -m bake --scene FILE          only this mission scene (repeatable): its altitude band
                                       and goal, the smallest grid that meets it (docs/tables.md)
  --root DIR                           write at the repository-relative paths under DIR
                                       (default: the repository, tables land in tables/)
  --list                               print those relative paths, one a line, bake nothing
  --method photon                      node values by photon mapping (bake/photon/)

Progress goes to stderr; a summary line per table to stdout (-q: none).
"""

import argparse
import glob
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CONFIG = os.path.join(HERE, "config")
DEFAULT_CFG = os.path.join(CONFIG, "default.json")
TABLES = "tables"
TARGETS = ("earthshine", "atmosphere", "skylight", "all")


def _earthshine_configs(scenes, all_scenes=True):
    from .earthshine import scenes as sc
    paths = [] if scenes else [DEFAULT_CFG]
    paths += list(scenes) if scenes else (
        sorted(glob.glob(os.path.join(CONFIG, "scene_*.json"))) if all_scenes else [])
    return [(p, sc.load(p)) for p in paths]


def outputs(target, scenes=()):
    """Repository-relative paths a target writes."""
    out = []
    if target in ("earthshine", "all") or scenes:
        for _, cfg in _earthshine_configs(scenes):
            out += ["%s/%s.%s" % (TABLES, cfg["name"], e) for e in ("c", "h", "json")]
        if not scenes:
            from .earthshine import angular_table as ang
            out += ["%s/%s.%s" % (TABLES, ang.NAME, e) for e in ("c", "h", "json")]
    if target in ("atmosphere", "all") and not scenes:
        from .atmosphere import table as at
        out += ["%s/%s.%s" % (TABLES, n, e) for n in at.NAMES for e in ("c", "h", "json")]
    if target in ("skylight", "all") and not scenes:
        from .skylight import table as sk
        out += ["%s/%s.%s" % (TABLES, sk.NAME, e) for e in ("c", "h", "json")]
    return out


def bake_earthshine(outdir, scenes, method, log, progress, photon_args):
    from .earthshine import scenes as sc
    default_bytes = None
    jobs = _earthshine_configs(scenes)
    for path, cfg in jobs:
        _, meta = sc.bake(cfg, outdir, method, log, progress, photon_args)
        if path == DEFAULT_CFG:
            default_bytes = meta["payload_bytes"]
        else:
            ref_bytes = default_bytes
            if ref_bytes is None:
                g = sc.load(DEFAULT_CFG)["grid"]
                ref_bytes = 8 * (g["n_lit"] + g["n_term"]) * g["n_alt"]
            log("  %s: %d bytes instead of %d for the default table: %d bytes saved (%.0f %%)" % (
                cfg["name"], meta["payload_bytes"], ref_bytes, ref_bytes - meta["payload_bytes"],
                100.0 * (ref_bytes - meta["payload_bytes"]) / ref_bytes))
    if not scenes:
        from .earthshine import angular_table as ang
        ang.run(outdir, log=log, progress=progress)
        return len(jobs) + 1
    return len(jobs)


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m bake", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("target", nargs="?", choices=TARGETS, default=None,
                    help="what to bake (default: all, or the --scene files)")
    ap.add_argument("--root", default=ROOT, help="output root (default: the repository)")
    ap.add_argument("--list", action="store_true", help="print the output paths, bake nothing")
    ap.add_argument("--scene", action="append", default=[], metavar="FILE",
                    help="bake a mission scene configuration (repeatable)")
    ap.add_argument("--method", choices=("quadrature", "photon"), default="quadrature",
                    help="earthshine node values (default quadrature)")
    ap.add_argument("--photons", type=int, default=None, help="photon count (--method photon)")
    ap.add_argument("--seed", type=int, default=None, help="photon random seed (--method photon)")
    ap.add_argument("--progress", dest="progress", action="store_true", default=True,
                    help="progress on stderr (default)")
    ap.add_argument("--no-progress", dest="progress", action="store_false")
    ap.add_argument("-q", "--quiet", action="store_true", help="no summary lines, no progress")
    a = ap.parse_args(argv)
    target = a.target or ("earthshine" if a.scene else "all")
    if a.scene and target != "earthshine":
        ap.error("--scene bakes earthshine scenes only")

    if a.list:
        for p in outputs(target, a.scene):
            print(p)
        return 0

    log = (lambda *x: None) if a.quiet else (lambda s: print(s, flush=True))
    progress = a.progress and not a.quiet
    photon_args = {}
    if a.photons is not None:
        photon_args["n_photons"] = a.photons
    if a.seed is not None:
        photon_args["seed"] = a.seed
    outdir = os.path.join(a.root, TABLES)
    t0 = time.monotonic()
    n = 0
    if target in ("atmosphere", "all"):
        from .atmosphere import table as at
        at.run(outdir, progress=progress, log=log)
        n += 1
    if target in ("skylight", "all"):
        from .skylight import table as sk
        sk.run(outdir, progress=progress, log=log)
        n += 1
    if target in ("earthshine", "all"):
        n += bake_earthshine(outdir, a.scene, a.method, log, progress, photon_args)
    log("baked %d table(s) into %s in %.1f s" % (n, outdir, time.monotonic() - t0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
