// SPDX-License-Identifier: MIT
// test_wasm.mjs: the runtime compiled to wasm32 gives the native double build's results bit for
// bit: the shipped cases through the JavaScript module (build/wasm/orbillum.js) against
// build/oi-plan --csv, and every double-precision stability vector (web/wasm/stab_dump.c built
// natively and for WASI). Run by `make test-wasm` (node --test).
//
// Two native runs each: with glibc's generic libm code (GLIBC_TUNABLES hides FMA and AVX2 from
// its function selection) every number must be the same double; with glibc's default choice
// within 1 ulp: on a CPU with fused multiply-add glibc runs its FMA variant of exp (and log,
// pow), which rounds differently from the same algorithm without FMA in rare cases, and wasm
// has no FMA, so wasi-libc's exp is that algorithm without it (docs/viewer.md).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { WASI } from 'node:wasi';

const ROOT = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const BUILD = process.env.BUILDDIR ? path.resolve(ROOT, process.env.BUILDDIR) : path.join(ROOT, 'build');
const { loadOrbillum, PLAN_COLUMNS } = await import(path.join(BUILD, 'wasm/orbillum.js'));
const oi = await loadOrbillum(fs.readFileSync(path.join(BUILD, 'wasm/orbillum.wasm')));
const parseCsv = (text) => oi.readCsv(text); // the planner's own reader, in the module

const f64 = new Float64Array(1);
const u64 = new BigUint64Array(f64.buffer);
function bits(x) { f64[0] = x; return u64[0]; }
/** Distance in units in the last place between two finite doubles of one sign. */
function ulps(a, b) { const d = bits(a) - bits(b); return d < 0n ? -d : d; }

const CASES = fs.readdirSync(path.join(ROOT, 'tests/golden')).filter((f) => f.endsWith('.in.csv')).sort();

test('the shipped cases exist', () => assert.ok(CASES.length >= 3, CASES.join(' ')));

const GENERIC_LIBM = { ...process.env, GLIBC_TUNABLES: 'glibc.cpu.hwcaps=-AVX2,-FMA' };
const RUNS = [
  { what: "glibc's generic libm: bit for bit", env: GENERIC_LIBM, maxUlp: 0n },
  { what: "glibc's default libm: within 1 ulp", env: process.env, maxUlp: 1n },
];

/* A shipped case with facet targets: target_shape cycling through the built-in shapes and the
 * sphere, q_w..q_z a steady spin (tests/golden's rows, the shape columns added here). */
function shapedCase() {
  const rows = parseCsv(fs.readFileSync(path.join(ROOT, 'tests/golden/leo-leo-pass.in.csv'), 'utf8'));
  const shapes = ['box-wing', 'plate', 'cylinder', 'sphere', ''];
  const lines = [[...rows[0], 'target_shape', 'q_w', 'q_x', 'q_y', 'q_z'].join(',')];
  rows.slice(1).forEach((r, i) => {
    const half = 0.05 * i;
    const a = [1 / Math.sqrt(14), 2 / Math.sqrt(14), 3 / Math.sqrt(14)];
    const q = [Math.cos(half), ...a.map((x) => Math.sin(half) * x)];
    lines.push([...r, shapes[i % shapes.length], ...q.map((x) => String(x))].join(','));
  });
  // a quaternion off unit norm and an unknown shape: the planner's ERR_SHAPE rows
  const last = rows[1];
  lines.push([...last, 'box-wing', '1.00001', '0', '0', '0'].join(','));
  lines.push([...last, 'Box-Wing', '1', '0', '0', '0'].join(','));
  const file = path.join(BUILD, 'wasm/shaped-case.in.csv');
  fs.writeFileSync(file, lines.join('\n') + '\n');
  return file;
}

/* The shipped cases with the band column: total, V, empty and total again on every row in
 * turn, and an unknown word (the planner's ERR_PARSE row). */
function bandedCase(name) {
  const rows = parseCsv(fs.readFileSync(path.join(ROOT, 'tests/golden', name), 'utf8'));
  const bands = ['total', 'V', '', 'Total'];
  const lines = [[...rows[0], 'band'].join(',')];
  rows.slice(1).forEach((r, i) => lines.push([...r, bands[i % bands.length]].join(',')));
  lines.push([...rows[1], 'infrared'].join(','));
  const file = path.join(BUILD, 'wasm/banded-' + name);
  fs.writeFileSync(file, lines.join('\n') + '\n');
  return file;
}

