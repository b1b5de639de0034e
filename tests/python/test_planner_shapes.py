# SPDX-License-Identifier: MIT
"""The planner's facet targets (docs/planner.md): the target_shape and q_w..q_z
columns and the --shapes file, on normal and hostile input.

Numbers are checked against closed forms written here: a Sun-lit Lambertian
plate of area A, albedo a, reflects F = E a A cos(i) cos(e) / (pi d^2) towards
an observer at distance d (incidence i, emission e); the attitude is turned
into a rotation matrix by _oi_plan.rotation (the textbook formula, not the
library's code).
"""
import csv
import io
import math

import numpy as np
import pytest

from _oi_plan import PLAN, rotation, run

AU = 149597870.7
TSI = 1361.0
SUN = np.array([AU, 0.0, 0.0])
TARGET = np.array([0.0, 7000.0, 0.0])
MAG_DARK = 99.0


def table(rows):
    columns = []
    for r in rows:
        columns += [c for c in r if c not in columns]
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(columns)
    for r in rows:
        w.writerow([_text(r.get(c, "")) for c in columns])
    return out.getvalue()


def _text(v):
    if isinstance(v, (float, np.floating)):
        return repr(float(v))
    return str(v)


def plan(rows, *extra):
    code, out, err = run(["--csv", "-"] + list(extra), stdin=table(rows).encode())
    return code, list(csv.DictReader(io.StringIO(out))), err


def qmul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return np.array([aw * bw - ax * bx - ay * by - az * bz,
                     aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw])


def scene(observer, q=None, **kw):
    r = dict(sun_x=SUN[0], sun_y=SUN[1], sun_z=SUN[2], target_x=TARGET[0], target_y=TARGET[1],
             target_z=TARGET[2], observer_x=observer[0], observer_y=observer[1],
             observer_z=observer[2], terms="sun")
    if q is not None:
        r.update(q_w=q[0], q_x=q[1], q_y=q[2], q_z=q[3])
    r.update(kw)
    return r


def plate_flux(e_sun, q, observer, albedo=0.2, area=1.0, normal=(0.0, 0.0, 1.0),
               two_sided=False):
    """Closed form of a Lambertian plate lit by the Sun (point source)."""
    n = rotation(q) @ np.asarray(normal, float)
    n /= np.linalg.norm(n)
    s = SUN - TARGET
    s /= np.linalg.norm(s)
    o = np.asarray(observer, float) - TARGET
    d_m = np.linalg.norm(o) * 1e3
    o /= np.linalg.norm(o)
    ci, ce = float(s @ n), float(o @ n)
    if two_sided and ci < 0 and ce < 0:
        ci, ce = -ci, -ce
    if ci <= 0 or ce <= 0:
        return 0.0
    return e_sun * albedo * area * ci * ce / (math.pi * d_m * d_m)


def random_quaternions(n, seed):
    q = np.random.default_rng(seed).normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def shapes_file(tmp_path, text, name="shapes.txt"):
    p = tmp_path / name
    p.write_bytes(text.encode() if isinstance(text, str) else text)
    return str(p)


# ---------------------------------------------------------------- the plate

def test_plate_sunlit_closed_form():
    """The built-in plate (1 m^2, body +z, one-sided, Lambertian, target_albedo)
    under random attitudes and observers 10 km away: the closed form to 1e-12."""
    qs = random_quaternions(40, 1)
    dirs = np.random.default_rng(2).normal(size=(40, 3))
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    rows = [scene(TARGET + 10.0 * d, q, target_shape="plate", target_albedo=0.3)
            for q, d in zip(qs, dirs)]
    code, out, err = plan(rows)
    assert code == 0, err
    lit = 0
    for r, q, d in zip(out, qs, dirs):
        assert r["status"] == "OK", r
        e_sun = float(r["e_sun"])
        assert abs(e_sun - TSI * AU ** 2 / (AU ** 2 + 7000.0 ** 2)) <= 1e-12 * TSI
        want = plate_flux(e_sun, q, TARGET + 10.0 * d, albedo=0.3)
        got = float(r["flux_obs"])
        assert abs(got - want) <= 1e-12 * max(want, 1e-30) + 1e-300, (q, d, got, want)
        if want > 0:
            lit += 1
            assert abs(float(r["mag_v"]) - (-26.74 - 2.5 * math.log10(got / TSI))) < 1e-9
        else:
            assert float(r["mag_v"]) == MAG_DARK
        assert "glint" not in r["flags"].split("+")
    assert 3 <= lit <= 37  # both sides of the plate were seen


