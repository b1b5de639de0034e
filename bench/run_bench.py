#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""run_bench.py: the driver of `make bench`.

1. Wall time: runs `bench-{double,float} time` (median ns per scene over
   repeated runs, clock_gettime inside the benchmark program).
2. Instructions: runs `bench-<prec> count CONFIG N` under
   `valgrind --tool=callgrind` for two run lengths N1 < N2 and divides the
   difference of the instruction totals by (N2 - N1) * scenes, so start-up,
   scene set-up and the dynamic loader cancel out.
3. The slow way: the baker's quadrature `bake.earthshine.reference.phi_psi_reference`
   called per scene (scalar calls, as a runtime would have to), timed here;
   the runtime's table (and the analytic Lambert model) compared with it:
   speed-up and the error the table costs.

Prints `name value unit` lines (also written to --out) and a JSON file next
to it, named after it (bench.txt: bench.json, which bake/report/perf.py reads).
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, ROOT)

CONFIGS = ["all", "sun", "sun_earth", "all_expose", "sun_fraction", "earthshine", "earthshine_lambert",
           "sun_moon", "sun_earth_mean", "sun_earth_plate", "sun_earth_box_wing",
           "sun_earth_cylinder", "sun_fraction_wgs84", "all_wgs84", "sun_fraction_batch",
           "sun_fraction_batch_all", "all_batch", "all_batch_observer", "all_batch_irradiance",
           "all_batch_full", "earthshine_batch",
           "sun_earth_knocke", "sun_earth_map", "sun_earth_table", "sun_earth_map_9x18", "sun_earth_map_q",
           "all_batch_observer_mean"]
# the exposure batch and its outputs masks (--only-expose measures these alone)
EXPOSE_CONFIGS = ["all_expose", "expose_batch", "expose_batch_all", "expose_batch_setting",
                  "expose_batch_faint", "expose_batch_flags", "expose_batch_moving_all",
                  "expose_batch_moving_faint"]
CONFIGS += [c for c in EXPOSE_CONFIGS if c not in CONFIGS]
# the finer albedo maps cost milliseconds per scene: callgrind over fewer passes
CALLGRIND_PASSES = {"sun_earth_map": (0, 2), "sun_earth_map_q": (0, 1)}

LIGHTS = ["lit", "penumbra", "umbra"]
R_EARTH_KM = 6378.137

GOAL_INSTR = 2000
GOAL_NS = 300.0
GOAL_SPEEDUP = 1e4
# the planar peers of the Sun fraction's goal (bench/peers.py): line name, label
PLANAR_PEERS = [("numpy_mg", "numpy M&G"), ("orekit", "Orekit"), ("basilisk", "Basilisk")]


class Out:
    def __init__(self, path):
        self.lines = []
        self.path = path
        self.data = {}

    def put(self, name, value, unit, comment=""):
        line = "%s %s %s" % (name, value, unit) + (("  # " + comment) if comment else "")
        print(line, flush=True)
        self.lines.append(line)
        self.data[name] = {"value": value, "unit": unit}

    def save(self):
        os.makedirs(os.path.dirname(os.path.abspath(self.path)), exist_ok=True)
        with open(self.path, "w") as f:
            f.write("\n".join(self.lines) + "\n")
        # named after the output (bench.txt: bench.json), so that a partial run
        # (--only-peers: peers.txt) leaves a full run's bench.json as it was
        with open(os.path.splitext(os.path.abspath(self.path))[0] + ".json", "w") as f:
            json.dump(self.data, f, indent=1, sort_keys=True)


def run(cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True)


def nscenes(binary):
    for line in run([binary, "configs"]).stdout.splitlines():
        if line.startswith("nscenes"):
            return int(line.split()[1])
    raise SystemExit("bench: no scene count")


