// SPDX-License-Identifier: MIT
// orbillum.js: the flight runtime compiled to WebAssembly, called from JavaScript (browser or node).
//
// Structs are laid out in the module's scratch memory at the offsets the compiler reports
// (web/wasm/oi_wasm.c exports them): no offset is typed here. planCsv() runs the planner's own
// CSV reader and row rules, compiled into the module (planner/csv_read.c, planner/rows.c,
// planner/output_text.c through web/wasm/plan_wasm.c), on a planner input CSV: its rows are the
// ones `oi-plan --csv` prints. This file only moves the text in and the numbers out.

/** Load the module: `source` is a URL (browser), or the bytes (ArrayBuffer / Uint8Array). */
export async function loadOrbillum(source) {
  let instance;
  if (source instanceof ArrayBuffer || ArrayBuffer.isView(source)) {
    ({ instance } = await WebAssembly.instantiate(source, {}));
  } else {
    const response = await fetch(source);
    const bytes = await response.arrayBuffer();
    ({ instance } = await WebAssembly.instantiate(bytes, {}));
  }
  return new Orbillum(instance);
}

/** The planner's output columns, in its order (checked against the module's at load). */
export const PLAN_COLUMNS = ['id', 'status', 'sun_fraction', 'sun_fraction_atm', 'e_sun',
  'e_earth', 'e_moon', 'earth_theta_deg', 'earth_h_km', 'flux_obs', 'mag_v', 'exposure_s',
  'gain', 'snr', 'flags', 'detect_margin_mag', 'e_sky'];

const UTF8 = new TextDecoder();

/* %.17g's texts that are no JavaScript number literals. */
const NUMBER_TEXT = { inf: Infinity, '-inf': -Infinity, nan: NaN, '-nan': NaN };

export class Orbillum {
  constructor(instance) {
    this.x = instance.exports;
    this.memory = this.x.memory;
    this.layout = {};
    const count = this.x.oi_wasm_layout_count();
    for (let k = 0; k < count; k++) {
      this.layout[this.cString(this.x.oi_wasm_layout_name(k))] = this.x.oi_wasm_layout_value(k);
    }
    const L = this.layout;
    if (L['sizeof.oi_real'] !== 8) throw new Error('the viewer needs the double-precision build');
    if (L['sizeof.void *'] !== 4) throw new Error('unexpected pointer size');
    this.c = {};
    for (const [k, v] of Object.entries(L)) if (k.startsWith('const.')) this.c[k.slice(6)] = v;
    // scratch slots, each 8-byte aligned
    const base = this.x.oi_wasm_scratch();
    let at = base;
    const slot = (bytes) => { const p = at; at += Math.ceil(bytes / 8) * 8; return p; };
    this.p = {
      scene: slot(L['sizeof.oi_scene']), model: slot(L['sizeof.oi_model']),
      illum: slot(L['sizeof.oi_illum']), expo: slot(L['sizeof.oi_exposure']),
      camera: slot(L['sizeof.oi_camera']), goal: slot(L['sizeof.oi_expose_goal']),
      expoIn: slot(L['sizeof.oi_expose_in']),
      name: slot(256), vecs: slot(24 * 4),
    };
    if (at - base > this.x.oi_wasm_scratch_bytes()) throw new Error('scratch area too small');
    // the rest: the batch calls' arrays (batchRows)
    this.p.batch = at;
    this.batchBytes = base + this.x.oi_wasm_scratch_bytes() - at;
    // the planner's output columns, as planner/output_text.c prints them
    this.planColumns = this.cString(this.x.oi_plan_wasm_csv_header()).split(',');
    if (this.planColumns.join() !== PLAN_COLUMNS.join()) throw new Error('PLAN_COLUMNS is not the planner\'s header');
    this.cameraList = [];
    for (let i = 0; ; i++) {
      const ptr = this.x.oi_camera_builtin(i);
      if (ptr === 0) break;
      this.cameraList.push(this.readCamera(ptr, i));
    }
  }