/** build/oi-plan --csv's output; exit 1 (some rows with errors) is an answer too. */
function planner(input, env) {
  const r = spawnSync(path.join(BUILD, 'oi-plan'), ['--csv', input], { encoding: 'utf8', env });
  assert.ok(r.status === 0 || r.status === 1, `oi-plan exit ${r.status}: ${r.stderr}`);
  return r.stdout;
}

// detect_margin_mag is 2.5 log10(signal / signal_min): where a libm result (exp, log) is 1 ulp
// apart, the margin's magnitude (about 1 to 10) carries it times 2.5 plus the product's own
// rounding, up to 3 ulp; bit for bit with the generic libm all the same.
// The atmosphere's lookup (sun_fraction_atm) is steep in the penumbra: a last-bit difference of
// exp or log between glibc's default libm and wasi-libc's moves it by up to ~120 ulp (measured by
// nudging those calls by 1 ulp), and the columns that follow from it (e_sun, flux_obs, mag_v, snr,
// detect_margin_mag) by as much in relative terms. With the default libm, on a row whose
// sun_fraction_atm differs by at most ATM_LIBM_ULP, those columns may differ by ATM_LIBM_REL
// relative; with the generic libm everything stays bit for bit.
const ATM_LIBM_ULP = 128n;
const ATM_LIBM_REL = 1e-13;
const ATM_COLUMNS = new Set(['sun_fraction_atm', 'e_sun', 'flux_obs', 'mag_v', 'snr', 'detect_margin_mag']);
function atmLibmRow(row, want, run) {
  if (run.maxUlp === 0n) return false;
  const w = Number(want[PLAN_COLUMNS.indexOf('sun_fraction_atm')]);
  const g = row.sun_fraction_atm;
  return typeof g === 'number' && Number.isFinite(w) && ulps(g, w) <= ATM_LIBM_ULP;
}

function maxUlpOf(column, run) {
  return column === 'detect_margin_mag' && run.maxUlp > 0n && run.maxUlp < 3n ? 3n : run.maxUlp;
}

/* [name, file, ulp allowed beyond the run's]: the facets' earthshine calls libm's acos and asin
 * (src/target/facet_earth.c), which glibc and wasi-libc round differently for some arguments: a facet
 * target's flux_obs then differs by an ulp, its V magnitude by a few (docs/viewer.md). */
const FACET_LIBM_ULP = 8n;
const INPUTS = [...CASES.map((name) => [name, path.join(ROOT, 'tests/golden', name), 0n]),
  ['leo-leo-pass with target_shape and q_*', shapedCase(), FACET_LIBM_ULP],
  ...CASES.map((name) => [name + ' with the band column', bandedCase(name), 0n])];

for (const [name, input, extraUlp] of INPUTS) for (const run0 of RUNS) {
  const run = { ...run0, maxUlp: run0.maxUlp > extraUlp ? run0.maxUlp : extraUlp };
  test(`${name}: wasm through the JavaScript module vs build/oi-plan --csv, ${run0.what}` +
       `${extraUlp ? ` (within ${run.maxUlp} ulp: libm's acos, asin)` : ''}`, () => {
    const native = parseCsv(planner(input, run.env));
    assert.deepEqual(native[0], PLAN_COLUMNS);
    const mine = oi.planCsv(fs.readFileSync(input, 'utf8'));
    assert.equal(mine.error, undefined);
    assert.equal(mine.rows.length, native.length - 1);
    let numbers = 0;
    const differ = [];
    const near = [];
    mine.rows.forEach((row, i) => {
      const want = native[i + 1];
      const atmRow = atmLibmRow(row, want, run);
      PLAN_COLUMNS.forEach((c, k) => {
        const w = want[k];
        const got = row[c];
        if (c === 'id' || c === 'status' || c === 'flags') {
          assert.equal(got ?? '', w, `row ${i + 1} ${c}`);
          return;
        }
        if (w === '') { assert.equal(got, null, `row ${i + 1} ${c}: the planner leaves it empty`); return; }
        // the planner prints %.17g (negative zero as 0): the double round-trips exactly
        const g = got + 0.0 === 0 ? 0 : got;
        numbers++;
        if (bits(g) === bits(Number(w))) return;
        const d = ulps(g, Number(w));
        const rel = Math.abs(g - Number(w)) / Math.max(Math.abs(g), Math.abs(Number(w)));
        const ok = d <= maxUlpOf(c, run) || (atmRow && ATM_COLUMNS.has(c) && rel <= ATM_LIBM_REL);
        (ok ? near : differ).push(`row ${i + 1} ${c}: ${g} vs ${w} (${d} ulp)`);
      });
    });
    assert.deepEqual(differ, [], `${differ.length} of ${numbers} numbers differ by more than ${run.maxUlp} ulp`);
    console.log(`# ${name} (${run.what}): ${mine.rows.length} rows, ${numbers} numbers, ` +
      `${numbers - near.length} bit-identical${near.length ? `, within ${run.maxUlp} ulp: ${near.join('; ')}` : ''}`);
  });
}