def test_plate_facing_away_is_dark_and_identity_is_default():
    """Identity attitude: the plate's normal is the input +z. An observer on -z
    sees its back (one-sided: nothing); the q columns empty or absent mean
    identity, to the byte."""
    above = TARGET + np.array([0.0, 0.0, 10.0])
    tilt = (math.cos(math.pi / 8), 0.0, math.sin(math.pi / 8), 0.0)  # normal to (1, 0, 1)/sqrt2
    rows = [scene(above, tilt, target_shape="plate"),
            scene(TARGET - np.array([0.0, 0.0, 10.0]), tilt, target_shape="plate"),
            scene(above, (1.0, 0.0, 0.0, 0.0), target_shape="plate"),
            scene(above, ("", "", "", ""), target_shape="plate")]
    code, out, err = plan(rows)
    assert code == 0, err
    front, back, ident, empty = out
    want = plate_flux(float(front["e_sun"]), tilt, above)
    assert want > 0 and abs(float(front["flux_obs"]) - want) <= 1e-12 * want
    assert float(back["flux_obs"]) == 0.0 and float(back["mag_v"]) == MAG_DARK
    # identity: normal +z, the Sun along +x: grazing incidence, nothing
    assert float(ident["flux_obs"]) == 0.0
    assert empty == ident | {"id": empty["id"]}
    code, out2, err = plan([{k: v for k, v in rows[2].items() if not k.startswith("q_")}])
    assert code == 0, err
    assert out2[0] == ident | {"id": out2[0]["id"]}


def test_sphere_is_the_default_and_ignores_attitude():
    """target_shape absent, empty or 'sphere', with or without an attitude:
    the same row, byte for byte (the sphere keeps its numbers)."""
    obs = TARGET + np.array([3.0, 4.0, 5.0])
    base = scene(obs, terms="")
    rows = [base, dict(base, target_shape=""), dict(base, target_shape="sphere"),
            dict(base, target_shape="sphere", q_w=0.5, q_x=0.5, q_y=0.5, q_z=-0.5)]
    code, out, err = plan(rows)
    assert code == 0, err
    first = {k: v for k, v in out[0].items() if k != "id"}
    for r in out[1:]:
        assert {k: v for k, v in r.items() if k != "id"} == first


def test_rotation_invariance():
    """Rotating every position and the attitude together changes no output
    (box-wing and cylinder with every term, earthshine included)."""
    moon = np.array([-200000.0, 300000.0, 50000.0])
    # an attitude that turns the plate's normal towards the Sun's side, the
    # observer out along the normal: every shape lit and seen
    s_dir = (SUN - TARGET) / np.linalg.norm(SUN - TARGET)
    q0 = next(q for q in random_quaternions(50, 5) if rotation(q)[:, 2] @ s_dir > 0.3)
    obs = TARGET + 50.0 * rotation(q0)[:, 2]
    rows = []
    turns = random_quaternions(6, 6)
    for shape in ("box-wing", "cylinder", "plate"):
        for t in turns:
            m = rotation(t)
            q = qmul(t, q0)
            p = dict(target_shape=shape, terms="", q_w=q[0], q_x=q[1], q_y=q[2], q_z=q[3])
            for name, v in (("sun", SUN), ("target", TARGET), ("observer", obs),
                            ("moon", moon)):
                w = m @ v
                p.update({f"{name}_x": w[0], f"{name}_y": w[1], f"{name}_z": w[2]})
            rows.append(p)
    code, out, err = plan(rows)
    assert code == 0, err
    for k in range(3):
        group = out[6 * k: 6 * k + 6]
        ref = group[0]
        assert float(ref["flux_obs"]) > 0, ref
        for r in group[1:]:
            for c in ("e_sun", "e_earth", "e_moon", "flux_obs", "mag_v", "exposure_s", "gain"):
                a, b = float(ref[c]), float(r[c])
                assert abs(a - b) <= 1e-9 * max(abs(a), 1e-300), (c, a, b)
            assert r["flags"] == ref["flags"]


def test_builtin_shapes_are_known():
    obs = TARGET + np.array([0.0, 0.0, 10.0])
    rows = [scene(obs, target_shape=s, terms="") for s in ("plate", "box-wing", "cylinder")]
    code, out, err = plan(rows)
    assert code == 0, err
    for r in out:
        assert r["status"] == "OK" and float(r["flux_obs"]) > 0