  // one view of the memory, renewed only if the memory grew (the runtime allocates nothing)
  get dv() {
    if (!this.view || this.view.buffer !== this.memory.buffer) this.view = new DataView(this.memory.buffer);
    return this.view;
  }

  cString(ptr) {
    if (!ptr) return null;
    const b = new Uint8Array(this.memory.buffer);
    let e = ptr;
    while (b[e] !== 0) e++;
    return UTF8.decode(b.subarray(ptr, e));
  }

  off(struct, field) {
    const v = this.layout[`${struct}.${field}`];
    if (v === undefined) throw new Error(`no layout for ${struct}.${field}`);
    return v;
  }

  getR(ptr, s, f, k = 0) { return this.dv.getFloat64(ptr + this.off(s, f) + 8 * k, true); }
  setR(ptr, s, f, v, k = 0) { this.dv.setFloat64(ptr + this.off(s, f) + 8 * k, v, true); }
  getI(ptr, s, f) { return this.dv.getInt32(ptr + this.off(s, f), true); }
  setI(ptr, s, f, v) { this.dv.setInt32(ptr + this.off(s, f), v, true); }
  getU(ptr, s, f) { return this.dv.getUint32(ptr + this.off(s, f), true); }
  setU(ptr, s, f, v) { this.dv.setUint32(ptr + this.off(s, f), v >>> 0, true); }
  get3(ptr, s, f) { return [0, 1, 2].map((k) => this.getR(ptr, s, f, k)); }
  set3(ptr, s, f, v) { for (let k = 0; k < 3; k++) this.setR(ptr, s, f, v[k], k); }

  readCamera(ptr, index) {
    const S = 'oi_camera';
    const cam = { index, ptr, name: this.cString(this.dv.getUint32(ptr + this.off(S, 'name'), true)) };
    for (const f of ['aperture_m', 'focal_length_m', 'pixel_pitch_m', 'transmission',
      'quantum_efficiency', 'band_fraction', 'photon_energy_j', 'full_well_e',
      'dark_current_e_s', 'psf_peak_fraction', 'fov_rad', 'sun_exclusion_rad']) {
      cam[f] = this.getR(ptr, S, f);
    }
    const nt = this.getI(ptr, S, 'n_times');
    const ng = this.getI(ptr, S, 'n_gains');
    cam.times_s = Array.from({ length: nt }, (_, k) => this.getR(ptr, S, 'times_s', k));
    cam.gains = Array.from({ length: ng }, (_, k) => this.getR(ptr, S, 'gains', k));
    cam.read_noise_e = Array.from({ length: ng }, (_, k) => this.getR(ptr, S, 'read_noise_e', k));
    return cam;
  }

  /** The built-in cameras, as the runtime defines them. */
  cameras() { return this.cameraList; }

  /** Camera by exact name (oi_camera_find); null if none. */
  findCamera(name) {
    const bytes = new TextEncoder().encode(name);
    if (bytes.length > 255) return null;
    const b = new Uint8Array(this.memory.buffer);
    b.set(bytes, this.p.name);
    b[this.p.name + bytes.length] = 0;
    const ptr = this.x.oi_camera_find(this.p.name);
    return ptr === 0 ? null : this.cameraList.find((c) => c.ptr === ptr);
  }

  statusName(st) { return this.cString(this.x.oi_status_name(st)); }

  /** Flag names of a mask, lowest bit first, joined by '+' (as the planner prints them). */
  flagNames(flags) {
    const names = [];
    for (let bit = 1; bit !== 0 && bit <= flags; bit = (bit << 1) >>> 0) {
      if (!(flags & bit)) continue;
      names.push(this.cString(this.x.oi_flag_name(bit)) ?? 'unknown');
    }
    return names.join('+');
  }

