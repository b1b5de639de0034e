// SPDX-License-Identifier: MIT
// viewer.js: the page: loads the runtime (wasm, embedded in the bundle), a pass (the built-in
// scenario, a shipped case or a dropped planner CSV) and draws one instant: the scene view, the
// camera's view and the runtime's numbers, under the controls (docs/viewer.md).
import wasmBytes from 'viewer-data:wasm';
import { loadOrbillum } from './orbillum.js';
import { builtinScenario } from './scenario.js';
import { renderView, drawImage, parseObj, HDR_DECADES } from './render.js';
import { SceneView } from './scene3d.js';
import cases from 'viewer-data:cases';
import stars from 'viewer-data:stars';
import models from 'viewer-data:models';

const $ = (id) => document.getElementById(id);
const DEG = 180 / Math.PI;

const state = { oi: null, rows: [], index: 0, dataset: '', view: null, touched: {} };

function fmt(x, digits = 5) {
  if (x === null || x === undefined) return '';
  if (typeof x !== 'number') return String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  return a >= 1e-3 && a < 1e6 ? String(Number(x.toPrecision(digits))) : x.toExponential(digits - 1);
}

/** Rows of a planner input CSV as viewer rows (the planner's own reader and row rules, in the wasm module). */
function rowsFromCsv(text) {
  const plan = state.oi.planCsv(text);
  if (plan.error) throw new Error(plan.error);
  return plan.rows.map((r, i) => {
    const t = Date.parse(r.id);
    return { id: r.id, t_s: Number.isNaN(t) ? i : t / 1000, scene: r.scene ?? null, model: r.model ?? {},
      goal: r.goal ?? null, camera: r.camera ?? null, planned: r };
  });
}

function loadDataset(name) {
  state.dataset = name;
  if (name === 'builtin') {
    state.rows = builtinScenario(state.oi);
  } else if (cases[name]) {
    state.rows = rowsFromCsv(cases[name]);
  }
  onRowsLoaded();
}

function onRowsLoaded() {
  const slider = $('time');
  slider.max = String(Math.max(0, state.rows.length - 1));
  const first = state.rows.find((r) => r.scene) ?? {};
  // controls start at the data's values and override it only once touched
  state.touched = {};
  const sc = first.scene ?? {};
  $('earth-albedo').value = sc.earth_albedo ?? 0.3;
  $('target-albedo').value = sc.target_albedo ?? 0.2;
  $('target-radius').value = sc.target_radius_m ?? 1.0;
  $('src-moon').disabled = !sc.moon_km;
  fillCameraChoice(first.camera);
  state.view.setTracks(state.rows);
  state.index = bestRow();
  slider.value = String(state.index);
  update();
}

// the row the planner's pictures would pick: the highest SNR without sun_exclusion, occulted, saturated
function bestRow() {
  let best = -1; let bestSnr = -1;
  state.rows.forEach((r, i) => {
    const p = r.planned;
    if (!p || p.snr === null || /sun_exclusion|occulted|saturated/.test(p.flags ?? '')) return;
    if (p.snr > bestSnr) { best = i; bestSnr = p.snr; }
  });
  return best >= 0 ? best : 0;
}

function fillCameraChoice(dataCamera) {
  const sel = $('camera');
  sel.innerHTML = '';
  const opt = (v, t) => { const o = document.createElement('option'); o.value = v; o.textContent = t; sel.appendChild(o); };
  opt('', `as in the data (${(dataCamera ?? state.oi.cameras()[0]).name})`);
  for (const c of state.oi.cameras()) opt(String(c.index), c.name);
  fillExposureChoice();
}

function currentCamera(row) {
  const v = $('camera').value;
  if (v !== '') return state.oi.cameras()[Number(v)];
  return row.camera ?? state.oi.cameras()[0];
}

function fillExposureChoice() {
  const row = state.rows[state.index] ?? {};
  const cam = currentCamera(row);
  const keepT = $('exposure').value; const keepG = $('gain').value;
  $('exposure').innerHTML = '<option value="">automatic</option>' + cam.times_s.map((t, k) => `<option value="${k}">${t} s</option>`).join('');
  $('gain').innerHTML = '<option value="">automatic</option>' + cam.gains.map((g, k) => `<option value="${k}">${g} (read noise ${cam.read_noise_e[k]} e-)</option>`).join('');
  if (keepT !== '' && Number(keepT) < cam.times_s.length) $('exposure').value = keepT;
  if (keepG !== '' && Number(keepG) < cam.gains.length) $('gain').value = keepG;
}