def callgrind_profile(binary, config, n, ns, tmp, out, prec, top=14):
    """Inclusive instructions per scene of the runtime's functions (and the libm
    functions they call) for one configuration: where the time goes."""
    path = os.path.join(tmp, "cg.profile.out")
    subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + path, binary,
                    "count", config, str(n)], check=True, capture_output=True, text=True)
    ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", path],
                         check=True, capture_output=True, text=True).stdout
    os.remove(path)
    rows = []
    pat = re.compile(r"^\s*([\d,]+) \(\s*[\d.]+%\)\s+(\S*):(\S+) \[")
    for line in ann.splitlines():
        m = pat.match(line)
        if not m:
            continue
        name = m.group(3)
        if name in ("main", "run_config") or name.startswith("0x") or "(below" in line or "libc_start" in name:
            continue
        rows.append((int(m.group(1).replace(",", "")) / float(n * ns), name))
    seen = set()
    k = 0
    for per, name in sorted(rows, reverse=True):
        if name in seen or per < 1.0:
            continue
        seen.add(name)
        out.put("profile.%s.%s.%s" % (prec, config, name), "%.0f" % per, "instructions",
                "inclusive, per scene")
        k += 1
        if k >= top:
            break


def callgrind_total(binary, config, n, tmp, light=None):
    out = os.path.join(tmp, "cg.%s.%d.out" % (config, n))
    subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out, binary,
                    "count", config, str(n)] + ([light] if light else []), check=True,
                   capture_output=True, text=True)
    total = None
    with open(out) as f:
        for line in f:
            if line.startswith("summary:") or line.startswith("totals:"):
                total = int(line.split()[1])
    os.remove(out)
    return total


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bindir", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--reps", type=int, default=31)
    ap.add_argument("--n1", type=int, default=2)
    ap.add_argument("--n2", type=int, default=12)
    ap.add_argument("--no-quadrature", action="store_true")
    ap.add_argument("--baseline", metavar="BENCH",
                    help="the bench of the illumination before the batch interface (make bench builds "
                         "it from git): its oi_illuminate over the same mix, the full illumination goal's base")
    ap.add_argument("--goals-from", metavar="JSON",
                    help="print the goal lines of a finished run's bench.json and stop")
    ap.add_argument("--only-illumination", action="store_true",
                    help="only the full illumination goal's instructions (double, callgrind: the "
                         "scene configurations and the --baseline), then the goals")
    ap.add_argument("--only-expose", action="store_true",
                    help="only the exposure batch's instructions per mask (both precisions, "
                         "callgrind), then stop")
    ap.add_argument("--peers", metavar="DIR",
                    help="where `make bench-peers` built the Orekit and Basilisk harnesses "
                         "($(BUILDDIR)/peers): time them beside numpy M&G")
    ap.add_argument("--only-peers", action="store_true",
                    help="only the peers and the binding's cost (section 2b), then the goals")
    args = ap.parse_args()
    out = Out(args.out)
    if args.only_peers:
        peer_run(args, out)
        goals(out)
        out.save()
        return 0
    if args.only_expose:
        expose_run(args, out)
        out.save()
        return 0
    if args.only_illumination:
        illumination_run(args, out)
        goals(out)
        out.save()
        return 0
    if args.goals_from:
        with open(args.goals_from) as f:
            out.data = json.load(f)
        goals(out)
        return 0

    # 1. wall time
    for prec in ("double", "float"):
        b = os.path.join(args.bindir, "bench-" + prec)
        for line in run([b, "time", str(args.reps)]).stdout.splitlines():
            parts = line.split(None, 2)
            if len(parts) >= 3:
                unit, _, comment = parts[2].partition("  # ")
                out.put(parts[0], parts[1], unit.strip(), comment)

    # 2. instructions (callgrind)
    if shutil.which("valgrind"):
        tmp = os.path.join(args.bindir, "cg")
        os.makedirs(tmp, exist_ok=True)
        for prec in ("double", "float"):
            b = os.path.join(args.bindir, "bench-" + prec)
            ns = nscenes(b)
            for c in CONFIGS:
                n1, n2 = CALLGRIND_PASSES.get(c, (args.n1, args.n2))
                put_instructions(out, "%s.%s" % (prec, c), b, c, n1, n2, tmp, ns)
                if c in ("all_expose", "sun_fraction", "sun_fraction_batch", "all", "all_batch_observer"):
                    for light in LIGHTS:  # where the cost is: lit, penumbra, umbra
                        t1 = callgrind_total(b, c, args.n1, tmp, light)
                        t2 = callgrind_total(b, c, args.n2, tmp, light)
                        per = (t2 - t1) / float((args.n2 - args.n1) * ns / len(LIGHTS))
                        out.put("bench.%s.%s.%s.instructions" % (prec, c, light), "%.0f" % per,
                                "instructions", "the %s third of the mix" % light)
        if args.baseline:  # the same mix through the baseline's oi_illuminate, in this run
            ns = nscenes(args.baseline)
            t1 = callgrind_total(args.baseline, "all", args.n1, tmp)
            t2 = callgrind_total(args.baseline, "all", args.n2, tmp)
            out.put("bench.double.all_baseline.instructions",
                    "%.0f" % ((t2 - t1) / float((args.n2 - args.n1) * ns)), "instructions",
                    "oi_illuminate before the batch interface, same mix; callgrind, (I(%d) - I(%d)) / (%d x %d scenes)"
                    % (args.n2, args.n1, args.n2 - args.n1, ns))
            for light in LIGHTS:
                t1 = callgrind_total(args.baseline, "all", args.n1, tmp, light)
                t2 = callgrind_total(args.baseline, "all", args.n2, tmp, light)
                out.put("bench.double.all_baseline.%s.instructions" % light,
                        "%.0f" % ((t2 - t1) / float((args.n2 - args.n1) * ns / len(LIGHTS))),
                        "instructions", "the %s third of the mix" % light)
        b = os.path.join(args.bindir, "bench-double")
        if shutil.which("callgrind_annotate"):
            callgrind_profile(b, "all_expose", args.n2, nscenes(b), tmp, out, "double")
    else:
        out.put("bench.instructions", "unavailable", "-", "valgrind not installed")

    # 2b. the planar peers of oi_sun_fraction, in the same run (bench/peers.py)
    peer_run(args, out)

    # 3. the slow way: quadrature per scene
    if not args.no_quadrature:
        quadrature(args, out)

    goals(out)
    out.save()
    return 0