  /* Write a scene (its bytes, those of a planned row, or else the defaults; then the given
   * fields) and a model (its bytes or zeros, then the given fields) into scratch. */
  writeScene(scene, p = this.p.scene) {
    const S = 'oi_scene';
    if (scene.bytes) new Uint8Array(this.memory.buffer).set(scene.bytes, p);
    else this.x.oi_scene_defaults(p);
    for (const f of ['sun_km', 'moon_km', 'target_km', 'observer_km']) {
      if (scene[f]) this.set3(p, S, f, scene[f]);
    }
    if (scene.has_observer !== undefined) this.setI(p, S, 'has_observer', scene.has_observer ? 1 : 0);
    if (scene.terms !== undefined) this.setU(p, S, 'terms', scene.terms);
    for (const f of ['earth_albedo', 'target_albedo', 'target_radius_m']) {
      if (scene[f] !== undefined) this.setR(p, S, f, scene[f]);
    }
    // a shape: an address in the module (oi_shape_find's, or a planned row's; wasm32 pointers are
    // 32-bit); its attitude (w, x, y, z)
    if (scene.shape_ptr) this.setU(p, S, 'shape', scene.shape_ptr);
    if (scene.attitude_q) for (let k = 0; k < 4; k++) this.setR(p, S, 'attitude_q', scene.attitude_q[k], k);
    return p;
  }

  writeModel(model = {}) {
    const p = this.p.model;
    if (model.bytes) new Uint8Array(this.memory.buffer).set(model.bytes, p);
    else new Uint8Array(this.memory.buffer, p, this.layout['sizeof.oi_model']).fill(0);
    const M = 'oi_model';
    for (const f of ['tsi_w_m2', 'au_km', 'sun_radius_km', 'earth_radius_km', 'moon_radius_km', 'moon_albedo']) {
      if (model[f] !== undefined) this.setR(p, M, f, model[f]);
    }
    for (const f of ['earth_model', 'moon_model', 'limb_darkening', 'no_atmosphere', 'band']) {
      if (model[f] !== undefined) this.setI(p, M, f, model[f] ? Number(model[f]) : 0);
    }
    return p;
  }

  readIllum(p) {
    const I = 'oi_illum';
    const sh = p + this.off(I, 'shadow');
    const H = 'oi_shadow';
    const out = {
      shadow: {
        fraction: this.getR(sh, H, 'fraction'), fraction_ld: this.getR(sh, H, 'fraction_ld'),
        fraction_atm: this.getR(sh, H, 'fraction_atm'), sun_radius_rad: this.getR(sh, H, 'sun_radius_rad'),
        earth_radius_rad: this.getR(sh, H, 'earth_radius_rad'),
        separation_rad: this.getR(sh, H, 'separation_rad'),
        sun_distance_km: this.getR(sh, H, 'sun_distance_km'), region: this.getI(sh, H, 'region'),
      },
    };
    for (const f of ['e_sun', 'e_earth', 'e_moon', 'earth_theta', 'earth_h_km', 'earth_phi',
      'earth_psi', 'moon_sun_fraction', 'phase_sun', 'phase_earth', 'phase_moon', 'flux_sun',
      'flux_earth', 'flux_moon', 'flux_obs', 'mag_v', 'range_km', 'flux_specular', 'e_sky',
      'flux_sky']) {
      out[f] = this.getR(p, I, f);
    }
    for (const f of ['dir_sun', 'dir_earth', 'dir_moon']) out[f] = this.get3(p, I, f);
    return out;
  }

  readExposure(p) {
    const E = 'oi_exposure';
    const out = {};
    for (const f of ['exposure_s', 'gain', 'signal_e', 'background_e', 'peak_e', 'saturation_e',
      'fill', 'snr', 'sun_angle_rad', 'detect_margin_mag', 'background_w_m2_sr', 'rate_rad_s',
      'trail_px', 'trail_factor', 'signal_min_e']) out[f] = this.getR(p, E, f);
    out.time_index = this.getI(p, E, 'time_index');
    out.gain_index = this.getI(p, E, 'gain_index');
    out.flags = this.getU(p, E, 'flags');
    return out;
  }

