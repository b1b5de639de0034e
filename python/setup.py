# SPDX-License-Identifier: MIT
"""Build hook: compile the runtime (../src/<layer>/*.c, ../tables/*.c) into orbillum/liborbillum.so.

The C sources live beside this directory in the repository, so install from a
checkout: ``pip install ./python``. The flags are the repository Makefile's own,
read from it (WARN, OPT, RT_MATH), plus -fPIC; the compiler is $CC or cc. Set ORBILLUM_LIB at run time to use another build instead (e.g. build/liborbillum.so from ``make shared``).

Extras: ``pip install "./python[catalog]"`` installs what the catalogue planner
(orbillum.catalog) needs, ``[plots]`` matplotlib for the examples' plots, each
pinned to the version of ../requirements.lock (read here, so the two agree).
"""
import glob
import os
import shlex
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def make_variable(name):
    """The words of the Makefile's `NAME := value` or `NAME ?= value` line: the
    library's flags are written once, there."""
    with open(os.path.join(ROOT, "Makefile")) as f:
        for line in f:
            for sep in (":=", "?="):
                key, found, value = line.partition(sep)
                if found and key.strip() == name:
                    return shlex.split(value, comments=True)
    raise SystemExit(f"orbillum: no {name} in ../Makefile: install from a repository checkout")


#: the extras and the packages each needs; the versions are requirements.lock's
EXTRAS = {"catalog": ("astropy", "sgp4", "pyarrow", "tqdm", "dask", "distributed"),
          "plots": ("matplotlib",)}


def locked_extras():
    """EXTRAS with each package pinned as ../requirements.lock pins it."""
    pins = {}
    with open(os.path.join(ROOT, "requirements.lock")) as f:
        for line in f:
            name, found, version = line.split("#", 1)[0].strip().partition("==")
            if found:
                pins[name.lower()] = version.strip()
    missing = [p for names in EXTRAS.values() for p in names if p not in pins]
    if missing:
        raise SystemExit(f"orbillum: no pin for {', '.join(missing)} in ../requirements.lock")
    return {extra: [f"{p}=={pins[p]}" for p in names] for extra, names in EXTRAS.items()}


class BuildWithLibrary(build_py):
    def run(self):
        super().run()
        # the runtime's layers (src/<layer>/), in the order of their file names as the Makefile links them
        src = sorted(glob.glob(os.path.join(ROOT, "src", "*", "*.c")), key=os.path.basename) + \
            sorted(glob.glob(os.path.join(ROOT, "tables", "*.c")))
        if not src:
            raise SystemExit("orbillum: the C sources (../src) are not beside python/: "
                             "install from a repository checkout with `pip install ./python`")
        out_dir = os.path.join(self.build_lib, "orbillum")
        os.makedirs(out_dir, exist_ok=True)
        out = os.path.join(out_dir, "liborbillum.so")
        cc = shlex.split(os.environ.get("CC", "cc"))
        # the library's own flags (RT_MATH's -fno-math-errno makes sqrt one
        # instruction, so that the batch's loops vectorise)
        flags = make_variable("WARN") + make_variable("OPT") + make_variable("RT_MATH")
        cmd = cc + flags + ["-fPIC", "-shared"] + [
            "-I" + os.path.join(ROOT, d) for d in ("include", "src", "tables")
        ] + src + ["-lm", "-o", out]
        print(" ".join(cmd))
        subprocess.check_call(cmd)


class BinaryDistribution(Distribution):
    """The wheel carries a compiled library: tag it for this platform."""

    def has_ext_modules(self):
        return True


setup(cmdclass={"build_py": BuildWithLibrary}, distclass=BinaryDistribution,
      extras_require=locked_extras())