ILLUMINATION_CONFIGS = ["all", "all_batch_observer", "all_batch_observer_mean", "all_batch_full",
                        "all_batch_irradiance"]


def put_instructions(out, name, b, c, n1, n2, tmp, ns):
    """Instructions per scene of configuration c of the bench binary b under
    callgrind, (I(n2) - I(n1)) / ((n2 - n1) ns), put as bench.<name>.instructions."""
    t1 = callgrind_total(b, c, n1, tmp)
    t2 = callgrind_total(b, c, n2, tmp)
    out.put("bench.%s.instructions" % name, "%.0f" % ((t2 - t1) / float((n2 - n1) * ns)),
            "instructions", "callgrind, (I(%d) - I(%d)) / (%d x %d scenes)" % (n2, n1, n2 - n1, ns))


def illumination_run(args, out):
    """The full illumination goal's numbers alone, as section 2 forms them."""
    tmp = os.path.join(args.bindir, "cg")
    os.makedirs(tmp, exist_ok=True)
    runs = [(os.path.join(args.bindir, "bench-double"), c, c) for c in ILLUMINATION_CONFIGS]
    if args.baseline:
        runs.append((args.baseline, "all", "all_baseline"))
    for b, c, name in runs:
        put_instructions(out, "double." + name, b, c, args.n1, args.n2, tmp, nscenes(b))


def expose_run(args, out):
    """The exposure batch's instructions per row and mask, as section 2 forms them."""
    tmp = os.path.join(args.bindir, "cg")
    os.makedirs(tmp, exist_ok=True)
    for prec in ("double", "float"):
        b = os.path.join(args.bindir, "bench-" + prec)
        ns = nscenes(b)
        for c in EXPOSE_CONFIGS:
            put_instructions(out, "%s.%s" % (prec, c), b, c, args.n1, args.n2, tmp, ns)