# ---------------------------------------------------------------- attitude errors

def test_quaternion_norm():
    """For a facet shape |norm - 1| > 1e-6 (and NaN, and zero) is ERR_SHAPE;
    within 1e-6 the quaternion is normalised: the same numbers as the unit one."""
    obs = TARGET + np.array([0.0, 0.0, 10.0])
    tilt = np.array([math.cos(math.pi / 8), 0.0, math.sin(math.pi / 8), 0.0])
    rows = [scene(obs, tilt, target_shape="plate"),
            scene(obs, tilt * (1 + 5e-7), target_shape="plate"),
            scene(obs, tilt * (1 - 5e-7), target_shape="plate"),
            scene(obs, tilt * (1 + 2e-6), target_shape="plate"),
            scene(obs, tilt * (1 - 2e-6), target_shape="plate"),
            scene(obs, (0.0, 0.0, 0.0, 0.0), target_shape="plate"),
            scene(obs, ("nan", 0.0, 0.0, 0.0), target_shape="plate"),
            scene(obs, (1.0, 0.0, "inf", 0.0), target_shape="plate"),
            scene(obs, (1.0, 0.0, 0.0, ""), target_shape="plate"),
            scene(obs, (1.0, 0.0, "x", 0.0), target_shape="plate")]
    code, out, err = plan(rows)
    assert code == 1
    unit = float(out[0]["flux_obs"])
    assert unit > 0
    for r in out[1:3]:
        assert r["status"] == "OK"
        assert abs(float(r["flux_obs"]) - unit) <= 1e-12 * unit
    for r in out[3:8]:
        assert r["status"] == "ERR_SHAPE", r
        assert r["flux_obs"] == "" and r["e_sun"] == "" and r["flags"] == ""
    assert [r["status"] for r in out[8:]] == ["ERR_PARSE", "ERR_PARSE"]
    assert "not a unit one" in err and "q_z" in err and "expected a number" in err
    # a sphere has no attitude: the library does not read it, and neither is it checked
    code, out, err = plan([scene(obs, (2.0, 0.0, 0.0, 0.0)), scene(obs, ("nan", 0, 0, 0))])
    assert code == 0, err
    assert [r["status"] for r in out] == ["OK", "OK"]


def test_quaternion_columns_come_together():
    text = table([scene(TARGET + 10, target_shape="plate")]).splitlines()
    head = text[0] + ",q_w,q_x,q_y"
    code, out, err = run(["--csv", "-"], stdin=(head + "\n" + text[1] + ",1,0,0\n").encode())
    assert code == 2 and out == ""
    assert "q_w, q_x, q_y, q_z must come together" in err


def test_unknown_shape_name():
    code, out, err = plan([scene(TARGET + 10, target_shape="Plate"),
                           scene(TARGET + 10, target_shape="plate")])
    assert code == 1
    assert [r["status"] for r in out] == ["ERR_SHAPE", "OK"]
    assert 'unknown target_shape "Plate"' in err and "box-wing" in err and "--shapes" in err


# ---------------------------------------------------------------- --shapes

FILE_OK = """# two shapes
shape flat-a   # a plate like the built-in one
 0 0 1  1.0 1  0.2 0 10
shape Two_sided.b
0 0 -3  2.5 2  0.5 0 10
\tshape\tcube
1 0 0 1 1 0.1 0 10
-1 0 0 1 1 0.1 0 10
0 1 0 1 1 0.1 0 10
0 -1 0 1 1 0.1 0 10
0 0 1 1 1 0.1 0 10
0 0 -1 1 1 0.1 0 10
"""