/** The row's scene with the controls applied (only those the user touched). */
function effectiveScene(row) {
  const sc = { ...row.scene };
  const C = state.oi.c;
  if (state.touched['earth-albedo']) sc.earth_albedo = Number($('earth-albedo').value);
  if (state.touched['target-albedo']) sc.target_albedo = Number($('target-albedo').value);
  if (state.touched['target-radius']) sc.target_radius_m = Number($('target-radius').value);
  let terms = sc.terms ?? (C.OI_TERM_SUN | C.OI_TERM_EARTH | (sc.moon_km ? C.OI_TERM_MOON : 0));
  if (!$('src-sun').checked) terms &= ~C.OI_TERM_SUN;
  if (!$('src-earth').checked) terms &= ~C.OI_TERM_EARTH;
  if (!$('src-moon').checked) terms &= ~C.OI_TERM_MOON;
  sc.terms = terms >>> 0;
  return sc;
}

function compute(row) {
  const oi = state.oi;
  const scene = effectiveScene(row);
  const model = { ...row.model };
  if ($('atmosphere').value === '0') model.no_atmosphere = 1;
  const cam = currentCamera(row);
  let r = oi.compute(scene, model, cam, null, row.goal);
  const tSel = $('exposure').value; const gSel = $('gain').value;
  if ((tSel !== '' || gSel !== '') && r.expo) {
    r = oi.compute(scene, model, cam, {
      time_s: tSel !== '' ? cam.times_s[Number(tSel)] : r.expo.exposure_s,
      gain_index: gSel !== '' ? Number(gSel) : r.expo.gain_index,
    }, row.goal);
  }
  const out = oi.fillRow({ id: row.id }, r);
  return { scene, model, cam, r, out };
}

const NUMBERS = [
  ['status', 'status', ''], ['sun_fraction', 'Sun fraction (disc)', ''], ['sun_fraction_atm', 'Sun fraction (with atmosphere)', ''],
  ['e_sun', 'irradiance: Sun', 'W/m²'], ['e_earth', 'irradiance: Earth', 'W/m²'], ['e_moon', 'irradiance: Moon', 'W/m²'],
  ['earth_theta_deg', 'Sun–Earth–target angle', 'deg'], ['earth_h_km', 'target altitude', 'km'],
  ['flux_obs', 'flux at the observer', 'W/m²'], ['mag_v', 'magnitude V', ''], ['exposure_s', 'exposure', 's'],
  ['gain', 'gain', ''], ['snr', 'SNR', ''], ['flags', 'flags', ''],
];

function showNumbers(c) {
  const tb = $('numbers');
  const extra = [];
  if (c.r.illum) {
    extra.push(['range_km', 'range', 'km', c.r.illum.range_km]);
    extra.push(['phase_sun_deg', 'phase angle (Sun)', 'deg', c.r.illum.phase_sun * DEG]);
  }
  if (c.r.expo) {
    extra.push(['fill', 'brightest pixel / saturation', '', c.r.expo.fill]);
    extra.push(['signal_e', 'target electrons (brightest px)', 'e-', c.r.expo.signal_e]);
    extra.push(['background_e', 'background + dark (that px)', 'e-', c.r.expo.background_e]);
    extra.push(['sun_angle_deg', 'Sun to boresight', 'deg', c.r.expo.sun_angle_rad * DEG]);
  }
  const rows = NUMBERS.map(([k, label, unit]) => [k, label, unit, c.out[k]]).concat(extra);
  tb.innerHTML = '';
  for (const [k, label, unit, v] of rows) {
    const tr = document.createElement('tr');
    const td = document.createElement('td');
    td.dataset.key = k;
    td.dataset.value = v === null || v === undefined ? '' : String(v);
    td.textContent = fmt(v) + (unit && v !== null && v !== undefined && v !== '' ? ` ${unit}` : '');
    tr.innerHTML = `<th>${label}</th>`;
    tr.appendChild(td);
    tb.appendChild(tr);
  }
}