def peer_run(args, out):
    import peers
    rows = []
    b = os.path.join(args.bindir, "bench-double")
    for line in run([b, "points"]).stdout.splitlines():
        if line.startswith("#"):
            continue
        f = line.split()
        v = [float(x) for x in f[1:]]
        rows.append((f[0], v[0:3], v[3:6], v[6]))
    peers.run(rows, out, peers_dir=args.peers)
    if shutil.which("valgrind"):
        # the goal's repeatable form: instructions per point on the same mix (callgrind)
        import peers_instructions
        n = 20000
        per = peers_instructions.measure(b, n, "mix")
        out.put("peer.numpy_mg.mix.instructions_per_point", "%.0f" % per["numpy_mg"], "instructions",
                "callgrind, (I(%d) - I(%d)) / (%d x %d points), bench/peers_instructions.py"
                % (2 * n, n, peers_instructions.CALLS, n))
        out.put("peer.orbillum.sun_fraction_batch.mix.instructions_per_point", "%.0f" % per["orbillum"],
                "instructions", "oi_sun_fraction_batch, outputs mask 0, the same points")
        out.put("peer.numpy_mg.over.sun_fraction_batch.mix.instructions",
                "%.2f" % (per["numpy_mg"] / per["orbillum"]), "x",
                "peer / orbillum instructions per point on the mix; > 1: orbillum cheaper")
    import binding_cost
    binding_cost.run(rows, out)


