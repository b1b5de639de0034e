# SPDX-License-Identifier: MIT
"""The brightest-pixel fraction from the optics (tools/psf_peak.py;
docs/camera.md, "Optics"): the frequency-plane integral against closed
forms for a Gaussian PSF (centred and at a pixel's corner), against a
direct spatial quadrature of the Airy pattern over a pixel (scipy dblquad
of the Bessel-function intensity, a different method), its limits, and the
built-in cameras' psf_peak_fraction against the tool's value for their
optics."""
import math
import sys
from pathlib import Path

import pytest
from scipy import integrate, special

import orbillum

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import psf_peak  # noqa: E402


def phi(x):
    return 0.5 * math.erfc(-x / math.sqrt(2.0))


@pytest.mark.parametrize("sigma", [0.3, 0.67, 1.0, 2.5])
def test_gaussian_closed_form(sigma):
    centred = math.erf(1.0 / (2.0 * math.sqrt(2.0) * sigma)) ** 2
    corner = (phi(1.0 / sigma) - 0.5) ** 2
    assert psf_peak.pixel_fraction(0.0, 0.0, sigma) == pytest.approx(centred, rel=1e-9)
    assert psf_peak.pixel_fraction(0.5, 0.5, sigma) == pytest.approx(corner, rel=1e-9)
    # off-axis along one side: separable, [Phi((x+1/2)/s) - Phi((x-1/2)/s)] per axis
    x0 = 0.3
    side = (phi((x0 + 0.5) / sigma) - phi((x0 - 0.5) / sigma)) * \
        (phi(0.5 / sigma) - phi(-0.5 / sigma))
    assert psf_peak.pixel_fraction(x0, 0.0, sigma) == pytest.approx(side, rel=1e-9)


def airy_pixel_direct(lam_f_px, x0, y0):
    """The pixel at offset (x0, y0) of the normalised Airy intensity
    pi / (4 (lambda F)^2) [2 J1(x) / x]^2, x = pi r / (lambda F), by dblquad."""
    def intensity(y, x):
        r = math.hypot(x, y)
        if r < 1e-12:
            return math.pi / (4.0 * lam_f_px ** 2)
        u = math.pi * r / lam_f_px
        return math.pi / (4.0 * lam_f_px ** 2) * (2.0 * special.j1(u) / u) ** 2
    v, _ = integrate.dblquad(intensity, x0 - 0.5, x0 + 0.5, y0 - 0.5, y0 + 0.5,
                             epsabs=1e-10, epsrel=1e-9)
    return v


@pytest.mark.parametrize("lam_f_px", [0.5, 1.0])
def test_airy_against_spatial_quadrature(lam_f_px):
    """Diffraction alone, monochromatic: lambda F of 0.5 and 1 pixel (the cut-off
    frequency is 1 / (lambda F) cycles per pixel)."""
    cutoff = 1.0 / lam_f_px
    for x0, y0 in ((0.0, 0.0), (0.5, 0.5)):
        got = psf_peak.pixel_fraction(x0, y0, 0.0, cutoff, n_rho=600, n_theta=512)
        want = airy_pixel_direct(lam_f_px, x0, y0)
        assert got == pytest.approx(want, abs=2e-6), (x0, y0)


def test_limits():
    """Diffraction alone with lambda F of 0.05 pixel: the centred pixel holds
    between the Airy encircled energy 1 - J0(x)^2 - J1(x)^2 of its inscribed
    and of its circumscribed circle (x = pi r / (lambda F)); a blur much
    wider than a pixel tends to the Gaussian's peak density 1 / (2 pi s^2)."""
    lam_f = 0.05
    got = psf_peak.pixel_fraction(0.0, 0.0, 0.0, 1.0 / lam_f)

    def ee(r):
        x = math.pi * r / lam_f
        return 1.0 - special.j0(x) ** 2 - special.j1(x) ** 2
    assert ee(0.5) < got < ee(math.sqrt(0.5))
    s = 20.0
    assert psf_peak.pixel_fraction(0.0, 0.0, s, 200.0) == pytest.approx(
        1.0 / (2.0 * math.pi * s * s), rel=1e-3)


def test_builtin_cameras_use_the_tool():
    """Each built-in camera's psf_peak_fraction is the tool's centred value for
    its optics and stated blur, to the 4 digits stored."""
    for name, p in psf_peak.CAMERAS.items():
        cam = orbillum.camera(name)
        assert cam["aperture_m"] == p["aperture_m"] and cam["pixel_pitch_m"] == p["pitch_m"]
        assert cam["focal_length_m"] == p["focal_m"]
        want = psf_peak.camera_fraction(p["aperture_m"], p["focal_m"], p["pitch_m"],
                                        p["sigma_px"])
        assert abs(cam["psf_peak_fraction"] - want) < 1e-4, (name, cam["psf_peak_fraction"], want)
