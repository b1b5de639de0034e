# SPDX-License-Identifier: MIT
"""The binding's docstring examples run (doctest) against the installed binding
(make binding), module by module; every call of orbillum.__all__ has one; the
face (orbillum/__init__.py) defines no call of its own and offers every name it
offered as one module; the installed modules are the source tree's (else the
examples would be those of an older install)."""
import ctypes
import doctest
import filecmp
import importlib
import os
import types

import pytest

orbillum = pytest.importorskip("orbillum", reason="binding not installed: make binding")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SOURCE = os.path.join(ROOT, "python", "orbillum")
# the package's modules, those of the source tree (orbillum.catalog, a
# subpackage with its own tests, aside; the installed liborbillum.so is no module)
MODULES = ["orbillum"] + sorted("orbillum." + f[:-3] for f in os.listdir(SOURCE)
                                if f.endswith(".py") and f != "__init__.py")
FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE

# the names `import orbillum` offered when it was one module (besides OI_*)
PUBLIC = ["EXPOSURE_DTYPE", "FACET_DTYPE", "ILLUM_DTYPE", "L", "SCENE_DTYPE", "Shape", "camera",
          "cameras", "ctypes", "earthshine", "expose", "expose_flux", "facet_brdf", "flag_names",
          "flux_from_magnitude", "galactic", "illuminate", "lambert_phase", "library_path",
          "magnitude_v", "moon_phase_law", "np", "shape", "shapes", "starlight_radiance",
          "status_name", "sun_fraction", "terms_mask"]


def _run(obj, name, globs):
    """The examples of obj's docstrings (and of what it defines): (examples,
    failures, report)."""
    finder = doctest.DocTestFinder()
    runner = doctest.DocTestRunner(optionflags=FLAGS)
    out = []
    n = 0
    for test in finder.find(obj, name, globs=dict(globs)):
        n += len(test.examples)
        runner.run(test, out=out.append)
    return n, runner.failures, "".join(out)


@pytest.mark.parametrize("name", MODULES)
def test_examples_run(name):
    mod = importlib.import_module(name)
    n, failed, report = _run(mod, name, vars(mod))
    assert failed == 0, report


def test_modules_found():
    # the split's modules, so that test_examples_run cannot pass on none
    for m in ("illumination", "exposure", "shadow", "facets", "photometry", "sky", "_runtime",
              "_status", "_arrays", "_models", "_lib"):
        assert "orbillum." + m in MODULES, m


CALLS = [n for n in orbillum.__all__ if not n.startswith("OI_") and callable(getattr(orbillum, n))]


@pytest.mark.parametrize("name", CALLS)
def test_call_has_examples(name):
    obj = getattr(orbillum, name)
    n, failed, report = _run(obj, name, {})
    assert n > 0, f"orbillum.{name}: no example in its docstring"
    assert failed == 0, report


def test_main_calls_listed():
    for n in ("sun_fraction", "illuminate", "expose", "expose_flux", "earthshine", "magnitude_v",
              "flux_from_magnitude", "Shape", "camera"):
        assert n in CALLS, n


def test_face_is_thin():
    """orbillum/__init__.py imports and re-exports: every call lives in a
    module by subject."""
    for n in CALLS + ["_scenes"]:
        assert getattr(orbillum, n).__module__.startswith("orbillum."), n


def test_names_kept():
    for n in PUBLIC:
        assert hasattr(orbillum, n), n
    # underscore names that tests, tools and bench use
    assert isinstance(orbillum._lib, ctypes.CDLL) and orbillum._lib.oi_illuminate_batch.argtypes
    assert orbillum._lib is orbillum._runtime._lib
    assert isinstance(orbillum.L, types.ModuleType) and orbillum.L.__name__ == "orbillum._lib"
    assert orbillum.L.oi_scene is orbillum._runtime.L.oi_scene
    assert callable(orbillum._scenes)
    assert orbillum.shapes() == orbillum.facets.shapes()  # a call, not the module facets


def test_installed_is_source():
    installed = os.path.dirname(os.path.abspath(orbillum.__file__))
    if os.path.samefile(installed, SOURCE):
        return  # PYTHONPATH=python: the source tree itself
    names = sorted(f for f in os.listdir(SOURCE) if f.endswith(".py"))
    match, mismatch, errors = filecmp.cmpfiles(SOURCE, installed, names, shallow=False)
    assert not mismatch and not errors, (f"{installed} differs from python/orbillum in "
                                         f"{mismatch + errors}: run `make binding`")
