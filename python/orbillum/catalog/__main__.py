# SPDX-License-Identifier: MIT
"""Command line of the catalogue planner: python -m orbillum.catalog (docs/catalog.md)."""
from __future__ import annotations

import argparse
import json
import os
import signal
import sys
import warnings

from . import elements, gp, output, plan, synthetic, tle

#: the example files the docs use, shipped with the package (orbillum/catalog/data/)
DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")

USAGE_EXAMPLE = """example:
  python -m orbillum.catalog.synthetic 1000 --seed 1 -o cat.3le
  python -m orbillum.catalog cat.3le --observers inspectors.3le \\
      --start 2026-12-01T00:00 --stop 2026-12-02T00:00 --step 60 \\
      --camera telescope-15cm --max-range-km 5000 --workers 2 -o plan.parquet --csv plan.csv
"""


def shipped(path: str) -> str:
    """path, or the shipped example of that name (orbillum/catalog/data/) when path
    does not exist and is a bare file name (docs/catalog.md's inspectors.json)."""
    if not os.path.exists(path) and os.path.basename(path) == path:
        alt = os.path.join(DATA, path)
        if os.path.exists(alt):
            print(f"orbillum.catalog: {path}: not here; the shipped example {alt}",
                  file=sys.stderr)
            return alt
    return path


def _observer_sets(path: str) -> list[tle.ElementSet]:
    """Observers given as mean elements in a JSON list (docs/catalog.md)."""
    path = shipped(path)
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
    src.add_argument("catalogue", nargs="?",
                     help="the objects: a 3LE/2LE file or an OMM file (JSON, XML or CSV, as "
                          "CelesTrak and Space-Track write GP data)")
    src.add_argument("--synthetic", type=int, metavar="N",
                     help="instead of a file: N synthetic objects (orbillum.catalog.synthetic)")
    src.add_argument("--seed", type=int, default=0, help="seed of --synthetic (default 0)")
    obs = p.add_argument_group("observers (at least one)")
    obs.add_argument("--observers", action="append", default=[], metavar="FILE",
                     help="3LE/2LE or OMM file: every set in it is an observer (repeatable)")
    obs.add_argument("--observer-elements", action="append", default=[], metavar="FILE",
                     help="JSON list of observers as mean elements (repeatable)")
    tm = p.add_argument_group("time")
    tm.add_argument("--start", required=True, help="first epoch, ISO 8601 UTC")
    tm.add_argument("--stop", required=True, help="last epoch (inclusive when on the grid)")
    tm.add_argument("--step", type=float, default=60.0, help="seconds between epochs (60)")
    tm.add_argument("--epoch-warn-days", type=float, default=elements.EPOCH_WARN_DAYS,
                    help="warn of element sets farther than this from a planned epoch "
                         f"(default {elements.EPOCH_WARN_DAYS:g})")
    tm.add_argument("--epoch-limit-days", type=float, default=elements.EPOCH_LIMIT_DAYS,
                    help="rows farther than this from their element epoch are ERR_SGP4 "
                         f"(default {elements.EPOCH_LIMIT_DAYS:g})")
    gp.add_arguments(p)
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
    out.add_argument("-o", "--parquet", metavar="FILE", help="Parquet output (one file)")
    out.add_argument("--dataset", metavar="DIR",
                     help="Parquet output as a partitioned dataset: a directory of one part per "
                          "block")
    out.add_argument("--csv", metavar="FILE", help="CSV output ('-' = standard output)")
    out.add_argument("--resume", action="store_true",
                     help="finish the interrupted run of the same arguments (its finished "
                          "parts, in OUTPUT.partial/, are not computed again)")
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
    ex.add_argument("--scheduler-timeout", type=float, metavar="S",
                    help=f"seconds to try to reach --scheduler (default "
                         f"{plan.SCHEDULER_TIMEOUT_S:g})")
    ex.add_argument("--client-writes", action="store_true",
                    help="on Dask, the rows come to this process, which writes them (default: "
                         "the workers write their parts: the output folder must be shared)")
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
    sources = [a.catalogue is not None, a.synthetic is not None,
               a.gp_group is not None or a.gp_catnr is not None]
    if sum(sources) != 1:
        p.error("give a catalogue file, --synthetic N or --gp-group/--gp-catnr (one of them)")
    if a.parquet is None and a.csv is None and a.dataset is None:
        p.error("give an output: -o FILE.parquet, --dataset DIR and/or --csv FILE")
    if a.resume and a.csv == "-":
        p.error("--resume and --csv -: standard output cannot be resumed")
    if a.workers == "auto":
        workers = os.cpu_count() or 1
    else:
        try:
            workers = int(a.workers)
        except ValueError:
            p.error(f"--workers: a number or 'auto' (got {a.workers!r})")
        if workers < 0:
            p.error("--workers must be >= 0")
    a.workers_n = workers
    if a.scheduler is not None and workers:
        p.error("--scheduler and --workers N together: the cluster at ADDRESS has its workers")
    for path in (a.parquet, a.csv, a.dataset):
        if path and path != "-":
            d = os.path.dirname(os.path.abspath(path))
            if not os.path.isdir(d):
                p.error(f"output folder {d} does not exist")
    old_term = signal.signal(signal.SIGTERM, _terminate)
    try:
        return _run(a)
    except KeyboardInterrupt:
        _interrupted(a, "interrupted")
        return 130
    except Terminated:
        _interrupted(a, "terminated")
        return 128 + signal.SIGTERM
    finally:
        signal.signal(signal.SIGTERM, old_term)


