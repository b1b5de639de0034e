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
  --changed                            bake only the tables whose inputs changed: the sha256 of
                                       the inputs (bake/common/inputs.py) differs from the one
                                       their sidecar records (key "inputs")
  --method photon                      node values by photon mapping (bake/photon/)

Progress goes to stderr; a summary line per table to stdout (-q: none).
"""

import argparse
import glob
import json
import os
import sys
import time

from .common import emit
from .common import inputs as gen_inputs

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


def _rel(path):
    """path relative to the repository when it lies in it (a table's recorded inputs)."""
    path = os.path.abspath(path)
    return os.path.relpath(path, ROOT) if path.startswith(ROOT + os.sep) else path


def units(target, scenes=(), method="quadrature", photon_args=None):
    """The tables of a target in baking order, each (name, entry modules, data files,
    bake(outdir, log, progress)): what records its inputs (bake/common/inputs.py) and what
    bakes it alone."""
    out = []
    if target in ("atmosphere", "all") and not scenes:
        from .atmosphere import table as at
        for band, b in at.BANDS.items():
            out.append((b["name"], ["bake.atmosphere.table"], ["bake/config/atmosphere.json"],
                        lambda o, log, pr, band=band: at.run(o, progress=pr, log=log,
                                                              bands=(band,))))
    if target in ("skylight", "all") and not scenes:
        from .skylight import table as sk
        out.append((sk.NAME, ["bake.skylight.table"], ["bake/config/skylight.json"],
                    lambda o, log, pr: sk.run(o, progress=pr, log=log)))
    if target in ("earthshine", "all") or scenes:
        from .earthshine import scenes as sc
        state = {}

        def bake_scene(o, log, pr, path, cfg):
            _, meta = sc.bake(cfg, o, method, log, pr, photon_args or {})
            if path == DEFAULT_CFG:
                state["default_bytes"] = meta["payload_bytes"]
                return
            ref_bytes = state.get("default_bytes")
            if ref_bytes is None:
                g = sc.load(DEFAULT_CFG)["grid"]
                ref_bytes = 8 * (g["n_lit"] + g["n_term"]) * g["n_alt"]
            log("  %s: %d bytes instead of %d for the default table: %d bytes saved (%.0f %%)" % (
                cfg["name"], meta["payload_bytes"], ref_bytes, ref_bytes - meta["payload_bytes"],
                100.0 * (ref_bytes - meta["payload_bytes"]) / ref_bytes))

        for path, cfg in _earthshine_configs(scenes):
            # a scene's log line compares it with the default table (bake/config/default.json)
            data = sorted({_rel(path), _rel(DEFAULT_CFG)})
            out.append((cfg["name"], ["bake.earthshine.scenes"], data,
                        lambda o, log, pr, path=path, cfg=cfg: bake_scene(o, log, pr, path, cfg)))
        if not scenes:
            from .earthshine import angular_table as ang
            out.append((ang.NAME, ["bake.earthshine.angular_table"], [],
                        lambda o, log, pr: ang.run(o, log=log, progress=pr)))
    return out


def committed_inputs(outdir, name):
    """The inputs' sha256 a table's sidecar under outdir records (None: no sidecar or none)."""
    try:
        with open(os.path.join(outdir, name + ".json"), encoding="ascii") as f:
            return (json.load(f).get("inputs") or {}).get("sha256")
    except (OSError, ValueError):
        return None


def stamp(outdir, name, rec):
    """Write the inputs record into a freshly baked table's sidecar."""
    p = os.path.join(outdir, name + ".json")
    with open(p, encoding="ascii") as f:
        side = json.load(f)
    side["inputs"] = rec
    with open(p, "w", encoding="ascii", newline="\n") as f:
        f.write(emit.sidecar_text(side))


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m bake", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("target", nargs="?", choices=TARGETS, default=None,
                    help="what to bake (default: all, or the --scene files)")
    ap.add_argument("--root", default=ROOT, help="output root (default: the repository)")
    ap.add_argument("--list", action="store_true", help="print the output paths, bake nothing")
    ap.add_argument("--changed", action="store_true",
                    help="bake only the tables whose sidecar's inputs sha256 differs from their "
                         "inputs' now (make check-generated)")
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
    todo = units(target, a.scene, a.method, photon_args)
    gen_inputs.watch_reads()
    n = 0
    for name, entries, data, run in todo:
        rec = gen_inputs.record(entries, data, ROOT)
        if a.changed and committed_inputs(outdir, name) == rec["sha256"]:
            log("%s: inputs unchanged (sha256 %s), not baked" % (name, rec["sha256"][:12]))
            continue
        run(outdir, log, progress)
        stamp(outdir, name, rec)
        n += 1
    unread = gen_inputs.unread_data({d for _, _, data, _ in todo for d in data}, ROOT,
                                    outputs(target, a.scene))
    if unread:
        print("bake: read %s, which no table's inputs name (bake/__main__.py, units)"
              % ", ".join(unread), file=sys.stderr)
        return 1
    log("baked %d table(s) into %s in %.1f s" % (n, outdir, time.monotonic() - t0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
