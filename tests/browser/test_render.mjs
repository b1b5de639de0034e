// SPDX-License-Identifier: MIT
// test_render.mjs: the viewer's camera picture (web/src/render.js) against the runtime (wasm), as
// tests/python/test_binding_render.py checks examples/render/view.py: the rendered radiance summed
// over the image is the flux the runtime computes in closed form, per source (two independent
// computations of one quantity), and the picture's electrons are the runtime's signal_e.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';

const ROOT = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const BUILD = process.env.BUILDDIR ? path.resolve(ROOT, process.env.BUILDDIR) : path.join(ROOT, 'build');
const { loadOrbillum } = await import(path.join(BUILD, 'wasm/orbillum.js'));
const { radianceImage, renderView, psfSigmaPx } = await import(path.join(ROOT, 'web/src/render.js'));
const oi = await loadOrbillum(fs.readFileSync(path.join(BUILD, 'wasm/orbillum.wasm')));

// a GEO target, the observer rangeKm away at phaseDeg from the Sun direction (test_binding_render.py)
function scene(phaseDeg, rangeKm = 5.0, radiusM = 2.0, albedo = 0.25) {
  const au = 149597870.7;
  const sun = [au, 0, 0];
  const tgt = [0, 42164, 0];
  const d = Math.hypot(sun[0] - tgt[0], sun[1] - tgt[1], sun[2] - tgt[2]);
  const s = [(sun[0] - tgt[0]) / d, (sun[1] - tgt[1]) / d, (sun[2] - tgt[2]) / d];
  const ph = (phaseDeg * Math.PI) / 180;
  const obs = tgt.map((t, i) => t + rangeKm * (Math.cos(ph) * s[i] + Math.sin(ph) * [0, 0, 1][i]));
  return { sun_km: sun, moon_km: [-300000, 200000, 50000], target_km: tgt, observer_km: obs, has_observer: true,
    target_radius_m: radiusM, target_albedo: albedo };
}

for (const phase of [5, 60, 120, 170]) {
  test(`rendered flux per source equals the runtime's, phase ${phase} deg`, () => {
    const cam = oi.findCamera('telescope-15cm');
    const sc = scene(phase);
    const r = oi.compute(sc, {}, cam);
    assert.equal(oi.statusName(r.status), 'OK');
    const { L, meta } = radianceImage(sc, r.illum, cam, null, { subpixAcross: 192, maxGrid: 4000 });
    for (const s of ['sun', 'earth', 'moon']) {
      const got = L[s].reduce((a, b) => a + b, 0) * meta.subpixSr;
      const want = r.illum[`flux_${s}`];
      // pixelised limb and terminator: ~1e-3 relative, worse for thin crescents (phase > 150 deg)
      const tol = (r.illum[`phase_${s}`] * 180) / Math.PI < 150 ? 3e-3 : 3e-2;
      assert.ok(Math.abs(got - want) <= tol * want + 1e-30, `${s}: want ${want} got ${got}`);
    }
  });
}

test("an unresolved target's electrons times the PSF peak fraction are the runtime's signal_e", () => {
  const cam = oi.findCamera('star-tracker');
  const sc = { ...scene(40, 300, 1.0, 0.2) };
  const r = oi.compute(sc, {}, cam);
  const v = renderView(sc, r.illum, r.expo, cam);
  assert.ok(v.meta.diamPx < 1);
  const got = v.meta.signalTotalE * cam.psf_peak_fraction;
  assert.ok(Math.abs(got / r.expo.signal_e - 1) < 5e-3, `want ${r.expo.signal_e} got ${got}`);
});

test('the PSF width holds the camera peak fraction in the centred pixel', () => {
  // erf from a series independent of render.js's approximation
  const erf = (x) => { let s = 0; let t = x; for (let n = 0; n < 60; n++) { s += t / (2 * n + 1); t *= (-x * x) / (n + 1); } return (2 / Math.sqrt(Math.PI)) * s; };
  for (const f of [0.9, 0.5, 0.3, 0.25, 0.05]) {
    const sigma = psfSigmaPx(f);
    const got = erf(1 / (2 * Math.SQRT2 * sigma)) ** 2;
    assert.ok(Math.abs(got - f) < 1e-6, `${f}: ${got}`);
  }
});