  /**
   * oi_illuminate and, with an observer, oi_expose_scene on one scene.
   * camera: a camera of cameras(); manual: null (the runtime's choice) or {time_s, gain_index}
   * (the runtime then exposes with that one time and gain: a copy of the camera that has only them);
   * goal: null (the defaults) or a planned row's goal ({bytes}: its sky and sensor temperature).
   * Returns {status, illum, expo (or null), expoStatus}.
   */
  compute(scene, model, camera, manual = null, goal = null) {
    const ps = this.writeScene(scene);
    const pm = this.writeModel(model);
    const st = this.x.oi_illuminate(ps, pm, this.p.illum);
    const out = { status: st, illum: null, expo: null, expoStatus: 0 };
    if (st < 0) return out;
    out.illum = this.readIllum(this.p.illum);
    if (!scene.has_observer || !camera) return out;
    let cptr = camera.ptr;
    if (manual) {
      const C = 'oi_camera';
      const size = this.layout['sizeof.oi_camera'];
      const b = new Uint8Array(this.memory.buffer);
      b.copyWithin(this.p.camera, camera.ptr, camera.ptr + size);
      cptr = this.p.camera;
      this.setI(cptr, C, 'n_times', 1);
      this.setR(cptr, C, 'times_s', manual.time_s, 0);
      this.setI(cptr, C, 'n_gains', 1);
      this.setR(cptr, C, 'gains', camera.gains[manual.gain_index], 0);
      this.setR(cptr, C, 'read_noise_e', camera.read_noise_e[manual.gain_index], 0);
    }
    let pg = 0;
    if (goal && goal.bytes) { new Uint8Array(this.memory.buffer).set(goal.bytes, this.p.goal); pg = this.p.goal; }
    const st2 = this.x.oi_expose_scene(cptr, ps, this.p.illum, pm, pg, this.p.expo);
    out.expoStatus = st2;
    if (st2 >= 0) {
      out.expo = this.readExposure(this.p.expo);
      if (manual) out.expo.gain_index = manual.gain_index;
    }
    return out;
  }

  /* Scratch pointers for small arrays: vectors after the struct slots. */
  vecs(...vs) {
    const base = this.p.vecs;
    vs.forEach((v, k) => { for (let i = 0; i < 3; i++) this.dv.setFloat64(base + 24 * k + 8 * i, v[i], true); });
    return vs.map((_, k) => base + 24 * k);
  }

  /** oi_angle(a, b). */
  angle(a, b) { const [pa, pb] = this.vecs(a, b); return this.x.oi_angle(pa, pb); }

  /** oi_sun_fraction: {status, shadow}. */
  sunFraction(sun, point, model = {}) {
    const [ps, pp] = this.vecs(sun, point);
    const pm = this.writeModel(model);
    const out = this.p.illum + this.off('oi_illum', 'shadow');
    const st = this.x.oi_sun_fraction(ps, pp, pm, out);
    return { status: st, shadow: this.readIllum(this.p.illum).shadow };
  }

  /** oi_earthshine: {status, phi, psi}. */
  earthshine(theta, hKm, model = null) {
    const pm = model ? this.writeModel(model) : 0;
    const [pphi] = this.vecs([0, 0, 0]);
    const st = this.x.oi_earthshine(theta, hKm, pm, pphi, pphi + 8);
    return { status: st, phi: this.dv.getFloat64(pphi, true), psi: this.dv.getFloat64(pphi + 8, true) };
  }

