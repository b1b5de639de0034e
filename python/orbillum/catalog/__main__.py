# SPDX-License-Identifier: MIT
"""Command line of the catalogue planner: python -m orbillum.catalog (docs/catalog.md)."""
from __future__ import annotations

import argparse
import json
import os
import sys
import warnings

from . import plan, synthetic, tle

USAGE_EXAMPLE = """example:
  python -m orbillum.catalog.synthetic 1000 --seed 1 -o cat.3le
  python -m orbillum.catalog cat.3le --observers inspectors.3le \\
      --start 2026-12-01T00:00 --stop 2026-12-02T00:00 --step 60 \\
      --camera telescope-15cm --max-range-km 5000 --workers 2 -o plan.parquet --csv plan.csv
"""


def _observer_sets(path: str) -> list[tle.ElementSet]:
    """Observers given as mean elements in a JSON list (docs/catalog.md)."""
    try:
        with open(path, encoding="utf-8") as f:
            items = json.load(f)
    except OSError as e:
        raise tle.CatalogueError(f"{path}: cannot read ({e.strerror})") from e
    except json.JSONDecodeError as e:
        raise tle.CatalogueError(f"{path}:{e.lineno}:{e.colno}: bad JSON: {e.msg}") from e
    if isinstance(items, dict):
        items = [items]
    if not isinstance(items, list):
        raise tle.CatalogueError(f"{path}: expected a JSON list of element objects")
    return [tle.from_elements(el, 99000 + i, f"{path}[{i}]") for i, el in enumerate(items)]


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python -m orbillum.catalog",
        description="Plan a TLE catalogue: for each object, observer and epoch whether the "
                    "observer can see it (not behind the Earth, Sun outside the camera's "
                    "exclusion angle, within the range limit), its brightness, the suggested "
                    "exposure and the flags, in one process or on Dask.",
        epilog=USAGE_EXAMPLE, formatter_class=argparse.RawDescriptionHelpFormatter)
    src = p.add_argument_group("catalogue")
    src.add_argument("catalogue", nargs="?", help="3LE or 2LE file of the objects")
    src.add_argument("--synthetic", type=int, metavar="N",
                     help="instead of a file: N synthetic objects (orbillum.catalog.synthetic)")
    src.add_argument("--seed", type=int, default=0, help="seed of --synthetic (default 0)")
    obs = p.add_argument_group("observers (at least one)")
    obs.add_argument("--observers", action="append", default=[], metavar="FILE",
                     help="3LE/2LE file: every set in it is an observer (repeatable)")
    obs.add_argument("--observer-elements", action="append", default=[], metavar="FILE",
                     help="JSON list of observers as mean elements (repeatable)")
    tm = p.add_argument_group("time")
    tm.add_argument("--start", required=True, help="first epoch, ISO 8601 UTC")
    tm.add_argument("--stop", required=True, help="last epoch (inclusive when on the grid)")
    tm.add_argument("--step", type=float, default=60.0, help="seconds between epochs (60)")
    sc = p.add_argument_group("scene")
    sc.add_argument("--camera", default="telescope-15cm",
                    help="built-in camera name, or a JSON file of a camera dict as "
                         "orbillum.camera() returns (default telescope-15cm)")
    sc.add_argument("--max-range-km", type=float, default=10000.0,
                    help="farthest visible range, km (10000)")
    sc.add_argument("--target-albedo", type=float, help="every object's albedo (C default 0.2)")
    sc.add_argument("--target-radius-m", type=float, help="every object's radius (C default 1 m)")
    sc.add_argument("--earth-albedo", type=float, help="Earth's albedo (C default 0.30)")
    out = p.add_argument_group("output")
    out.add_argument("-o", "--parquet", metavar="FILE", help="Parquet output")
    out.add_argument("--csv", metavar="FILE", help="CSV output ('-' = standard output)")
    out.add_argument("--all-rows", action="store_true",
                     help="write every (object, observer, epoch), not only the visible ones")
    out.add_argument("--positions", action="store_true",
                     help="add the scene's vectors (oi-plan's input columns)")
    out.add_argument("--progress", dest="progress", action="store_true", default=None,
                     help="progress bar on stderr (default: when stderr is a terminal)")
    out.add_argument("--no-progress", dest="progress", action="store_false")
    ex = p.add_argument_group("execution")
    ex.add_argument("--workers", default="0",
                    help="0: this process (default); N: a local Dask cluster of N worker "
                         "processes on loopback; 'auto': one per local core")
    ex.add_argument("--scheduler", metavar="ADDRESS",
                    help="run on an existing Dask cluster, e.g. tcp://10.0.0.5:8786")
    ex.add_argument("--objects-per-block", type=int,
                    help=f"objects per task (default: about {plan.SCENES_PER_BLOCK} scenes)")
    return p