function update() {
  const row = state.rows[state.index];
  if (!row) return;
  $('time-label').textContent = `${row.id}   (row ${state.index + 1} of ${state.rows.length})`;
  if (!row.scene) {
    // the planner's status and, where oi-plan prints one, its message for the row
    const p = row.planned;
    $('message').textContent = `row ${state.index + 1}: ${p ? p.status + (p.message ? ` (${p.message})` : '') : 'no scene'}`;
    return;
  }
  const c = compute(row);
  state.last = c;
  showNumbers(c);
  state.view.update(c.scene, c.r.illum, c.cam, currentModel());
  const msg = [];
  if (c.r.status < 0) msg.push(`runtime: ${c.out.status}`);
  if (!row.scene.has_observer) msg.push('no observer in this row: no camera view');
  if (c.r.expo && c.r.illum) {
    const model = currentModel();
    const v = renderView(c.scene, c.r.illum, c.r.expo, c.cam, Number($('seed').value) || 1, model);
    drawImage($('frame'), v.frame, v.n);
    drawImage($('hdr'), v.hdr, v.m);
    drawImage($('fc'), v.fc, v.m, true);
    const mt = v.meta;
    $('frame-caption').textContent = `${c.r.expo.exposure_s} s, gain ${c.r.expo.gain}: linear 0..saturation, noise; peak ${(100 * mt.peakE / mt.saturationE).toFixed(1)}% of saturation`;
    $('hdr-caption').textContent = `log radiance, ${HDR_DECADES} decades, noiseless`;
    $('view-note').textContent = `target ${mt.diamPx.toPrecision(3)} px across, crop ${mt.cropPx}×${mt.cropPx} px` +
      (mt.resolved ? '' : ': UNRESOLVED, the frame is the PSF blob; the HDR and colour panels show the sphere finer than a pixel') +
      (model ? `; facet model ${$('shape').value} (${model.tris.length} triangles, nadir-Sun attitude): the runtime's numbers and exposure are still the sphere's` : '') +
      `; up = away from the Earth. Picture flux ${fmt(mt.fluxRender)} W/m² (runtime ${fmt(c.r.illum.flux_obs)}).`;
  }
  $('message').textContent = msg.join('; ');
  document.body.dataset.ready = String(Number(document.body.dataset.ready || 0) + 1);
}

const parsedModels = {};
function currentModel() {
  const name = $('shape').value;
  if (name === 'sphere' || !models[name]) return null;
  parsedModels[name] = parsedModels[name] ?? parseObj(models[name]);
  return parsedModels[name];
}

async function main() {
  state.oi = await loadOrbillum(wasmBytes);
  state.view = new SceneView($('scene'), stars);
  const sel = $('dataset');
  sel.innerHTML = '<option value="builtin">built-in scenario (oi-plan without --csv)</option>' +
    Object.keys(cases).map((k) => `<option value="${k}">${k}</option>`).join('');
  sel.addEventListener('change', () => loadDataset(sel.value));
  $('time').addEventListener('input', () => { state.index = Number($('time').value); update(); });
  for (const id of ['earth-albedo', 'target-albedo', 'target-radius']) {
    $(id).addEventListener('input', () => { state.touched[id] = true; update(); });
  }
  $('shape').innerHTML = '<option value="sphere">sphere (the runtime\'s)</option>' +
    Object.keys(models).map((k) => `<option value="${k}">${k} (facets, examples/render/models)</option>`).join('');
  for (const id of ['src-sun', 'src-earth', 'src-moon', 'atmosphere', 'exposure', 'gain', 'seed', 'shape']) {
    $(id).addEventListener('change', update);
  }
  $('camera').addEventListener('change', () => { $('exposure').value = ''; $('gain').value = ''; fillExposureChoice(); update(); });
  $('focus').addEventListener('change', () => { state.view.setFocus($('focus').value); });
  $('play').addEventListener('click', () => {
    if (state.timer) { clearInterval(state.timer); state.timer = null; $('play').textContent = 'play'; return; }
    $('play').textContent = 'stop';
    state.timer = setInterval(() => {
      state.index = (state.index + 1) % state.rows.length;
      $('time').value = String(state.index);
      update();
    }, 120);
  });
  const drop = $('drop');
  const takeFile = async (file) => {
    try {
      state.rows = rowsFromCsv(await file.text());
      state.dataset = file.name;
      const o = document.createElement('option'); o.value = ''; o.textContent = `dropped: ${file.name}`;
      sel.appendChild(o); sel.value = '';
      onRowsLoaded();
    } catch (e) { $('message').textContent = `${file.name}: ${e.message}`; }
  };
  document.addEventListener('dragover', (e) => { e.preventDefault(); drop.classList.add('over'); });
  document.addEventListener('dragleave', () => drop.classList.remove('over'));
  document.addEventListener('drop', (e) => {
    e.preventDefault(); drop.classList.remove('over');
    if (e.dataTransfer.files.length) takeFile(e.dataTransfer.files[0]);
  });
  $('file').addEventListener('change', () => { if ($('file').files.length) takeFile($('file').files[0]); });
  window.addEventListener('resize', () => state.view.resize());
  $('stars-note').textContent = `${stars.length} stars brighter than V = 6 (Hipparcos, from the d3-celestial package)`;
  // tests and links: ?dataset=NAME&row=N
  const q = new URLSearchParams(location.search);
  loadDataset(q.get('dataset') && (cases[q.get('dataset')] || q.get('dataset') === 'builtin') ? q.get('dataset') : 'builtin');
  if (q.get('dataset')) sel.value = q.get('dataset');
  if (q.get('row')) { state.index = Math.min(state.rows.length - 1, Number(q.get('row'))); $('time').value = String(state.index); update(); }
  window.orbillumViewer = state; // for the browser test
}

main().catch((e) => { console.error(e); const m = document.getElementById('message'); if (m) m.textContent = `error: ${e.message}`; });