def quadrature(args, out):
    try:
        from bake.earthshine import reference as ref
    except Exception as e:  # the baker is another module; say so, do not fail
        out.put("bench.quadrature", "unavailable", "-", "bake.reference: %s" % e)
        return
    import numpy as np

    rows = []
    b = os.path.join(args.bindir, "bench-double")
    for line in run([b, "dump"]).stdout.splitlines():
        if line.startswith("#"):
            continue
        f = line.split()
        rows.append((f[0], f[1], float(f[3]), float(f[4]), float(f[5]), float(f[6]), int(f[7])))
    theta = np.array([r[2] for r in rows])
    h = np.array([r[3] for r in rows])
    x = R_EARTH_KM / (R_EARTH_KM + h)
    phi_tab = np.array([r[4] for r in rows])
    status = np.array([r[6] for r in rows])

    # per-scene scalar calls, as an on-board implementation would make them
    times = []
    phi_ref = np.empty(len(rows))
    psi_ref = np.empty(len(rows))
    for i in range(len(rows)):
        t0 = time.perf_counter()
        p, s = ref.phi_psi_reference(float(theta[i]), float(x[i]))
        times.append(time.perf_counter() - t0)
        phi_ref[i], psi_ref[i] = float(p), float(s)
    times.sort()
    t_quad_ns = times[len(times) // 2] * 1e9
    out.put("bench.quadrature.phi_psi_reference.ns_median", "%.0f" % t_quad_ns, "ns",
            "bake.reference.phi_psi_reference, one scalar call per scene (numpy Gauss-Legendre)")

    lam = x * x * ref.lambert_phase(theta)
    # Two error measures: relative where earthshine is at least 1e-3 of its
    # sub-solar value at that altitude, and absolute in units of that value.
    phi0 = np.array([float(ref.phi_reference(0.0, float(xi))) for xi in x])
    big = phi_ref >= 1e-3 * phi0
    ok = status >= 0
    for name, approx, sel in (("earthshine", phi_tab, ok), ("earthshine_lambert", lam, np.ones_like(ok))):
        if not sel.any():
            continue
        rel = np.abs(approx - phi_ref)[sel & big] / phi_ref[sel & big]
        nrm = np.abs(approx - phi_ref)[sel] / phi0[sel]
        what = "runtime table" if name == "earthshine" else "far-field Lambert x^2 p(theta), computed here"
        if rel.size:
            out.put("bench.double.%s.max_rel_err_vs_quadrature" % name, "%.3g" % rel.max(), "1",
                    "%s; scenes where phi >= 1e-3 phi(0, h)" % what)
        out.put("bench.double.%s.max_err_over_subsolar" % name, "%.3g" % nrm.max(), "1",
                "%s; |approx - quadrature| / phi(0, h), all scenes" % what)
    # the single-precision build: the same error measure at its own (float-rounded) inputs
    bf = os.path.join(args.bindir, "bench-float")
    if os.path.exists(bf):
        fr = [l.split() for l in run([bf, "dump"]).stdout.splitlines() if not l.startswith("#")]
        th_f = np.array([float(r[3]) for r in fr])
        x_f = R_EARTH_KM / (R_EARTH_KM + np.array([float(r[4]) for r in fr]))
        phi_f = np.array([float(r[5]) for r in fr])
        ok_f = np.array([int(r[7]) for r in fr]) >= 0
        ref_f = np.asarray(ref.phi_psi_reference(th_f, x_f)[0], dtype=float)
        phi0_f = np.asarray(ref.phi_psi_reference(np.zeros_like(x_f), x_f)[0], dtype=float)
        big_f = (ref_f >= 1e-3 * phi0_f) & ok_f
        if big_f.any():
            out.put("bench.float.earthshine.max_rel_err_vs_quadrature", "%.3g" % (
                np.abs(phi_f - ref_f)[big_f] / ref_f[big_f]).max(), "1",
                "single-precision runtime at its float inputs; scenes where phi >= 1e-3 phi(0, h)")
        if ok_f.any():
            out.put("bench.float.earthshine.max_err_over_subsolar", "%.3g" % (
                np.abs(phi_f - ref_f)[ok_f] / phi0_f[ok_f]).max(), "1")
    for prec in ("double", "float"):
        d = out.data.get("bench.%s.earthshine.ns_median" % prec)
        if d:
            t = float(d["value"])
            out.put("bench.%s.earthshine.speedup_vs_quadrature" % prec, "%.0f" % (t_quad_ns / max(t, 1e-3)),
                    "x", "quadrature ns / table ns")
    # The same quadrature at the lowest order (of a fixed ladder) whose error on
    # these scenes is no larger than the table's: the slow way at matched accuracy.
    tab_err = out.data.get("bench.double.earthshine.max_err_over_subsolar")
    if tab_err is not None:
        target = float(tab_err["value"])
        for order in (4, 6, 8, 12, 16, 24, 32):
            approx = np.array([float(ref.phi_psi_reference(float(theta[i]), float(x[i]), order, order)[0])
                               for i in range(len(rows))])
            err = float((np.abs(approx - phi_ref) / phi0).max())
            if err <= target:
                tt = []
                for i in range(len(rows)):
                    t0 = time.perf_counter()
                    ref.phi_psi_reference(float(theta[i]), float(x[i]), order, order)
                    tt.append(time.perf_counter() - t0)
                tt.sort()
                tq = tt[len(tt) // 2] * 1e9
                out.put("bench.quadrature.matched_accuracy.order", order, "nodes",
                        "Gauss-Legendre order per axis reaching the table's error (%.2g of phi(0,h))" % err)
                out.put("bench.quadrature.matched_accuracy.ns_median", "%.0f" % tq, "ns")
                d = out.data.get("bench.double.earthshine.ns_median")
                if d:
                    out.put("bench.double.earthshine.speedup_vs_quadrature_matched", "%.0f" % (
                        tq / max(float(d["value"]), 1e-3)), "x", "quadrature at matched accuracy / table")
                break
    if not ok.all():
        out.put("bench.double.earthshine.scenes_with_error_status", int((~ok).sum()), "scenes")


def goals(out):
    def val(name):
        d = out.data.get(name)
        try:
            return float(d["value"]) if d else None
        except ValueError:
            return None

    incomplete = [k for k in out.data if k.endswith(".incomplete")]
    note = " (INCOMPLETE: %d configurations ran a stub)" % len(incomplete) if incomplete else ""
    i = val("bench.double.all_expose.instructions")
    if i is not None:
        out.put("goal.full_scene_at_most_%d_instructions" % GOAL_INSTR, "met" if i <= GOAL_INSTR else "missed",
                "-", "double, all terms + exposure: %.0f instructions%s" % (i, note))
    t = val("bench.double.all_expose.ns_median")
    if t is not None:
        out.put("goal.full_scene_under_%d_ns" % GOAL_NS, "met" if t < GOAL_NS else "missed", "-",
                "double, all terms + exposure: %.1f ns median%s" % (t, note))
    # the fastest planar peer timed in this run: the least peer / orbillum ratio
    timed = [(val("peer.%s.over.sun_fraction_batch_same_rows" % p), p, label)
             for p, label in PLANAR_PEERS]
    timed = [t for t in timed if t[0] is not None]
    if timed:
        r, p, label = min(timed)
        orbit = [v for v in (val("peer.%s.over.sun_fraction_batch_orbits" % q) for q, _ in PLANAR_PEERS)
                 if v is not None]
        ro = min(orbit) if orbit else None
        absent = [lb for q, lb in PLANAR_PEERS if q not in [t[1] for t in timed]]
        # met when the time ratio of this run and (where callgrind ran) the instruction
        # ratio against numpy M&G both reach 2
        ri = val("peer.numpy_mg.over.sun_fraction_batch.mix.instructions")
        met = r >= 2 and (ri is None or ri >= 2)
        out.put("goal.sun_fraction_2x_faster_than_fastest_planar_peer", "met" if met else "missed",
                "-", "fastest planar peer %s / oi_sun_fraction_batch (mask 0), same 1e5 points: %.2fx "
                "in time (a third in the penumbra; %s)%s%s%s%s"
                % (label, r, ", ".join("%s %.2fx" % (lb, v) for v, _, lb in sorted(timed)),
                   "; numpy M&G %.2fx in instructions (callgrind, the same mix)" % ri if ri is not None else "",
                   "; along orbits uniform in time, the fastest peer %.2fx" % ro if ro is not None else "",
                   " (not timed: %s)" % ", ".join(absent) if absent else "", note))
    worst = [val(k) for k in out.data if k.startswith("binding.") and k.endswith(".over_c_batch")]
    worst = [w for w in worst if w is not None]
    best = [val(k) for k in out.data
            if k.startswith("binding.") and k.endswith(".over_c_batch_best")]
    best = [w for w in best if w is not None]
    if worst:
        out.put("goal.binding_within_1.3x_of_c_batch", "met" if max(worst) <= 1.3 else "missed",
                "-", "largest binding / C batch ratio per row: %.2fx (medians)%s"
                % (max(worst), "; %.2fx on the least of 9 calls each" % max(best) if best else ""))
    # the full illumination: oi_illuminate against the scene batch with the
    # outputs a planner reads (OI_BATCH_OBSERVER: irradiances, fluxes,
    # magnitude), in instructions (wall times of one shared run vary by 2x);
    # beside it the batch with every output and with the irradiances only
    # The base is the baseline's oi_illuminate (before the batch interface, built
    # from git by make bench); without it, today's oi_illuminate.
    base = val("bench.double.all_baseline.instructions")
    a = val("bench.double.all.instructions")
    b = val("bench.double.all_batch_observer.instructions")
    full = val("bench.double.all_batch_full.instructions")
    irr = val("bench.double.all_batch_irradiance.instructions")
    if a and b:
        ref, what = (base, "oi_illuminate before the batch interface") if base else (a, "oi_illuminate")
        extra = "; every output %.2fx, irradiances only %.2fx" % (ref / full, ref / irr) if full and irr else ""
        mean = val("bench.double.all_batch_observer_mean.instructions")
        if base:
            extra += "; today's oi_illuminate %.2fx" % (base / a)
            if mean:  # the baseline's physics: the sphere reflects from the mean direction
                extra += "; the batch with the mean direction (OI_EARTH_REFLECT_MEAN) %.2fx" % (base / mean)
        # where the scene's instructions go: the goal's budget, the sphere's
        # cubature (the batch less its mean-direction run), the irradiances
        extra += "; %.0f instructions per scene against the goal's %.0f" % (b, ref / 3)
        if mean:
            extra += ", the sphere's earthshine cubature %.0f of them" % (b - mean)
        if irr:
            extra += ", the irradiances at the target (mask 0) %.0f" % irr
        out.put("goal.full_illumination_3x_faster", "met" if ref / b >= 3 else "missed", "-",
                "%s / oi_illuminate_batch_outputs(OI_BATCH_OBSERVER), instructions "
                "per scene: %.2fx%s%s" % (what, ref / b, extra, note))
    s = val("bench.double.earthshine.speedup_vs_quadrature")
    if s is not None:
        out.put("goal.earthshine_%dx_faster_than_quadrature" % GOAL_SPEEDUP, "met" if s >= GOAL_SPEEDUP else "missed",
                "-", "%.0fx%s" % (s, note))


if __name__ == "__main__":
    sys.exit(main())
