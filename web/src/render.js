// SPDX-License-Identifier: MIT
// render.js: what the observer's camera sees, as examples/render/view.py draws it: a Lambertian
// sphere lit by each source from the runtime's irradiance and direction, the camera frame at the
// chosen exposure and gain with photon and read noise, an HDR (logarithmic) view and the light of
// each source in false colour. Sum L dOmega over the image equals the runtime's flux_obs.

/** A target fewer pixels across than this is drawn as the PSF blob. */
export const RESOLVED_PX = 4.0;
/** Decades of radiance the HDR view shows. */
export const HDR_DECADES = 8.0;
const MIN_SUBPIX_ACROSS = 48;
const TINT = { sun: [1.0, 0.85, 0.6], earth: [0.25, 0.5, 1.0], moon: [0.3, 1.0, 0.4] };

// erf, Abramowitz & Stegun 7.1.26 (|error| < 1.5e-7): for the PSF's shape only
function erf(x) {
  const s = Math.sign(x); const a = Math.abs(x);
  const t = 1 / (1 + 0.3275911 * a);
  const y = 1 - (((((1.061405429 * t - 1.453152027) * t) + 1.421413741) * t - 0.284496736) * t + 0.254829592) * t * Math.exp(-a * a);
  return s * y;
}

/** Sigma (pixels) of a Gaussian PSF whose centred pixel holds peakFraction. */
export function psfSigmaPx(peakFraction) {
  if (!(peakFraction > 0 && peakFraction < 1)) return 0;
  let lo = 1e-3; let hi = 50;
  for (let k = 0; k < 80; k++) {
    const mid = 0.5 * (lo + hi);
    if (erf(1 / (2 * Math.SQRT2 * mid)) ** 2 > peakFraction) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => Math.sqrt(dot(a, a));
const unit = (a) => { const n = norm(a); return [a[0] / n, a[1] / n, a[2] / n]; };

/** Boresight basis: forward to the target, up away from the Earth (as view.py). */
export function basis(forward, observer) {
  const f = unit(forward);
  let up0 = unit(observer);
  if (Math.abs(dot(f, up0)) > 0.99) up0 = Math.abs(f[2]) < 0.9 ? [0, 0, 1] : [1, 0, 0];
  const r = unit(cross(f, up0));
  const u = cross(r, f);
  return { f, r, u };
}

/** Vertices (metres) and triangles of a Wavefront OBJ text (v and f records; faces fanned). */
export function parseObj(text) {
  const verts = []; const tris = [];
  for (const line of text.split('\n')) {
    const p = line.trim().split(/\s+/);
    if (p[0] === 'v') verts.push(p.slice(1, 4).map(Number));
    else if (p[0] === 'f') {
      const idx = p.slice(1).map((q) => { const k = parseInt(q.split('/')[0], 10); return k > 0 ? k - 1 : verts.length + k; });
      for (let j = 1; j + 1 < idx.length; j++) tris.push([idx[0], idx[j], idx[j + 1]]);
    }
  }
  return { verts, tris };
}

/**
 * Attitude "nadir-sun" (examples/render/facets.py): body +z to the Earth's centre, +x towards
 * the Sun projected on the plane normal to nadir, +y = z x x. Returns the body axes [x, y, z].
 */
export function nadirSunAttitude(targetKm, sunKm) {
  const z = unit(targetKm.map((v) => -v));
  const s = unit(sub(sunKm, targetKm));
  let x = sub(s, z.map((v) => v * dot(s, z)));
  if (norm(x) < 1e-9) x = cross(z, Math.abs(z[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]);
  x = unit(x);
  return [x, cross(z, x), z];
}

/* Facets in the inertial frame (km, target-centred) with their unit normals. */
function placeModel(model, axes) {
  const P = model.verts.map((v) => [0, 1, 2].map((i) => (v[0] * axes[0][i] + v[1] * axes[1][i] + v[2] * axes[2][i]) / 1000));
  return model.tris.map(([a, b, c]) => {
    const A = P[a]; const e1 = sub(P[b], A); const e2 = sub(P[c], A);
    return { A, e1, e2, n: unit(cross(e1, e2)) };
  });
}

/* Nearest facet hit by the ray o + t d (Moller & Trumbore 1997), or null. */
function castFacets(o, d, facets) {
  let best = Infinity; let hit = null;
  for (const f of facets) {
    const pv = cross(d, f.e2);
    const det = dot(pv, f.e1);
    if (Math.abs(det) < 1e-30) continue;
    const inv = 1 / det;
    const tv = sub(o, f.A);
    const u = dot(pv, tv) * inv;
    if (u < 0 || u > 1) continue;
    const qv = cross(tv, f.e1);
    const v = dot(d, qv) * inv;
    if (v < 0 || u + v > 1) continue;
    const t = dot(qv, f.e2) * inv;
    if (t > 0 && t < best) { best = t; hit = f; }
  }
  return hit;
}

/**
 * Noiseless radiance per source on a sub-pixel grid, and its geometry. model: null (the sphere of
 * the scene's radius) or parseObj()'s facets, in the nadir-sun attitude, two-sided facets.
 */
export function radianceImage(scene, illum, cam, model = null, { subpixAcross = MIN_SUBPIX_ACROSS, maxGrid = 480 } = {}) {
  const tgt = scene.target_km; const obs = scene.observer_km;
  const facets = model ? placeModel(model, nadirSunAttitude(tgt, scene.sun_km)) : null;
  const aKm = model ? Math.max(...model.verts.map(norm)) / 1000 : (scene.target_radius_m ?? 1.0) / 1000.0;
  const albedo = scene.target_albedo ?? 0.2;
  const los = sub(tgt, obs);
  const d = norm(los);
  const { f, r, u } = basis(los, obs);
  const ifov = cam.pixel_pitch_m / cam.focal_length_m;
  const rho = Math.asin(Math.min(aKm / d, 1));
  const diamPx = (2 * rho) / ifov;
  let cropPx = Math.floor(Math.min(Math.max(24, Math.ceil(2.6 * diamPx) + 8), 400));
  const resolved = diamPx >= RESOLVED_PX;
  let m; let step; let os;
  if (resolved) {
    os = Math.max(1, Math.ceil(subpixAcross / diamPx));
    os = Math.min(os, Math.max(1, Math.floor(maxGrid / cropPx))); // keep the grid drawable
    m = cropPx * os; step = ifov / os;
  } else {
    m = Math.ceil(1.25 * subpixAcross); step = (2 * rho) / subpixAcross; os = ifov / step;
  }
  const oc = sub(obs, tgt);
  const cc = dot(oc, oc) - aKm * aKm;
  const L = { sun: new Float64Array(m * m), earth: new Float64Array(m * m), moon: new Float64Array(m * m) };
  const src = ['sun', 'earth', 'moon'].map((s) => ({ s, e: illum[`e_${s}`], dir: illum[`dir_${s}`] }))
    .filter((x) => x.e > 0 && norm(x.dir) > 0);
  for (let iy = 0; iy < m; iy++) {
    const ay = -(iy - (m - 1) / 2) * step;
    const ty = Math.tan(ay);
    for (let ix = 0; ix < m; ix++) {
      const tx = Math.tan((ix - (m - 1) / 2) * step);
      const dir = unit([f[0] + tx * r[0] + ty * u[0], f[1] + tx * r[1] + ty * u[1], f[2] + tx * r[2] + ty * u[2]]);
      if (facets) {
        const hit = castFacets(oc, dir, facets);
        if (!hit) continue;
        const n = dot(hit.n, dir) > 0 ? hit.n.map((v) => -v) : hit.n; // the side facing the viewer
        for (const x of src) L[x.s][iy * m + ix] = (albedo / Math.PI) * x.e * Math.max(0, dot(n, x.dir));
        continue;
      }
      const b = dot(dir, oc);
      const disc = b * b - cc;
      if (disc < 0) continue;
      const t = -b - Math.sqrt(disc);
      const p = [obs[0] + t * dir[0], obs[1] + t * dir[1], obs[2] + t * dir[2]];
      const n = [(p[0] - tgt[0]) / aKm, (p[1] - tgt[1]) / aKm, (p[2] - tgt[2]) / aKm];
      for (const x of src) L[x.s][iy * m + ix] = (albedo / Math.PI) * x.e * Math.max(0, dot(n, x.dir));
    }
  }
  return { L, m, meta: { range_km: d, ifov, diamPx, cropPx, os, subpixSr: step * step, resolved, shape: model ? 'facets' : 'sphere' } };
}

/** Electrons per (W/m^2/sr) in one sub-pixel during the exposure. */
function electronsPerRadiance(cam, exposureS, subpixSr) {
  const area = Math.PI * (cam.aperture_m / 2) ** 2;
  return subpixSr * area * cam.transmission * cam.band_fraction * cam.quantum_efficiency / cam.photon_energy_j * exposureS;
}

function gaussBlur(img, m, sigma) {
  const rad = Math.max(1, Math.ceil(4 * sigma));
  const k = new Float64Array(2 * rad + 1);
  let s = 0;
  for (let i = -rad; i <= rad; i++) { k[i + rad] = Math.exp(-(i * i) / (2 * sigma * sigma)); s += k[i + rad]; }
  for (let i = 0; i < k.length; i++) k[i] /= s;
  const tmp = new Float64Array(m * m); const out = new Float64Array(m * m);
  for (let y = 0; y < m; y++) for (let x = 0; x < m; x++) {
    let v = 0;
    for (let i = -rad; i <= rad; i++) { const xx = x + i; if (xx >= 0 && xx < m) v += img[y * m + xx] * k[i + rad]; }
    tmp[y * m + x] = v;
  }
  for (let y = 0; y < m; y++) for (let x = 0; x < m; x++) {
    let v = 0;
    for (let i = -rad; i <= rad; i++) { const yy = y + i; if (yy >= 0 && yy < m) v += tmp[yy * m + x] * k[i + rad]; }
    out[y * m + x] = v;
  }
  return out;
}

function bin(img, m, k) {
  const n = Math.floor(m / k);
  const out = new Float64Array(n * n);
  for (let y = 0; y < n * k; y++) for (let x = 0; x < n * k; x++) out[Math.floor(y / k) * n + Math.floor(x / k)] += img[y * m + x];
  return { img: out, n };
}

/** A small seeded generator (mulberry32) with Gaussian and Poisson draws. */
export function rng(seed) {
  let a = seed >>> 0;
  const uni = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const gauss = () => Math.sqrt(-2 * Math.log(1 - uni())) * Math.cos(2 * Math.PI * uni());
  const poisson = (mean) => {
    if (mean <= 0) return 0;
    if (mean > 50) return Math.max(0, Math.round(mean + Math.sqrt(mean) * gauss()));
    const l = Math.exp(-mean);
    let k = 0; let p = 1;
    do { k++; p *= uni(); } while (p > l);
    return k - 1;
  };
  return { uni, gauss, poisson };
}

/**
 * The three panels: frame (detector pixels, fraction of saturation, with noise), hdr and false
 * colour (sub-pixel grid), plus what the picture measured. expo: the runtime's exposure.
 */
export function renderView(scene, illum, expo, cam, seed = 1, model = null) {
  const { L, m, meta } = radianceImage(scene, illum, cam, model);
  const ePerL = electronsPerRadiance(cam, expo.exposure_s, meta.subpixSr);
  const sigmaPx = psfSigmaPx(cam.psf_peak_fraction);
  let n; let signal;
  if (meta.resolved) {
    const k = meta.os;
    const total = new Float64Array(m * m);
    for (const s of Object.keys(L)) for (let i = 0; i < m * m; i++) total[i] += L[s][i] * ePerL;
    const blurred = sigmaPx > 0 ? gaussBlur(total, m, sigmaPx * k) : total;
    ({ img: signal, n } = bin(blurred, m, k));
  } else {
    n = meta.cropPx | 1;
    const edges = Array.from({ length: n + 1 }, (_, i) => i - n / 2);
    const cdf = edges.map((x) => (sigmaPx > 0 ? 0.5 * (1 + erf(x / (Math.SQRT2 * sigmaPx))) : (x >= 0 ? 1 : 0)));
    const w = cdf.slice(1).map((c, i) => c - cdf[i]);
    let sum = 0;
    for (const s of Object.keys(L)) for (let i = 0; i < m * m; i++) sum += L[s][i];
    signal = new Float64Array(n * n);
    for (let y = 0; y < n; y++) for (let x = 0; x < n; x++) signal[y * n + x] = w[y] * w[x] * sum * ePerL;
  }
  const g = rng(seed);
  const rn = cam.read_noise_e[expo.gain_index] ?? 0;
  const sat = cam.full_well_e / expo.gain;
  const frame = new Float64Array(n * n);
  let saturated = 0; let peak = 0; let signalTotal = 0;
  for (let i = 0; i < n * n; i++) {
    const mean = signal[i] + expo.background_e;
    peak = Math.max(peak, mean);
    signalTotal += signal[i];
    const e = g.poisson(mean) + rn * g.gauss();
    if (e >= sat) saturated++;
    frame[i] = Math.min(1, Math.max(0, e / sat));
  }
  const lum = new Float64Array(m * m);
  let mx = 0;
  for (const s of Object.keys(L)) for (let i = 0; i < m * m; i++) lum[i] += L[s][i];
  for (let i = 0; i < m * m; i++) mx = Math.max(mx, lum[i]);
  const hdr = new Float64Array(m * m);
  if (mx > 0) for (let i = 0; i < m * m; i++) hdr[i] = Math.min(1, Math.max(0, 1 + Math.log10(Math.max(lum[i], mx * 1e-30) / mx) / HDR_DECADES));
  const fc = new Float64Array(m * m * 3);
  for (const s of Object.keys(L)) {
    let smax = 0;
    for (let i = 0; i < m * m; i++) smax = Math.max(smax, L[s][i]);
    if (!(smax > 0)) continue;
    for (let i = 0; i < m * m; i++) {
      const v = Math.sqrt(L[s][i] / smax);
      for (let c = 0; c < 3; c++) fc[3 * i + c] += v * TINT[s][c];
    }
  }
  let fluxRender = 0;
  for (let i = 0; i < m * m; i++) fluxRender += lum[i];
  fluxRender *= meta.subpixSr;
  return {
    frame, n, hdr, fc, m,
    meta: { ...meta, peakE: peak, saturationE: sat, saturatedPx: saturated, signalTotalE: signalTotal, fluxRender },
  };
}

/** Draw a grey (values 0..1) or RGB image into a canvas at its own size. */
export function drawImage(canvas, data, size, rgb = false) {
  canvas.width = size; canvas.height = size;
  const ctx = canvas.getContext('2d');
  const im = ctx.createImageData(size, size);
  for (let i = 0; i < size * size; i++) {
    for (let c = 0; c < 3; c++) im.data[4 * i + c] = Math.round(255 * Math.min(1, Math.max(0, rgb ? data[3 * i + c] : data[i])));
    im.data[4 * i + 3] = 255;
  }
  ctx.putImageData(im, 0, 0);
}