function wasiDump(file) {
  const out = path.join(BUILD, 'wasm/stab_dump.wasm.txt');
  const fd = fs.openSync(out, 'w');
  const wasi = new WASI({ version: 'preview1', args: ['stab_dump'], env: {}, stdout: fd, returnOnExit: true });
  const mod = new WebAssembly.Module(fs.readFileSync(file));
  const inst = new WebAssembly.Instance(mod, wasi.getImportObject());
  const rc = wasi.start(inst);
  fs.closeSync(fd);
  assert.equal(rc, 0);
  return fs.readFileSync(out, 'utf8');
}

for (const run of RUNS) test(`every double-precision stability vector: wasm vs native, ${run.what}`, () => {
  const native = execFileSync(path.join(BUILD, 'wasm/stab_dump'), { encoding: 'utf8', env: run.env })
    .trim().split('\n');
  const wasm = wasiDump(path.join(BUILD, 'wasm/stab_dump.wasm')).trim().split('\n');
  assert.equal(wasm.length, native.length);
  assert.ok(native.length > 500, `${native.length} vectors`);
  const differ = [];
  const near = [];
  const tables = new Set();
  let outputs = 0;
  native.forEach((line, i) => {
    const a = line.split(' ');
    const b = wasm[i].split(' ');
    tables.add(a[0]);
    assert.deepEqual(b.slice(0, 4), a.slice(0, 4), `line ${i + 1}: table, index, status, region`);
    for (let k = 4; k < a.length; k++) {
      outputs++;
      if (a[k] !== b[k]) {
        let d = BigInt(`0x${a[k]}`) - BigInt(`0x${b[k]}`);
        if (d < 0n) d = -d;
        (d <= run.maxUlp ? near : differ).push(`${a[0]}[${a[1]}] output ${k - 4}: ${a[k]} vs ${b[k]} (${d} ulp)`);
      }
    }
  });
  assert.deepEqual(differ, [], `${differ.length} of ${outputs} outputs differ by more than ${run.maxUlp} ulp`);
  console.log(`# stability (${run.what}): ${native.length} vectors in ${tables.size} tables, ${outputs} ` +
    `outputs, ${outputs - near.length} bit-identical${near.length ? `, 1 ulp: ${near.join('; ')}` : ''}`);
});

test('struct layout comes from the compiler (wasm32: 4-byte pointers, 8-byte oi_real)', () => {
  assert.equal(oi.layout['sizeof.void *'], 4);
  assert.equal(oi.layout['sizeof.oi_real'], 8);
  assert.ok(oi.layout['oi_illum.mag_v'] > oi.layout['oi_illum.flux_obs']);
  assert.ok(oi.cameras().length >= 1);
  assert.equal(oi.findCamera(oi.cameras()[0].name).index, 0);
  assert.equal(oi.findCamera('no such camera'), null);
});