def _camera(arg: str):
    if arg.endswith(".json") or os.path.sep in arg:
        try:
            with open(arg, encoding="utf-8") as f:
                return json.load(f)
        except (OSError, json.JSONDecodeError) as e:
            raise tle.CatalogueError(f"{arg}: cannot read a camera dict ({e})") from e
    return arg


def main(argv=None) -> int:
    p = _parser()
    a = p.parse_args(argv)
    if (a.catalogue is None) == (a.synthetic is None):
        p.error("give a catalogue file or --synthetic N (one of them)")
    if a.parquet is None and a.csv is None:
        p.error("give an output: -o FILE.parquet and/or --csv FILE")
    if a.workers == "auto":
        workers = os.cpu_count() or 1
    else:
        try:
            workers = int(a.workers)
        except ValueError:
            p.error(f"--workers: a number or 'auto' (got {a.workers!r})")
        if workers < 0:
            p.error("--workers must be >= 0")
    if a.scheduler is not None and workers:
        p.error("--scheduler and --workers N together: the cluster at ADDRESS has its workers")
    for path in (a.parquet, a.csv):
        if path and path != "-":
            d = os.path.dirname(os.path.abspath(path))
            if not os.path.isdir(d):
                p.error(f"output folder {d} does not exist")
    try:
        if a.synthetic is not None:
            sets = synthetic.generate(a.synthetic, a.seed)
        else:
            sets = tle.read(a.catalogue)
        observers = []
        for path in a.observers:
            observers += tle.read(path)
        for path in a.observer_elements:
            observers += _observer_sets(path)
        csv = sys.stdout.buffer if a.csv == "-" else a.csv
        with warnings.catch_warnings():
            warnings.simplefilter("default")
            summary, _ = plan.plan(
                sets, observers, a.start, a.stop, a.step, camera=_camera(a.camera),
                max_range_km=a.max_range_km, all_rows=a.all_rows, positions=a.positions,
                objects_per_block=a.objects_per_block, workers=workers, scheduler=a.scheduler,
                parquet=a.parquet, csv=csv, progress=a.progress, target_albedo=a.target_albedo,
                target_radius_m=a.target_radius_m, earth_albedo=a.earth_albedo)
    except (tle.CatalogueError, ValueError, TypeError) as e:
        print(f"orbillum.catalog: {e}", file=sys.stderr)
        return 2
    r = plan.rate(summary)
    print(f"orbillum.catalog: {summary.objects} objects x {summary.observers} observers x "
          f"{summary.epochs} epochs = {summary.scenes} scenes in {summary.blocks} blocks on "
          f"{summary.workers} worker(s); {summary.visible} visible, {summary.rows_written} rows "
          f"written; {r['end_to_end']:.3g} scenes per CPU-second (propagation "
          f"{r['propagate']:.3g}, illumination {r['illuminate']:.3g}); "
          f"{summary.wall_s:.1f} s wall", file=sys.stderr)
    if summary.sgp4_failures:
        print(f"orbillum.catalog: {summary.sgp4_failures} scenes not propagated (sgp4 error: "
              f"decayed or too far from the element epoch), status {plan.block.STATUS_SGP4}",
              file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
