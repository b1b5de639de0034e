# SPDX-License-Identifier: MIT
"""Regenerate docs/gallery/: each shipped case planned by build/oi-plan, its
pass plot and camera views at chosen instants, and the light curve of a
tumbling box-wing over the LEO-LEO pass (examples/render/light_curve.py).

    python -m examples.render.gallery --plan build/oi-plan --out docs/gallery
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys

# (case, [(picture suffix, time id or None for the best-SNR row, camera or None)])
VIEWS = {
    "geo-inspector-eclipse": [
        ("view", None, None),
        ("view-telescope-lit", "2006-04-09T18:30:00Z", "telescope-15cm"),
        ("view-telescope-umbra", "2006-04-09T20:00:00Z", "telescope-15cm"),
    ],
    "leo-leo-pass": [("view", None, None)],
    "leo-inspector": [("view", None, None), ("view-umbra", "2006-06-26T18:45:00Z",
                                             None),
                      ("view-boxwing", None, None, "examples/render/models/boxwing.obj")],
}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m examples.render.gallery")
    p.add_argument("--plan", default="build/oi-plan", help="the planner executable")
    p.add_argument("--out", default="docs/gallery")
    p.add_argument("--work", default="build/gallery", help="scratch directory for CSVs")
    a = p.parse_args(argv)
    os.makedirs(a.out, exist_ok=True)
    os.makedirs(a.work, exist_ok=True)

    from examples.scenarios import scenario as S

    from . import pass_plot, view

    for case, views in VIEWS.items():
        inp = os.path.join(a.work, f"{case}.csv")
        plan = os.path.join(a.work, f"{case}-plan.csv")
        sc = S.load_case(case)
        with open(inp, "w", encoding="utf-8") as f:
            S.write_csv(S.build_rows(sc), f)
        with open(plan, "w", encoding="utf-8") as f:
            rc = subprocess.run([a.plan, "--csv", inp], stdout=f).returncode
        if rc not in (0, 1):
            print(f"error: {a.plan} failed on {inp} (exit {rc})", file=sys.stderr)
            return 2
        pass_plot.main([inp, plan, "-o", os.path.join(a.out, f"{case}-pass.png"),
                        "--title", f"{case}: {sc.target_label} seen by {sc.observer_label}"])
        for suffix, when, cam, *obj in views:
            args = [inp, "-o", os.path.join(a.out, f"{case}-{suffix}.png")]
            if obj:
                args += ["--obj", obj[0]]
            if when:
                args += ["--time", when]
            if cam:
                args += ["--camera", cam]
            if view.main(args) != 0:
                return 2
    from . import light_curve
    lc_dir = os.path.join(a.work, "light-curve")
    if light_curve.main(["--case", "leo-leo-pass", "--plan", a.plan, "--out", lc_dir]) != 0:
        return 2
    shutil.copyfile(os.path.join(lc_dir, "leo-leo-pass-light-curve.png"),
                    os.path.join(a.out, "leo-leo-pass-light-curve.png"))
    from . import season
    if season.main(["--case", "geo-inspector-eclipse", "--start", "2006-02-20",
                    "--stop", "2006-04-20", "--step", "120",
                    "-o", os.path.join(a.out, "geo-eclipse-season.png")]) != 0:
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