def test_shapes_file_closed_forms(tmp_path):
    """A file's one-sided plate equals the built-in plate (albedo 0.2); a
    two-sided facet reflects from both faces; a cube of six facets: the sum of
    the lit, seen faces."""
    path = shapes_file(tmp_path, FILE_OK.replace("\n", "\r\n", 3))
    obs_up = TARGET + np.array([6.0, 0.0, 8.0])
    obs_down = TARGET + np.array([6.0, 0.0, -8.0])
    q = (math.cos(math.pi / 8), 0.0, math.sin(math.pi / 8), 0.0)
    q_back = (0.0, 1.0, 0.0, 0.0)  # a half turn about x: body +z to input -z
    rows = [scene(obs_up, q, target_shape="plate"), scene(obs_up, q, target_shape="flat-a"),
            scene(obs_up, q, target_shape="Two_sided.b"),
            scene(obs_down, q_back, target_shape="Two_sided.b"),
            scene(obs_up, q, target_shape="cube")]
    code, out, err = plan(rows, "--shapes", path)
    assert code == 0, err
    builtin, flat, two, two_back, cube = out
    e = float(builtin["e_sun"])
    want = plate_flux(e, q, obs_up)
    assert abs(float(builtin["flux_obs"]) - want) <= 1e-12 * want
    assert flat["flux_obs"] == builtin["flux_obs"]
    want2 = plate_flux(e, q, obs_up, albedo=0.5, area=2.5, normal=(0, 0, -1), two_sided=True)
    assert want2 > 0
    assert abs(float(two["flux_obs"]) - want2) <= 1e-12 * want2
    want2b = plate_flux(e, q_back, obs_down, albedo=0.5, area=2.5, normal=(0, 0, -1),
                        two_sided=True)
    assert abs(float(two_back["flux_obs"]) - want2b) <= 1e-12 * want2b
    want_cube = sum(plate_flux(e, q, obs_up, albedo=0.1, normal=n)
                    for n in ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1),
                              (0, 0, -1)))
    assert abs(float(cube["flux_obs"]) - want_cube) <= 1e-12 * want_cube
    # without the file the names are unknown
    code, out, err = plan(rows[1:2])
    assert code == 1 and out[0]["status"] == "ERR_SHAPE"


def test_glint_flag(tmp_path):
    """A mirror-like facet at the mirror geometry: specular dominates -> glint."""
    path = shapes_file(tmp_path, "shape mirror\n0 0 1 1 1 0.0 0.9 500\n"
                                 "shape matte\n0 0 1 1 1 0.9 0.0 500\n")
    # normal (1, 0, 1)/sqrt2, the Sun on +x: the mirror direction is +z
    q = (math.cos(math.pi / 8), 0.0, math.sin(math.pi / 8), 0.0)
    obs = TARGET + np.array([0.0, 7000.0 / AU * 10.0, 10.0])
    code, out, err = plan([scene(obs, q, target_shape="mirror"),
                           scene(obs, q, target_shape="matte")], "--shapes", path)
    assert code == 0, err
    mirror, matte = out
    assert "glint" in mirror["flags"].split("+")
    assert "glint" not in matte["flags"].split("+")
    assert float(mirror["flux_obs"]) > float(matte["flux_obs"])