  /** A camera of the caller's (the fields of cameras()' entries) in the scratch camera slot. */
  writeCamera(spec) {
    const p = this.p.camera;
    const C = 'oi_camera';
    new Uint8Array(this.memory.buffer, p, this.layout['sizeof.oi_camera']).fill(0);
    for (const f of ['aperture_m', 'focal_length_m', 'pixel_pitch_m', 'transmission',
      'quantum_efficiency', 'band_fraction', 'photon_energy_j', 'full_well_e',
      'dark_current_e_s', 'psf_peak_fraction', 'fov_rad', 'sun_exclusion_rad']) this.setR(p, C, f, spec[f]);
    this.setI(p, C, 'n_times', spec.times_s.length);
    spec.times_s.forEach((t, k) => this.setR(p, C, 'times_s', t, k));
    this.setI(p, C, 'n_gains', spec.gains.length);
    spec.gains.forEach((g, k) => this.setR(p, C, 'gains', g, k));
    spec.read_noise_e.forEach((r, k) => this.setR(p, C, 'read_noise_e', r, k));
    return { ...spec, ptr: p };
  }

  /** oi_expose on a photometric input (default goal): {status, expo}. */
  expose(camera, flux, background, flags = 0) {
    const E = 'oi_expose_in';
    const p = this.p.expoIn;
    this.setR(p, E, 'flux_w_m2', flux);
    this.setR(p, E, 'background_w_m2_sr', background);
    this.setU(p, E, 'flags', flags);
    const st = this.x.oi_expose(camera.ptr, p, 0, this.p.expo);
    return { status: st, expo: this.readExposure(this.p.expo) };
  }

  /*
   * Rows [0, n) of a batch call in chunks that fit the scratch's batch area: perRow lists the
   * bytes per row of each array the call takes (each array 8-byte aligned); run(start, k, ptrs)
   * writes the chunk's inputs, calls, reads its rows and returns the call's value. Returns the
   * sum of the chunks' values (rows in error), or the first batch error (negative).
   */
  batchRows(n, perRow, run) {
    const total = perRow.reduce((a, b) => a + b, 0) + 8 * perRow.length;
    const per = Math.max(1, Math.floor(this.batchBytes / total));
    let bad = 0;
    for (let start = 0; start < n || (n === 0 && start === 0); start += per) {
      const k = Math.min(per, n - start);
      let at = this.p.batch;
      const ptrs = perRow.map((b) => { const q = at; at += Math.ceil((b * k) / 8) * 8; return q; });
      const r = run(start, k, ptrs);
      if (r < 0) return r;
      bad += r;
      if (n === 0) break;
    }
    return bad;
  }

  /** oi_sun_fraction_batch: suns and points are arrays of [x, y, z]; {result, rows: [{status, shadow}]}. */
  sunFractionBatch(suns, points, model = {}, outputs = this.c.OI_BATCH_ALL) {
    const pm = this.writeModel(model);
    const SH = this.layout['sizeof.oi_shadow'];
    const rows = [];
    const result = this.batchRows(suns.length, [24, 24, SH, 4], (start, k, [ps, pp, po, pst]) => {
      for (let i = 0; i < k; i++) for (let j = 0; j < 3; j++) {
        this.dv.setFloat64(ps + 24 * i + 8 * j, suns[start + i][j], true);
        this.dv.setFloat64(pp + 24 * i + 8 * j, points[start + i][j], true);
      }
      const r = this.x.oi_sun_fraction_batch(k, ps, pp, pm, outputs, po, pst);
      for (let i = 0; i < k; i++) {
        rows.push({ status: this.dv.getInt32(pst + 4 * i, true), shadow: this.readShadow(po + SH * i) });
      }
      return r;
    });
    return { result, rows };
  }

  readShadow(p) {
    const H = 'oi_shadow';
    const out = { region: this.getI(p, H, 'region') };
    for (const f of ['fraction', 'fraction_ld', 'fraction_atm', 'sun_radius_rad', 'earth_radius_rad',
      'separation_rad', 'sun_distance_km']) out[f] = this.getR(p, H, f);
    return out;
  }