// The viewer's built-in scenario (web/src/scenario.js) against the planner's own table (oi-plan
// without --csv): every printed column of every printed row, to the printed digits (half a unit
// of the last digit). Its positions come from JavaScript's Math.cos/sin, so this check is at the
// table's precision, not bit for bit.
test("the viewer's built-in scenario is oi-plan's, to the digits its table prints", async () => {
  const { builtinScenario, SCENARIO_STEP_S } = await import(path.join(ROOT, 'web/src/scenario.js'));
  const rows = builtinScenario(oi);
  const text = execFileSync(path.join(BUILD, 'oi-plan'), { encoding: 'utf8' });
  const table = text.split('\n').filter((l) => /^ +\d+\.\d\d +\d\.\d{3} /.test(l));
  assert.ok(table.length >= 40, `${table.length} table rows`);
  const halfUnit = (s) => {
    const [m, e] = s.toLowerCase().split('e');
    const d = m.includes('.') ? m.split('.')[1].length : 0;
    return 0.5 * 10 ** ((e ? Number(e) : 0) - d) * (1 + 1e-9);
  };
  const camera = oi.cameras()[0];
  const DEG = 180 / Math.PI;
  let checked = 0;
  for (const line of table) {
    const f = line.trim().split(/ +/);
    const k = Math.round((Number(f[0]) * 60) / SCENARIO_STEP_S);
    const row = rows[k];
    assert.ok(Math.abs(row.t_s - Number(f[0]) * 60) < 1e-6);
    const r = oi.compute(row.scene, row.model, camera);
    const planned = oi.fillRow({ id: row.id }, r);
    const il = r.illum;
    const dx = row.scene.target_km.map((x, i) => x - row.scene.observer_km[i]);
    const got = [il.shadow.fraction_atm, il.e_sun, il.e_earth, il.e_moon, Math.hypot(...dx),
      r.expo.sun_angle_rad * DEG, il.mag_v, r.expo.exposure_s, r.expo.gain, r.expo.snr];
    got.forEach((g, j) => {
      const want = f[1 + j];
      assert.ok(Math.abs(g - Number(want)) <= halfUnit(want), `t = ${f[0]} min, column ${j + 2}: ${g} vs ${want}`);
    });
    assert.equal(planned.flags, f[11] ?? '', `t = ${f[0]} min flags`);
    checked++;
  }
  console.log(`# built-in scenario: ${checked} rows of oi-plan's table, every column to its printed digits`);
});