BAD_FILES = [
    ("", 1, "no shapes in the file"),
    ("# only a comment\n\n", 2, "no shapes in the file"),
    ("0 0 1 1 1 0.2 0 10\n", 1, "a facet before any 'shape NAME' line"),
    ("shape a\n", 1, "shape has no facets: a"),
    ("shape a\nshape b\n0 0 1 1 1 0.2 0 10\n", 1, "shape has no facets: a"),
    ("shape\n", 1, "expected 'shape NAME'"),
    ("shape a b\n", 1, "expected 'shape NAME'"),
    ("shape a/b\n", 1, "bad shape name"),
    ("shape " + "x" * 32 + "\n", 1, "bad shape name"),
    ("shape plate\n0 0 1 1 1 0.2 0 10\n", 1, "built-in shape"),
    ("shape sphere\n0 0 1 1 1 0.2 0 10\n", 1, "built-in shape"),
    ("shape a\n0 0 1 1 1 0.2 0 10\nshape a\n", 3, "shape defined twice: 'a' (first at line 1)"),
    ("shape a\n0 0 1 1 1 0.2 0\n", 2, "(7 fields)"),
    ("shape a\n0 0 1 1 1 0.2 0 10 5\n", 2, "(more than 8 fields)"),
    ("shape a\n0 0 1 1 1 0.2 zero 10\n", 2, 'expected a number for albedo_specular, got "zero"'),
    ("shape a\n0 0 1 1x 1 0.2 0 10\n", 2, "expected a number for area_m2"),
    ("shape a\n0 0 1 0x1p0 1 0.2 0 10\n", 2, 'expected a number for area_m2, got "0x1p0"'),
    ("shape a\n0 0 0x1 1 1 0.2 0 10\n", 2, 'expected a number for nz, got "0x1"'),
    ("shape a\nnan 0 1 1 1 0.2 0 10\n", 2, "expected a finite number for nx"),
    ("shape a\n0 0 1 inf 1 0.2 0 10\n", 2, "expected a finite number for area_m2"),
    ("shape a\n0 0 1 1 1 0.2 0 1e999\n", 2, "expected a finite number for shininess"),
    ("shape a\n0 0 0 1 1 0.2 0 10\n", 2, "the normal is zero"),
    ("shape a\n0 0 1 0 1 0.2 0 10\n", 2, "area_m2 must be above 0"),
    ("shape a\n0 0 1 -1 1 0.2 0 10\n", 2, "area_m2 must be above 0"),
    ("shape a\n0 0 1 1 0 0.2 0 10\n", 2, "sided must be 1 or 2"),
    ("shape a\n0 0 1 1 1.5 0.2 0 10\n", 2, "sided must be 1 or 2"),
    ("shape a\n0 0 1 1 1 -0.1 0 10\n", 2, "must be in [0, 1]"),
    ("shape a\n0 0 1 1 1 0.2 1.1 10\n", 2, "must be in [0, 1]"),
    ("shape a\n0 0 1 1 1 0.6 0.5 10\n", 2, "must not exceed 1"),
    ("shape a\n0 0 1 1 1 0.2 0.1 -5\n", 2, "the library rejects this facet: ERR_SHAPE"),
    ("shape a\n" + "0 0 1 1 1 0.2 0 10\n" * 33, 34, "more than OI_FACETS_MAX = 32 facets"),
    ("".join(f"shape s{k}\n0 0 1 1 1 0.2 0 10\n" for k in range(17)), 33,
     "too many shapes (at most 16)"),
    ("shape a\n0 0 1 1 1 0.2 0 10" + " " * 1100 + "\n", 2, "line too long"),
    (b"shape a\n0 0 1 1 1 0.2\x00 0 10\n", 2, "NUL byte in the line"),
]


@pytest.mark.parametrize("text,line,what", BAD_FILES)
def test_bad_shapes_file(tmp_path, text, line, what):
    """Every problem: exit 2, nothing on stdout, 'FILE:LINE: what' on stderr."""
    path = shapes_file(tmp_path, text)
    code, out, err = run(["--csv", "-", "--shapes", path],
                         stdin=table([scene(TARGET + 10, target_shape="plate")]).encode())
    assert code == 2 and out == "", err
    assert f"oi-plan: {path}:{line}: " in err, err
    assert what in err, err


def test_shapes_option_misuse(tmp_path):
    stdin = table([scene(TARGET + 10)]).encode()
    code, out, err = run(["--csv", "-", "--shapes", str(tmp_path / "missing.txt")], stdin=stdin)
    assert code == 2 and "cannot open shapes file" in err
    code, out, err = run(["--csv", "-", "--shapes", "-"], stdin=stdin)
    assert code == 2 and "--shapes wants a file" in err
    code, out, err = run(["--csv", "-", "--shapes"], stdin=stdin)
    assert code == 2 and "needs a value" in err
    path = shapes_file(tmp_path, "shape a\n0 0 1 1 1 0.2 0 10\n")
    code, out, err = run(["--shapes", path])
    assert code == 2 and "--shapes applies to --csv" in err
    code, out, err = run([f"--shapes={path}", "--csv", "-"], stdin=stdin)
    assert code == 0, err


def test_full_shapes_file_is_accepted(tmp_path):
    """The documented bounds are reachable: 16 shapes of 32 facets."""
    text = "".join(f"shape s{k}\n" + "0 0 1 0.5 2 0.2 0.1 10\n" * 32 for k in range(16))
    path = shapes_file(tmp_path, text)
    rows = [scene(TARGET + np.array([0, 0, 10.0]), (math.cos(0.3), 0, math.sin(0.3), 0),
                  target_shape=f"s{k}") for k in (0, 15)]
    code, out, err = run(["--csv", "-", "--shapes", path], stdin=table(rows).encode())
    assert code == 0, err
    a, b = list(csv.DictReader(io.StringIO(out)))
    assert a["flux_obs"] == b["flux_obs"] and float(a["flux_obs"]) > 0


def test_help_mentions_shapes():
    code, out, _ = run(["--help"])
    assert code == 0
    for word in ("--shapes FILE", "target_shape", "q_w,q_x,q_y,q_z", "glint"):
        assert word in out