  /** oi_earthshine_batch: {result, rows: [{status, phi, psi}]}. */
  earthshineBatch(thetas, hKms, model = null) {
    const pm = model ? this.writeModel(model) : 0;
    const rows = [];
    const result = this.batchRows(thetas.length, [8, 8, 8, 8, 4], (start, k, [pt, ph, pphi, ppsi, pst]) => {
      for (let i = 0; i < k; i++) {
        this.dv.setFloat64(pt + 8 * i, thetas[start + i], true);
        this.dv.setFloat64(ph + 8 * i, hKms[start + i], true);
      }
      const r = this.x.oi_earthshine_batch(k, pt, ph, pm, pphi, ppsi, pst);
      for (let i = 0; i < k; i++) {
        rows.push({ status: this.dv.getInt32(pst + 4 * i, true), phi: this.dv.getFloat64(pphi + 8 * i, true),
          psi: this.dv.getFloat64(ppsi + 8 * i, true) });
      }
      return r;
    });
    return { result, rows };
  }

  /**
   * oi_illuminate_batch (outputs null) or oi_illuminate_batch_outputs (an OI_BATCH_* mask) over
   * scenes (writeScene's fields): {result, rows: [{status, illum}]}.
   */
  illuminateBatch(scenes, model = {}, outputs = null) {
    const pm = this.writeModel(model);
    const SC = this.layout['sizeof.oi_scene'];
    const IL = this.layout['sizeof.oi_illum'];
    const rows = [];
    const result = this.batchRows(scenes.length, [SC, IL, 4], (start, k, [ps, po, pst]) => {
      for (let i = 0; i < k; i++) this.writeScene(scenes[start + i], ps + SC * i);
      const r = outputs === null ? this.x.oi_illuminate_batch(k, ps, pm, po, pst)
        : this.x.oi_illuminate_batch_outputs(k, ps, pm, outputs, po, pst);
      for (let i = 0; i < k; i++) rows.push({ status: this.dv.getInt32(pst + 4 * i, true), illum: this.readIllum(po + IL * i) });
      return r;
    });
    return { result, rows };
  }

  /**
   * oi_expose_batch (outputs null) or oi_expose_batch_outputs (an OI_EXPOSE_* mask) with the
   * default goal: ins are {flux_w_m2, background_w_m2_sr, flags, rate_rad_s}; {result, rows: [{status, expo}]}.
   */
  exposeBatch(camera, ins, outputs = null) {
    const E = 'oi_expose_in';
    const IN = this.layout['sizeof.oi_expose_in'];
    const EX = this.layout['sizeof.oi_exposure'];
    const rows = [];
    const result = this.batchRows(ins.length, [IN, EX, 4], (start, k, [pi, po, pst]) => {
      new Uint8Array(this.memory.buffer, pi, IN * k).fill(0);
      for (let i = 0; i < k; i++) {
        const x = ins[start + i];
        this.setR(pi + IN * i, E, 'flux_w_m2', x.flux_w_m2);
        this.setR(pi + IN * i, E, 'background_w_m2_sr', x.background_w_m2_sr ?? 0);
        this.setU(pi + IN * i, E, 'flags', x.flags ?? 0);
        this.setR(pi + IN * i, E, 'rate_rad_s', x.rate_rad_s ?? 0);
      }
      const r = outputs === null ? this.x.oi_expose_batch(k, camera.ptr, pi, 0, po, pst)
        : this.x.oi_expose_batch_outputs(k, camera.ptr, pi, 0, outputs, po, pst);
      for (let i = 0; i < k; i++) rows.push({ status: this.dv.getInt32(pst + 4 * i, true), expo: this.readExposure(po + EX * i) });
      return r;
    });
    return { result, rows };
  }