class Terminated(SystemExit):
    """SIGTERM: stop as ^C does (the finished parts stay for --resume)."""


def _terminate(signum, frame):
    raise Terminated(128 + signum)


def _interrupted(a, what):
    works = [p + output.SUFFIX for p in (a.parquet, a.csv if a.csv != "-" else None, a.dataset)
             if p and os.path.isdir(p + output.SUFFIX)]
    where = f"; the finished blocks are kept in {', '.join(works)}" if works else ""
    print(f"orbillum.catalog: {what}: no output written{where}; run again with --resume "
          "to finish", file=sys.stderr)


def _show_warning(message, category, filename, lineno, file=None, line=None):
    """The planner's own warnings as one line `orbillum.catalog: warning: ...`."""
    if issubclass(category, (elements.EpochWarning, gp.StaleWarning)):
        print(f"orbillum.catalog: warning: {message}", file=sys.stderr)
    else:
        _default_show(message, category, filename, lineno, file, line)


_default_show = warnings.showwarning


def _run(a) -> int:
    try:
        sets = gp.from_arguments(a)
        if a.synthetic is not None:
            sets = synthetic.generate(a.synthetic, a.seed)
        elif sets is None:
            sets = elements.read(a.catalogue)
        observers = []
        for path in a.observers:
            observers += elements.read(shipped(path))
        for path in a.observer_elements:
            observers += _observer_sets(path)
        csv = sys.stdout.buffer if a.csv == "-" else a.csv
        with warnings.catch_warnings():
            warnings.simplefilter("default")
            warnings.showwarning = _show_warning
            summary, _ = plan.plan(
                sets, observers, a.start, a.stop, a.step, camera=_camera(a.camera),
                max_range_km=a.max_range_km, all_rows=a.all_rows, positions=a.positions,
                objects_per_block=a.objects_per_block, workers=a.workers_n,
                scheduler=a.scheduler, parquet=a.parquet, csv=csv, dataset=a.dataset,
                progress=a.progress, target_albedo=a.target_albedo,
                target_radius_m=a.target_radius_m, earth_albedo=a.earth_albedo,
                resume=a.resume, epoch_warn_days=a.epoch_warn_days,
                epoch_limit_days=a.epoch_limit_days, scheduler_timeout_s=a.scheduler_timeout,
                workers_write=not a.client_writes)
    except (tle.CatalogueError, ValueError, TypeError) as e:
        print(f"orbillum.catalog: {e}", file=sys.stderr)
        return 2
    r = plan.rate(summary)
    resumed = (f" ({summary.resumed_blocks} taken from the interrupted run)"
               if summary.resumed_blocks else "")
    print(f"orbillum.catalog: {summary.objects} objects x {summary.observers} observers x "
          f"{summary.epochs} epochs = {summary.scenes} scenes in {summary.blocks} blocks"
          f"{resumed} on {summary.workers} worker(s); {summary.visible} visible, "
          f"{summary.observable} observable, {summary.rows_written} rows "
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
