# SPDX-License-Identifier: MIT
"""python -m examples.scenarios: write the planner's CSV from TLEs and the real Sun and Moon."""
from __future__ import annotations

import argparse
import sys
import time

EPILOG = """\
examples:
  # a shipped case (see --list) into a file, then plan it
  python -m examples.scenarios --case geo-inspector-eclipse -o geo.csv
  build/oi-plan --csv geo.csv > geo-plan.csv

  # your own TLEs: observer and target, one day every 60 s
  python -m examples.scenarios --observer-tle obs.tle --target-tle tgt.tle \\
      --start 2026-03-20T00:00 --stop 2026-03-21T00:00 --step 60 --camera NAME -o my.csv

  # a file with several element sets: pick one by catalogue number or name
  python -m examples.scenarios --target-tle catalog.tle:25544 ...

  # a target given by SGP4 mean elements instead of a TLE
  python -m examples.scenarios --target-elements \\
      epoch=2026-03-20T00:00,a_km=42164,ecc=0,incl_deg=0,raan_deg=0,argp_deg=0,mo_deg=0 ...

Frame: GCRS, km (Sun and Moon from astropy's built-in ephemeris, satellites by
sgp4 in TEME converted to GCRS by astropy). Runs offline: IERS downloads are off.
"""


def _parse_elements(s: str) -> dict:
    out: dict = {}
    for part in s.split(","):
        if not part.strip():
            continue
        k, eq, v = part.partition("=")
        if not eq:
            raise SystemExit(f"--*-elements: {part!r} is not KEY=VALUE")
        k = k.strip()
        out[k] = v.strip() if k == "epoch" else float(v)
    return out


def _builtin_cameras() -> list[str] | None:
    """Names of the planner's built-in cameras: from the binding, else from
    `build/oi-plan --list-cameras`; None when neither is available."""
    try:
        import orbillum
        return orbillum.cameras()
    except Exception:  # the binding is optional here
        pass
    import os
    import subprocess
    plan = os.path.join(os.path.dirname(__file__), "..", "..", "build", "oi-plan")
    try:
        out = subprocess.run([plan, "--list-cameras"], capture_output=True, text=True,
                             timeout=30, check=True).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    return [ln.split()[0] for ln in out.splitlines() if ln and not ln[0].isspace()]


def _check_columns(p, a) -> None:
    """Refuse, before any output is written, a camera the planner does not
    know and albedos or a radius it would refuse row by row."""
    if a.camera is not None:
        names = _builtin_cameras()
        if names is None:
            print("warning: --camera not checked (no orbillum binding, no build/oi-plan)",
                  file=sys.stderr)
        elif a.camera not in names:
            p.error(f"--camera {a.camera!r}: not a built-in camera; one of {', '.join(names)}")
    for opt in ("target_albedo", "earth_albedo"):
        v = getattr(a, opt)
        if v is not None and not 0.0 <= v <= 1.0:
            p.error(f"--{opt.replace('_', '-')} {v:g}: an albedo is in [0, 1]")
    if a.target_radius_m is not None and not 0.0 < a.target_radius_m < float("inf"):
        p.error(f"--target-radius-m {a.target_radius_m:g}: a radius is > 0")
    if a.step is not None and not a.step > 0:
        p.error(f"--step {a.step:g}: the step is > 0 seconds")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(
        prog="python -m examples.scenarios",
        description="Write the exposure planner's CSV (build/oi-plan --csv) for a date range: "
                    "Sun, Moon, target and observer positions in GCRS (km).",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--case", help="a shipped case name (see --list) or a JSON case file")
    p.add_argument("--list", action="store_true", help="list the shipped cases and exit")
    p.add_argument("--target-tle", metavar="FILE[:KEY]", help="target TLE/3LE file")
    p.add_argument("--target-elements", metavar="K=V,...", help="target SGP4 mean elements")
    p.add_argument("--observer-tle", metavar="FILE[:KEY]", help="observer TLE/3LE file")
    p.add_argument("--observer-elements", metavar="K=V,...", help="observer mean elements")
    p.add_argument("--start", help="first epoch, ISO 8601 UTC")
    p.add_argument("--stop", help="last epoch, ISO 8601 UTC")
    p.add_argument("--step", type=float, help="step in seconds")
    p.add_argument("--camera", help="built-in camera name for the camera column")
    p.add_argument("--target-radius-m", type=float)
    p.add_argument("--target-albedo", type=float)
    p.add_argument("--earth-albedo", type=float)
    p.add_argument("-o", "--output", default="-", help="output CSV (default: standard output)")
    a = p.parse_args(argv)
    if a.case and (a.target_tle or a.target_elements or a.observer_tle or a.observer_elements):
        p.error("--case carries its own orbits: give --case or the --target-*/--observer-* "
                "options, not both")
    _check_columns(p, a)
    if a.output != "-":
        import os
        folder = os.path.dirname(os.path.abspath(a.output))
        if not os.path.isdir(folder):
            p.error(f"-o {a.output}: the folder {folder} does not exist")

    import warnings

    from . import scenario as S  # astropy import is slow: only after --help

    warnings.showwarning = lambda m, c, f, l, file=None, line=None: print(
        f"warning: {m}", file=sys.stderr)

    if a.list:
        for name in S.list_cases():
            sc = S.load_case(name)
            print(f"{name}\n    {sc.start} .. {sc.stop} every {sc.step_s:g} s\n"
                  f"    {sc.description}")
        return 0
    try:
        if a.case:
            sc = S.load_case(a.case)
            if a.start:
                sc.start = a.start
            if a.stop:
                sc.stop = a.stop
            if a.step:
                sc.step_s = a.step
        else:
            if not (a.start and a.stop and a.step):
                p.error("give --case, or --start, --stop and --step with the orbits")
            specs = {}
            for role in ("target", "observer"):
                tle, el = getattr(a, f"{role}_tle"), getattr(a, f"{role}_elements")
                if tle and el:
                    p.error(f"give --{role}-tle or --{role}-elements, not both")
                if tle:
                    specs[role] = {"tle": tle}
                elif el:
                    specs[role] = {"elements": _parse_elements(el)}
            if "target" not in specs:
                p.error("a target is needed: --target-tle or --target-elements")
            sats = {r: S._sat_from_spec(s, ".", {}, r) for r, s in specs.items()}
            sc = S.Scenario(name="cli", start=a.start, stop=a.stop, step_s=a.step,
                            target=sats["target"], observer=sats.get("observer"))
        for col, val in (("camera", a.camera), ("target_radius_m", a.target_radius_m),
                         ("target_albedo", a.target_albedo), ("earth_albedo", a.earth_albedo)):
            if val is not None:
                sc.columns[col] = val
        t0 = time.monotonic()
        cols = S.build_rows(sc)
        if a.output == "-":
            n = S.write_csv(cols, sys.stdout)
        else:
            with open(a.output, "w", encoding="utf-8", newline="\n") as f:
                n = S.write_csv(cols, f)
        print(f"{sc.name}: {n} rows, {sc.start} .. {sc.stop} every {sc.step_s:g} s "
              f"-> {a.output} ({time.monotonic() - t0:.1f} s)", file=sys.stderr)
    except S.ScenarioError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # e.g. piped into head
        sys.stderr.close()
        return 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