  /**
   * oi_illuminate_batch, then oi_expose_scene_batch (outputs null) or
   * oi_expose_scene_batch_outputs (an OI_EXPOSE_* mask) with the default goal, over scenes:
   * {result, rows: [{status, illumStatus, expo}]}.
   */
  exposeSceneBatch(camera, scenes, model = {}, outputs = null) {
    const pm = this.writeModel(model);
    const SC = this.layout['sizeof.oi_scene'];
    const IL = this.layout['sizeof.oi_illum'];
    const EX = this.layout['sizeof.oi_exposure'];
    const rows = [];
    const result = this.batchRows(scenes.length, [SC, IL, EX, 4, 4], (start, k, [ps, pl, po, pist, pst]) => {
      for (let i = 0; i < k; i++) this.writeScene(scenes[start + i], ps + SC * i);
      const ri = this.x.oi_illuminate_batch(k, ps, pm, pl, pist);
      let r = ri;
      if (ri < 0) {
        // the scenes refused as a batch (the model): every row its status and a zeroed
        // exposure, the shape the other batch wrappers give
        new Uint8Array(this.memory.buffer, po, EX * k).fill(0);
        for (let i = 0; i < k; i++) this.dv.setInt32(pst + 4 * i, this.dv.getInt32(pist + 4 * i, true), true);
      } else {
        r = outputs === null ? this.x.oi_expose_scene_batch(k, camera.ptr, ps, pl, pm, 0, po, pst)
          : this.x.oi_expose_scene_batch_outputs(k, camera.ptr, ps, pl, pm, 0, outputs, po, pst);
      }
      for (let i = 0; i < k; i++) {
        rows.push({ status: this.dv.getInt32(pst + 4 * i, true), illumStatus: this.dv.getInt32(pist + 4 * i, true),
          expo: this.readExposure(po + EX * i) });
      }
      return r;
    });
    return { result, rows };
  }

  /* The text's UTF-8 bytes in the module's memory, for the planner's reader: their length. */
  writeText(text) {
    const bytes = new TextEncoder().encode(text);
    const ptr = this.x.oi_plan_wasm_text(bytes.length);
    if (ptr === 0) throw new Error(`no memory for a text of ${bytes.length} bytes`);
    new Uint8Array(this.memory.buffer).set(bytes, ptr);
    return bytes.length;
  }

  /** Records of a CSV text, as the planner's reader (planner/csv_read.c) gives them: arrays of fields. */
  readCsv(text) {
    this.x.oi_plan_wasm_records(this.writeText(text));
    const records = [];
    for (;;) {
      const st = this.x.oi_plan_wasm_record();
      if (st === 1) break; // CSV_END
      if (st !== 0) { records.push(null); continue; } // a record the reader rejects
      const n = this.x.oi_plan_wasm_nfields();
      records.push(Array.from({ length: n }, (_, i) => this.cString(this.x.oi_plan_wasm_field(i))));
    }
    return records;
  }

  /* A copy of a struct's bytes in the module's memory. */
  bytesAt(ptr, size) { return new Uint8Array(this.memory.buffer, ptr, size).slice(); }

  /* The planner's fields of the row the module holds (oi_plan_wasm_next or _finish): status,
   * the numbers as doubles (null where the planner leaves the field empty), flags. */
  readPlanned(row) {
    const X = this.x;
    row.status = this.cString(X.oi_plan_wasm_row_ptr(1));
    // the text oi-plan prints after the status: ",n1,...,n12,flags,n13,n14\n" (%.17g)
    const fields = this.cString(X.oi_plan_wasm_row_ptr(2)).slice(1, -1).split(',');
    const hasNumbers = X.oi_plan_wasm_row_int(10) !== 0;
    this.planColumns.slice(2).forEach((c, k) => {
      const t = fields[k];
      if (c === 'flags') row.flags = hasNumbers ? t : null;
      else row[c] = t === '' ? null : NUMBER_TEXT[t] ?? Number(t);
    });
    row.flagBits = X.oi_plan_wasm_row_int(4) >>> 0;
    const line = X.oi_plan_wasm_row_int(5);
    if (line !== 0) {
      const field = X.oi_plan_wasm_row_int(6);
      row.message = `line ${line}${field >= 0 ? `, column ${field + 1}` : ''}: ${this.cString(X.oi_plan_wasm_row_ptr(3))}`;
    }
    return row;
  }

