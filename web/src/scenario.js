// SPDX-License-Identifier: MIT
// scenario.js: the planner's built-in scenario (planner/scenario.c) as viewer rows: an
// inspector 1.5 km below and 8 km behind a target in a 500 km, 51.6 deg circular orbit, Sun and
// Moon fixed, one orbit sampled every 10 s. Positions come from JavaScript's Math.cos/sin, not
// the C library's: they may differ from the planner's in the last bits.

const PI = 3.14159265358979323846;
const DEG = PI / 180.0;
const GM_KM3_S2 = 398600.4418;
const TARGET_ALT_KM = 500.0;
const INCL_DEG = 51.6;
const INSPECTOR_DROP_KM = 1.5;
const INSPECTOR_DINCL_DEG = 0.005;
const INSPECTOR_BEHIND_KM = 8.0;
const SUN_RA_DEG = 280.0;
const SUN_DEC_DEG = -23.0;
const SUN_DIST_AU = 0.98329;
const MOON_RA_DEG = 110.0;
const MOON_DEC_DEG = 18.0;
const MOON_DIST_KM = 384400.0;
export const SCENARIO_STEP_S = 10.0;

function makeOrbit(a, incl, raan, u0) {
  return { a, incl, raan, u0, n: Math.sqrt(GM_KM3_S2 / (a * a * a)) };
}

function orbitPos(o, t) {
  const u = o.u0 + o.n * t;
  const cu = Math.cos(u); const su = Math.sin(u);
  const co = Math.cos(o.raan); const so = Math.sin(o.raan);
  const ci = Math.cos(o.incl); const si = Math.sin(o.incl);
  return [o.a * (cu * co - su * ci * so), o.a * (cu * so + su * ci * co), o.a * (su * si)];
}

function radec(ra, dec, dist) {
  return [dist * Math.cos(dec * DEG) * Math.cos(ra * DEG), dist * Math.cos(dec * DEG) * Math.sin(ra * DEG),
    dist * Math.sin(dec * DEG)];
}

/** Rows {id, t_s, scene, model, camera: null (the default camera)} of the built-in scenario. */
export function builtinScenario(oi) {
  const re = oi.c.OI_EARTH_RADIUS_KM;
  const aT = re + TARGET_ALT_KM;
  const tgt = makeOrbit(aT, INCL_DEG * DEG, 0.0, 0.0);
  const insp = makeOrbit(aT - INSPECTOR_DROP_KM, (INCL_DEG + INSPECTOR_DINCL_DEG) * DEG, 0.0,
    -INSPECTOR_BEHIND_KM / aT);
  const period = (2.0 * PI) / tgt.n;
  const n = Math.floor(period / SCENARIO_STEP_S);
  const sun = radec(SUN_RA_DEG, SUN_DEC_DEG, SUN_DIST_AU * oi.c.OI_AU_KM);
  const moon = radec(MOON_RA_DEG, MOON_DEC_DEG, MOON_DIST_KM);
  const rows = [];
  for (let i = 0; i <= n; i++) {
    const t = i * SCENARIO_STEP_S;
    rows.push({
      id: `t = ${(t / 60).toFixed(2)} min`, t_s: t,
      scene: { sun_km: sun, moon_km: moon, target_km: orbitPos(tgt, t), observer_km: orbitPos(insp, t),
        has_observer: true },
      model: {}, camera: null,
    });
  }
  return rows;
}
