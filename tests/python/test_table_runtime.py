# SPDX-License-Identifier: MIT
"""The C runtime's lookup (src/sources/earthshine.c, build/liborbillum.a) equals the
numpy mirror (bake/earthshine/lookup.py) that the bake's error measurement uses, so
the measured errors in the provenance hold for the runtime."""

import glob
import math
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.dirname(__file__))

from bake.earthshine import lookup  # noqa: E402
from bake.earthshine import reference as ref  # noqa: E402
from test_table import load_table  # noqa: E402

LIB = os.path.join(ROOT, "build", "liborbillum.a")

PROG = r"""
#include <stdio.h>
#include "orbillum.h"
int main(void)
{
    double th, h;
    while (scanf("%lf %lf", &th, &h) == 2) {
        oi_real phi, psi;
        int st = oi_earthshine((oi_real)th, (oi_real)h, NULL, &phi, &psi);
        printf("%d %.17g %.17g\n", st, (double)phi, (double)psi);
    }
    return 0;
}
"""


@pytest.mark.skipif(shutil.which("cc") is None or not os.path.exists(LIB),
                    reason="needs cc and build/liborbillum.a (make lib)")
def test_c_lookup_equals_python_mirror(tmp_path):
    src = tmp_path / "es.c"
    src.write_text(PROG)
    exe = str(tmp_path / "es")
    subprocess.run(["cc", "-std=c99", "-O2", "-I" + os.path.join(ROOT, "include"), str(src), LIB,
                    "-lm", "-o", exe], check=True)
    rng = np.random.default_rng(11)
    n = 4000
    h = 10 ** rng.uniform(-3.0, 7.0, n)  # 1 m .. 1e7 km (the table reaches the surface)
    th = rng.uniform(0.0, math.pi, n)
    inp = "\n".join("%.17g %.17g" % (a, b) for a, b in zip(th, h))
    out = subprocess.run([exe], input=inp, capture_output=True, text=True, check=True).stdout
    a = np.array([line.split() for line in out.splitlines()], dtype=float)
    st, phi_c, psi_c = a.T
    assert np.all(st == 0)
    spec, q, psi, _, _ = load_table("oi_earth_diffuse")
    phi_p, psi_p = lookup.lookup(spec, q.astype(float), psi.astype(float), th, ref.x_from_h(h))
    phi0 = ref.phi_reference(np.zeros(n), ref.x_from_h(h), 24, 24)
    assert np.max(np.abs(phi_c - phi_p) / phi0) < 1e-12
    assert np.max(np.abs(psi_c - psi_p)) < 1e-12


PROG_NO_TABLE = r"""
#include <stdio.h>
#include <math.h>
#include "orbillum.h"
int main(void)
{
    oi_real phi, psi;
    double x = 6378.137 / (6378.137 + 500.0), t = 1.1;
    double want = x * x * 2.0 / (3.0 * 3.14159265358979323846) *
                  ((3.14159265358979323846 - t) * cos(t) + sin(t));
    int st = oi_earthshine((oi_real)t, (oi_real)500.0, NULL, &phi, &psi);
    printf("%d %.17g %.17g %.17g\n", st, (double)phi, (double)psi, want);
    return 0;
}
"""


@pytest.mark.skipif(shutil.which("cc") is None, reason="needs cc")
@pytest.mark.parametrize("defs", [[], ["-DOI_SINGLE_PRECISION"]])
def test_no_earth_table_falls_back_to_far_field(tmp_path, defs):
    """-DOI_NO_EARTH_TABLE: nothing refers to the default table, so it is not
    linked (it compiles the same under every option; the linker leaves it
    out), and oi_earthshine uses the Lambert far field with
    OI_WARN_TABLE_RANGE (1)."""
    src = tmp_path / "nt.c"
    src.write_text(PROG_NO_TABLE)
    exe = str(tmp_path / "nt")
    warn = ["-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wshadow",
            "-Wdouble-promotion", "-Werror"]
    # every runtime source and every table: what nothing refers to is left out
    files = sorted(glob.glob(os.path.join(ROOT, "src", "*", "*.c")) +
                   glob.glob(os.path.join(ROOT, "tables", "*.c")))
    inc = ["-I" + os.path.join(ROOT, d) for d in ("include", "src", "tables")]
    subprocess.run(["cc"] + warn + ["-O2", "-ffunction-sections", "-fdata-sections",
                                    "-Wl,--gc-sections", "-DOI_NO_EARTH_TABLE"] + defs + inc +
                   files + [str(src), "-lm", "-o", exe], check=True)
    out = subprocess.run(["nm", exe], capture_output=True, text=True, check=True).stdout
    assert "oi_earth_diffuse" not in out
    st, phi, psi, want = subprocess.run([exe], capture_output=True, text=True,
                                        check=True).stdout.split()
    assert int(st) == 1 and float(psi) == 0.0
    assert abs(float(phi) / float(want) - 1) < (1e-5 if defs else 1e-13)