  /* The scene the module holds as a JavaScript scene (writeScene's fields, and its bytes). */
  readScene(p) {
    const S = 'oi_scene';
    const scene = { bytes: this.bytesAt(p, this.layout['sizeof.oi_scene']) };
    for (const f of ['sun_km', 'target_km', 'observer_km']) scene[f] = this.get3(p, S, f);
    if (this.getI(p, S, 'has_moon')) scene.moon_km = this.get3(p, S, 'moon_km');
    scene.has_observer = this.getI(p, S, 'has_observer') !== 0;
    scene.terms = this.getU(p, S, 'terms');
    for (const f of ['earth_albedo', 'target_albedo', 'target_radius_m']) scene[f] = this.getR(p, S, f);
    scene.shape_ptr = this.getU(p, S, 'shape');
    scene.attitude_q = [0, 1, 2, 3].map((k) => this.getR(p, S, 'attitude_q', k));
    return scene;
  }

  /**
   * The planner's batch on a CSV text: {columns, rows, error}: the planner's own reader and
   * row rules in the module (web/wasm/plan_wasm.c). Each row has the planner's output fields
   * (numbers as doubles, null where the planner leaves the field empty), `message` where
   * oi-plan prints one for it, and, when it was computed, `scene`, `model`, `goal`, `camera`
   * and `result` (compute()'s answer) for drawing it.
   */
  planCsv(text, defaultCamera = null) {
    const X = this.x;
    const cam0 = defaultCamera ?? this.cameraList[0];
    const st = X.oi_plan_wasm_open(this.writeText(text), cam0.ptr);
    const notes = this.cString(X.oi_plan_wasm_notes());
    if (st === 1) return { error: 'empty input: no header row', rows: [] };
    if (st > 1) {
      return { error: `line ${X.oi_plan_wasm_row_int(8)}, character ${X.oi_plan_wasm_row_int(9)}: cannot read the header`, rows: [] };
    }
    if (st < 0) return { error: notes.trim().split('\n').pop(), notes, rows: [] };
    const columns = this.planColumns;
    const rows = [];
    while (X.oi_plan_wasm_next()) {
      const row = this.readPlanned({ id: this.cString(X.oi_plan_wasm_row_ptr(0)) });
      if (X.oi_plan_wasm_row_int(0)) {
        const L = this.layout;
        row.scene = this.readScene(X.oi_plan_wasm_row_ptr(4));
        row.model = { bytes: this.bytesAt(X.oi_plan_wasm_row_ptr(5), L['sizeof.oi_model']) };
        row.goal = { bytes: this.bytesAt(X.oi_plan_wasm_row_ptr(6), L['sizeof.oi_expose_goal']) };
        const cptr = X.oi_plan_wasm_row_ptr(7);
        row.camera = this.cameraList.find((c) => c.ptr === cptr) ?? cam0;
        const status = X.oi_plan_wasm_row_int(1);
        const expoStatus = X.oi_plan_wasm_row_int(2);
        row.result = { status, illum: null, expo: null, expoStatus };
        if (status >= 0) {
          row.result.illum = this.readIllum(X.oi_plan_wasm_row_ptr(8));
          if (row.scene.has_observer && expoStatus >= 0) row.result.expo = this.readExposure(X.oi_plan_wasm_row_ptr(9));
        }
      }
      rows.push(row);
    }
    return { columns, rows, notes };
  }

  /**
   * The planner's fields of a row from the last compute()'s answer r (its structs are still in
   * the scratch slots): the planner's own rules (planner/rows.c, planner/output_text.c).
   */
  fillRow(row, r) {
    row.result = r;
    this.x.oi_plan_wasm_finish(this.p.scene, this.p.illum, r.status, this.p.expo, r.expoStatus);
    return this.readPlanned(row);
  }
}