// The stability vectors again, now through the JavaScript module's entry points (the wrappers
// a page calls, and their struct copies), against the native dump: the same evaluations as
// tests/stability/evaluators.h, input by input.
function vectorInputs(name) {
  const text = fs.readFileSync(path.join(ROOT, 'tests/stability/vectors.h'), 'utf8');
  const start = text.indexOf(`static const stab_vec stab_${name}_d[] = {`);
  assert.ok(start >= 0, `no table ${name}`);
  const block = text.slice(start, text.indexOf('\n};', start));
  return block.split('\n').filter((l) => /^\s*\{\{/.test(l)).map((l) => l.match(/^\s*\{\{([^}]*)\}/)[1].split(',').map(Number));
}

const STAB_CAMERA = { aperture_m: 0.15, focal_length_m: 1.2, pixel_pitch_m: 5.5e-6, transmission: 0.8,
  quantum_efficiency: 0.6, band_fraction: 0.4, photon_energy_j: 3.6e-19, full_well_e: 30000, dark_current_e_s: 10,
  psf_peak_fraction: 0.3, fov_rad: 0.02, sun_exclusion_rad: 0.5, times_s: [1e-4, 1e-3, 1e-2, 0.1, 1, 10],
  gains: [1, 4, 16], read_noise_e: [10, 4, 2] }; // gen_vectors.py CAM, as evaluators.h test_camera

// the exposure's two bits of the stability vectors' region (tests/stability/evaluators.h):
// TOO_FAINT, and a full well (SATURATED or, the background's, BACKGROUND_SATURATED)
const wellBits = (flags) => ((flags & oi.c.OI_FLAG_TOO_FAINT) ? 1 : 0) +
  ((flags & (oi.c.OI_FLAG_SATURATED | oi.c.OI_FLAG_BACKGROUND_SATURATED)) ? 2 : 0);

const JS_EVAL = {
  phase: (v) => [0, -1, [oi.x.oi_lambert_phase(v[0])]],
  moon: (v) => [0, -1, [oi.x.oi_moon_phase_law(v[0])]],
  angle: (v) => [0, -1, [oi.angle(v.slice(0, 3), v.slice(3, 6))]],
  overlap: (v) => [0, -1, [oi.x.oi_cap_overlap(v[0], v[1], v[2])]],
  shadow: (v) => {
    const { status, shadow: s } = oi.sunFraction(v.slice(0, 3), v.slice(3, 6), { no_atmosphere: 1 });
    return [status, s.region, [s.fraction, s.sun_radius_rad, s.earth_radius_rad, s.separation_rad, s.sun_distance_km, s.fraction_ld]];
  },
  magnitude: (v) => [0, -1, [oi.x.oi_magnitude_v(v[0], 0)]],
  earth_lambert: (v) => {
    const r = oi.earthshine(v[0], v[1], { earth_model: oi.c.OI_EARTH_LAMBERT });
    return [r.psi !== 0 ? -100 : (r.status > 0 ? 0 : r.status), -1, [r.phi]];
  },
  illum: (v) => {
    const r = oi.compute({ sun_km: v.slice(0, 3), target_km: v.slice(3, 6), observer_km: v.slice(6, 9), has_observer: true,
      terms: oi.c.OI_TERM_SUN | oi.c.OI_TERM_EARTH, earth_albedo: 0.3, target_albedo: 0.2, target_radius_m: 1 },
    { no_atmosphere: 1, earth_model: oi.c.OI_EARTH_LAMBERT }, null);
    const o = r.illum ?? {};
    return [r.status > 0 ? 0 : r.status, -1, [o.e_sun, o.e_earth, o.earth_theta, o.earth_h_km, o.flux_sun, o.mag_v, o.flux_obs]];
  },
  earth_table: (v) => { const r = oi.earthshine(v[0], v[1]); return [r.status, -1, [r.phi, r.psi]]; },
  camera: (v) => {
    const cam = oi.writeCamera(STAB_CAMERA);
    const { status, expo: e } = oi.expose(cam, v[0], v[1]);
    return [status, e.time_index * 100 + e.gain_index * 10 + wellBits(e.flags), [e.signal_e, e.background_e, e.peak_e, e.fill, e.snr]];
  },
};

// The batch calls (stab_dump's <table>_batch and <table>_mask lines): each table's vectors in
// one call of the JavaScript module's batch wrapper, row by row against the native batch's dump.
const BATCH_ROWS = {};
function batchRow(name, all, idx, compute) {
  BATCH_ROWS[name] = BATCH_ROWS[name] ?? compute(all);
  return BATCH_ROWS[name][idx];
}
const illumScene = (v) => ({ sun_km: v.slice(0, 3), target_km: v.slice(3, 6), observer_km: v.slice(6, 9),
  has_observer: true, terms: oi.c.OI_TERM_SUN | oi.c.OI_TERM_EARTH, earth_albedo: 0.3, target_albedo: 0.2,
  target_radius_m: 1 });
const ILLUM_MODEL = { no_atmosphere: 1, earth_model: oi.c.OI_EARTH_LAMBERT };
const shadowRow = ({ status, shadow: s }) => [status, s.region,
  [s.fraction, s.sun_radius_rad, s.earth_radius_rad, s.separation_rad, s.sun_distance_km, s.fraction_ld]];
const illumRow = ({ status, illum: o }) => [status > 0 ? 0 : status, -1,
  [o.e_sun, o.e_earth, o.earth_theta, o.earth_h_km, o.flux_sun, o.mag_v, o.flux_obs]];
const expoRow = ({ status, expo: e }) => [status, e.time_index * 100 + e.gain_index * 10 + wellBits(e.flags),
  [e.signal_e, e.background_e, e.peak_e, e.fill, e.snr, e.exposure_s, e.sun_angle_rad, e.background_w_m2_sr,
    e.detect_margin_mag]];
const sunBatch = (outputs) => (v, i, all) => batchRow(`shadow ${outputs}`, all, i, (a) =>
  oi.sunFractionBatch(a.map((x) => x.slice(0, 3)), a.map((x) => x.slice(3, 6)), { no_atmosphere: 1 }, outputs)
    .rows.map(shadowRow));
const illumBatch = (outputs) => (v, i, all) => batchRow(`illum ${outputs}`, all, i, (a) =>
  oi.illuminateBatch(a.map(illumScene), ILLUM_MODEL, outputs).rows.map(illumRow));
const exposeBatch = (outputs) => (v, i, all) => batchRow(`camera ${outputs}`, all, i, (a) =>
  oi.exposeBatch(oi.writeCamera(STAB_CAMERA), a.map((x) => ({ flux_w_m2: x[0], background_w_m2_sr: x[1] })), outputs)
    .rows.map(expoRow));
const exposeSceneBatch = (outputs) => (v, i, all) => batchRow(`expose_scene ${outputs}`, all, i, (a) =>
  oi.exposeSceneBatch(oi.writeCamera(STAB_CAMERA), a.map(illumScene), ILLUM_MODEL, outputs).rows.map(expoRow));
Object.assign(JS_EVAL, {
  shadow_batch: sunBatch(oi.c.OI_BATCH_ALL),
  shadow_mask: sunBatch(0),
  earth_table_batch: (v, i, all) => batchRow('earth_table', all, i, (a) =>
    oi.earthshineBatch(a.map((x) => x[0]), a.map((x) => x[1])).rows.map((r) => [r.status, -1, [r.phi, r.psi]])),
  illum_batch: illumBatch(null),
  illum_mask: illumBatch(oi.c.OI_BATCH_OBSERVER),
  camera_batch: exposeBatch(null),
  camera_mask: exposeBatch(oi.c.OI_EXPOSE_SETTING | oi.c.OI_EXPOSE_FAINT),
  expose_scene_batch: exposeSceneBatch(null),
  expose_scene_mask: exposeSceneBatch(oi.c.OI_EXPOSE_SETTING | oi.c.OI_EXPOSE_BACKGROUND),
});
test('a batch refused for its model: every wrapper the error and a zeroed row per scene', () => {
  const scenes = [[1.496e8, 0, 0, 7000, 0, 0, 7000, 10, 0], [1.496e8, 0, 0, 0, 7000, 0, 0, 7010, 0]].map(illumScene);
  const bad = { ...ILLUM_MODEL, earth_model: 99 };
  const cam = oi.writeCamera(STAB_CAMERA);
  const calls = {
    illuminateBatch: oi.illuminateBatch(scenes, bad),
    exposeSceneBatch: oi.exposeSceneBatch(cam, scenes, bad),
    exposeSceneBatchMask: oi.exposeSceneBatch(cam, scenes, bad, oi.c.OI_EXPOSE_SETTING),
  };
  for (const [name, { result, rows }] of Object.entries(calls)) {
    assert.equal(result, oi.c.OI_ERR_MODEL, `${name} result`);
    assert.equal(rows.length, scenes.length, `${name} rows`);
    for (const row of rows) assert.equal(row.status, oi.c.OI_ERR_MODEL, `${name} row status`);
  }
  for (const row of calls.exposeSceneBatch.rows) {
    assert.equal(row.illumStatus, oi.c.OI_ERR_MODEL);
    assert.equal(row.expo.exposure_s, 0);
    assert.equal(row.expo.snr, 0);
  }
});

const baseTable = (name) => name.replace(/_(batch|mask)$/, '');
const INPUT_TABLE = { expose_scene: 'illum' }; // the scene exposure batch runs on the illum vectors' scenes

test('the batch calls are in the stability dump, each over its whole table', () => {
  const native = execFileSync(path.join(BUILD, 'wasm/stab_dump'), { encoding: 'utf8' }).trim().split('\n');
  const names = new Set(native.map((l) => l.split(' ')[0]));
  for (const n of Object.keys(JS_EVAL)) assert.ok(names.has(n), `no ${n} lines in the dump`);
  assert.ok(native.filter((l) => l.startsWith('expose_scene_mask ') && l.split(' ')[2] === '0').length > 20);
});

for (const run of RUNS) test(`every double-precision stability vector through the JavaScript module vs native, ${run.what}`, () => {
  const native = execFileSync(path.join(BUILD, 'wasm/stab_dump'), { encoding: 'utf8', env: run.env }).trim().split('\n')
    .map((l) => l.split(' '));
  const inputs = {};
  const differ = [];
  const near = [];
  let outputs = 0;
  for (const [name, idx, st, region, ...want] of native) {
    const base = baseTable(name);
    const table = INPUT_TABLE[base] ?? base;
    inputs[table] = inputs[table] ?? vectorInputs(table);
    const v = inputs[table][Number(idx)];
    const [gst, gregion, got] = JS_EVAL[name](v, Number(idx), inputs[table]);
    assert.equal(gst, Number(st), `${name}[${idx}] status`);
    if (['shadow', 'camera', 'expose_scene'].includes(base)) assert.equal(gregion, Number(region), `${name}[${idx}] region`);
    want.forEach((w, k) => {
      outputs++;
      const g = bits(got[k] ?? 0);
      const d = g > BigInt(`0x${w}`) ? g - BigInt(`0x${w}`) : BigInt(`0x${w}`) - g;
      if (d === 0n) return;
      (d <= run.maxUlp ? near : differ).push(`${name}[${idx}] output ${k}: ${got[k]} (${d} ulp)`);
    });
  }
  assert.deepEqual(differ, [], `${differ.length} of ${outputs} outputs differ by more than ${run.maxUlp} ulp`);
  console.log(`# stability through orbillum.js (${run.what}): ${native.length} vectors, ${outputs} outputs, ` +
    `${outputs - near.length} bit-identical${near.length ? `, 1 ulp: ${near.join('; ')}` : ''}`);
});

// The planner's reader and row rules on a text that tries them: a byte-order mark, CRLF and CR
// line ends, blank lines, quoted ids (commas, quotes, a line break, blanks), every optional
// column (velocities, sky, sensor temperature, the Earth's shape, the albedo model, band,
// shape and attitude), every row error oi-plan reports, a record the reader rejects (a quote
// never closed, a NUL byte) and one longer than its limit (1 MiB). planCsv gives what
// build/oi-plan --csv prints, row by row, and the same messages it writes on stderr.
function trickyCase() {
  const head = ['id', 'sun_x', 'sun_y', 'sun_z', 'moon_x', 'moon_y', 'moon_z', 'target_x', 'target_y', 'target_z',
    'observer_x', 'observer_y', 'observer_z', 'camera', 'target_radius_m', 'target_albedo', 'earth_albedo',
    'Target_VX', 'target_vy', 'target_vz', 'observer_vx', 'observer_vy', 'observer_vz', 'terms', 'sky',
    'sensor_temp_c', 'earth_shape', 'albedo_model', 'epoch_jd', 'earth_rotation_deg', 'band', 'atmosphere',
    'target_shape', 'q_w', 'q_x', 'q_y', 'q_z', 'no_such_column'];
  const rows = oi.readCsv(fs.readFileSync(path.join(ROOT, 'tests/golden/leo-leo-pass.in.csv'), 'utf8')).slice(1);
  const base = (i) => rows[i].slice(1, 17);
  const extra = (o) => ['7.1', '-0.2', '0.3', '', '', '', '', '', '', '', '', '', '', '', '', '', '', '', '', '', 'x']
    .map((v, k) => (k in o ? o[k] : v));
  // extra()'s fields: 0-2 target velocity, 3-5 observer velocity, 6 terms, 7 sky, 8 sensor_temp_c,
  // 9 earth_shape, 10 albedo_model, 11 epoch_jd, 12 earth_rotation_deg, 13 band, 14 atmosphere,
  // 15 target_shape, 16-19 q, 20 the unknown column
  const line = (id, i, o = {}) => [id, ...base(i), ...extra(o)].join(',');
  const out = ['\ufeff' + head.join(',')];
  const cases = [
    ['plain', {}], ['"quoted, with a comma"', {}], ['"say ""hi"""', {}], ['"two\nlines"', {}], ['" blanks "', {}],
    ['vel-empty', { 0: '', 1: '', 2: '' }], ['obs-vel', { 3: '0.1', 4: '7.5', 5: '0' }],
    ['sky-all', { 7: 'all' }], ['sky-starlight', { 7: 'zodiacal+moon+starlight' }], ['cold', { 8: '-20' }],
    ['wgs84', { 9: 'WGS84' }], ['knocke', { 10: 'knocke', 11: '2453912.19' }], ['total', { 13: 'total' }],
    ['no-atm', { 14: '0' }], ['terms-all-sky', { 6: 'all+sky' }], ['terms-sun', { 6: ' sun ' }],
    ['box', { 15: 'box-wing', 16: '0.5', 17: '0.5', 18: '0.5', 19: '0.5' }],
    ['bad-number', { 0: '7.1x' }], ['half-vel', { 1: '' }], ['bad-terms', { 6: 'sun+star' }],
    ['bad-sky', { 7: 'aurora' }], ['bad-shape-earth', { 9: 'pear' }], ['bad-albedo-model', { 10: 'mars' }],
    ['knocke-no-epoch', { 10: 'knocke' }], ['map-no-file', { 10: 'map', 11: '2453912.19', 12: '10' }],
    ['bad-band', { 13: 'infrared' }], ['bad-atm', { 14: '2' }], ['bad-shape', { 15: 'blob' }],
    ['bad-q', { 15: 'plate', 16: '2', 17: '0', 18: '0', 19: '0' }], ['half-q', { 16: '1' }],
    ['bad-temp', { 8: 'warm' }], ['knocke-early', { 10: 'knocke', 11: '100' }],
  ];
  cases.forEach(([id, o], k) => out.push(line(id, k % rows.length, o)));
  out.push(line('bad-camera', 3).replace('telescope-15cm', 'pinhole'));
  out.push('');
  out.push('   ');
  out.push(line('short', 4).split(',').slice(0, 9).join(','));
  out.push(line('long', 5) + ',1,2,3');
  out.push(line('nul\0byte', 7));
  // (short fields: a plain run longer than the reader's room is rescanned byte by byte, the
  // quadratic time on long lines that planner/csv_read.c is being rid of)
  out.push(line('huge', 8, { 20: 'y,'.repeat((1 << 19) + 10) }));
  out.push(line('after-huge', 9));
  out.push(line('zero-sun', 10).replace(/^([^,]*),[^,]*,[^,]*,[^,]*/, '$1,0,0,0'));
  out.push(line('"bad" quote', 11));
  out.push(line('"never closed', 6)); // the last record: the quote runs to the end
  const file = path.join(BUILD, 'wasm/tricky-case.in.csv');
  // CRLF on most lines, a bare CR on one
  fs.writeFileSync(file, out.map((l, i) => l + (i === 5 ? '\r' : '\r\n')).join(''));
  return file;
}

test("a text that tries the planner's reader and row rules: planCsv gives oi-plan's rows and messages", () => {
  const input = trickyCase();
  const r = spawnSync(path.join(BUILD, 'oi-plan'), ['--csv', input], { encoding: 'utf8', env: GENERIC_LIBM, maxBuffer: 1 << 26 });
  assert.equal(r.status, 1, r.stderr);
  const native = oi.readCsv(r.stdout);
  const mine = oi.planCsv(fs.readFileSync(input, 'utf8'));
  assert.equal(mine.error, undefined);
  assert.deepEqual(native[0], mine.columns);
  assert.equal(mine.rows.length, native.length - 1);
  const statuses = new Set();
  mine.rows.forEach((row, i) => {
    const want = native[i + 1];
    statuses.add(want[1]);
    mine.columns.forEach((c, k) => {
      const got = row[c] ?? '';
      const w = want[k];
      if (typeof got === 'number') {
        assert.equal(bits(got + 0.0 === 0 ? 0 : got), bits(Number(w)), `row ${i + 1} (${row.id}) ${c}: ${got} vs ${w}`);
      } else {
        assert.equal(got, w, `row ${i + 1} (${row.id}) ${c}`);
      }
    });
  });
  // every row message oi-plan prints (its notes about the header and extra fields are the batch's)
  const prefix = `oi-plan: ${input}: `;
  const wantMsgs = r.stderr.split('\n').filter((l) => l.startsWith(prefix + 'line ') && !l.includes(': note: '))
    .map((l) => l.slice(prefix.length));
  const gotMsgs = mine.rows.filter((row) => row.message).map((row) => row.message);
  assert.deepEqual(gotMsgs, wantMsgs);
  assert.ok(wantMsgs.length >= 21, `${wantMsgs.length} messages`);
  assert.ok(mine.notes.includes("ignoring unknown column 38 'no_such_column'"), mine.notes);
  for (const s of ['OK', 'ERR_PARSE', 'ERR_SHAPE', 'ERR_CAMERA', 'ERR_ZERO_VECTOR']) assert.ok(statuses.has(s), `no ${s} row`);
  console.log(`# tricky case: ${mine.rows.length} rows (${[...statuses].join(' ')}), ${gotMsgs.length} messages, all as oi-plan's`);
});

test("the planner's reader in the module gives the records oi-plan's reader reads", () => {
  const text = '\ufeffa, b ,"c,d"\r\n\r\n"e""f",,"g\nh"\n  \n1,2';
  assert.deepEqual(oi.readCsv(text), [['a', 'b', 'c,d'], ['e"f', '', 'g\nh'], ['1', '2']]);
  assert.deepEqual(oi.readCsv('x,"y\n'), [null]);
  assert.deepEqual(oi.readCsv(''), []);
});
