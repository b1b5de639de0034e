// SPDX-License-Identifier: MIT
// scene3d.js: the scene view (three.js): the Earth lit from the Sun's direction (its terminator is
// the shading's), the Sun's direction, the Moon, the target and the observer with its camera's
// frustum, the Earth's umbra and penumbra cones, the pass's tracks and a star field. Earth-centred
// inertial frame, one unit = one Earth radius; the Moon and Sun are drawn in their directions at
// shortened distances (the view says so).
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { nadirSunAttitude } from './render.js';

const MOON_DRAW_R = 9;     // Earth radii: where the Moon is drawn along its direction
const SUN_DRAW_R = 30;
const CONE_LEN_R = 12;     // how far behind the Earth the shadow cones are drawn
const STAR_R = 800;

// ECI (x, y, z; z to the north pole) to three.js (y up): x -> x, z -> y, y -> -z
const v3 = (p, s = 1) => new THREE.Vector3(p[0] * s, p[2] * s, -p[1] * s);

function starColour(bv) {
  // B-V to a rough RGB (blue-white to orange)
  const t = Math.min(1, Math.max(0, (bv + 0.4) / 2.4));
  return new THREE.Color().setRGB(0.75 + 0.25 * t, 0.8 + 0.1 * (1 - Math.abs(t - 0.4)), 1.0 - 0.5 * t);
}

export class SceneView {
  constructor(canvas, stars) {
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0x02030a);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.0001, 5000);
    this.camera.position.set(4, 2.5, 4);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = false;
    this.controls.addEventListener('change', () => this.draw());

    this.sunLight = new THREE.DirectionalLight(0xffffff, 2.2);
    this.scene.add(this.sunLight, this.sunLight.target);
    this.scene.add(new THREE.AmbientLight(0x223355, 0.25));

    const earthGeo = new THREE.SphereGeometry(1, 96, 64);
    this.earth = new THREE.Mesh(earthGeo, new THREE.MeshLambertMaterial({ color: 0x2a62b8 }));
    this.scene.add(this.earth);
    const grid = new THREE.Group();
    const lineMat = new THREE.LineBasicMaterial({ color: 0x88aadd, transparent: true, opacity: 0.35 });
    for (let lat = -60; lat <= 60; lat += 30) {
      const pts = [];
      for (let lon = 0; lon <= 360; lon += 5) {
        const a = (lon * Math.PI) / 180; const b = (lat * Math.PI) / 180;
        pts.push(v3([Math.cos(b) * Math.cos(a), Math.cos(b) * Math.sin(a), Math.sin(b)], 1.002));
      }
      grid.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), lineMat));
    }
    for (let lon = 0; lon < 180; lon += 30) {
      const pts = [];
      for (let lat = 0; lat <= 360; lat += 5) {
        const a = (lon * Math.PI) / 180; const b = (lat * Math.PI) / 180;
        pts.push(v3([Math.cos(b) * Math.cos(a), Math.cos(b) * Math.sin(a), Math.sin(b)], 1.002));
      }
      grid.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), lineMat));
    }
    this.scene.add(grid);
    const axis = new THREE.ArrowHelper(new THREE.Vector3(0, 1, 0), new THREE.Vector3(0, 1, 0), 0.4, 0x99aacc, 0.08, 0.05);
    this.scene.add(axis);

    this.sunArrow = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 0, 0), 3, 0xffd34d, 0.25, 0.12);
    this.scene.add(this.sunArrow);
    this.sunDot = new THREE.Mesh(new THREE.SphereGeometry(0.8, 24, 16), new THREE.MeshBasicMaterial({ color: 0xffe27a }));
    this.scene.add(this.sunDot);
    this.moon = new THREE.Mesh(new THREE.SphereGeometry(1737.4 / 6378.137, 48, 32), new THREE.MeshLambertMaterial({ color: 0xbdbdbd }));
    this.scene.add(this.moon);

    this.umbra = new THREE.Mesh(new THREE.CylinderGeometry(1, 1, 1, 64, 1, true),
      new THREE.MeshBasicMaterial({ color: 0x000000, transparent: true, opacity: 0.55, side: THREE.DoubleSide, depthWrite: false }));
    this.penumbra = new THREE.Mesh(new THREE.CylinderGeometry(1, 1, 1, 64, 1, true),
      new THREE.MeshBasicMaterial({ color: 0x5a3c8c, transparent: true, opacity: 0.18, side: THREE.DoubleSide, depthWrite: false }));
    this.scene.add(this.umbra, this.penumbra);

    this.target = new THREE.Mesh(new THREE.SphereGeometry(1, 24, 16), new THREE.MeshLambertMaterial({ color: 0xf0f0f0 }));
    this.observer = new THREE.Mesh(new THREE.BoxGeometry(1, 1, 1), new THREE.MeshBasicMaterial({ color: 0x44ff88 }));
    this.scene.add(this.target, this.observer);
    this.frustum = new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0x44ff88 }));
    this.scene.add(this.frustum);
    this.trackTarget = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0xffffff, transparent: true, opacity: 0.5 }));
    this.trackObserver = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0x44ff88, transparent: true, opacity: 0.4 }));
    this.scene.add(this.trackTarget, this.trackObserver);

    if (stars && stars.length) {
      const pos = new Float32Array(stars.length * 3); const col = new Float32Array(stars.length * 3);
      stars.forEach(([ra, dec, mag, bv], i) => {
        const a = (ra * Math.PI) / 180; const b = (dec * Math.PI) / 180;
        const p = v3([Math.cos(b) * Math.cos(a), Math.cos(b) * Math.sin(a), Math.sin(b)], STAR_R);
        pos.set([p.x, p.y, p.z], 3 * i);
        const c = starColour(bv);
        const k = Math.min(1, Math.max(0.15, 10 ** (-0.4 * (mag - 1.0))) ** 0.5);
        col.set([c.r * k, c.g * k, c.b * k], 3 * i);
      });
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
      g.setAttribute('color', new THREE.BufferAttribute(col, 3));
      this.stars = new THREE.Points(g, new THREE.PointsMaterial({ size: 2.2, sizeAttenuation: false, vertexColors: true }));
      this.scene.add(this.stars);
    }
    this.focus = 'earth';
    this.resize();
  }

  resize() {
    const c = this.renderer.domElement;
    const w = c.clientWidth || 640; const h = c.clientHeight || 480;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.draw();
  }

  /** Tracks of the pass (target and observer positions of every row, km). */
  setTracks(rows) {
    const r = 1 / 6378.137;
    this.trackTarget.geometry.dispose();
    this.trackTarget.geometry = new THREE.BufferGeometry().setFromPoints(rows.filter((x) => x.scene).map((x) => v3(x.scene.target_km, r)));
    const obs = rows.filter((x) => x.scene && x.scene.observer_km);
    this.trackObserver.geometry.dispose();
    this.trackObserver.geometry = new THREE.BufferGeometry().setFromPoints(obs.map((x) => v3(x.scene.observer_km, r)));
  }

  /** One instant: scene (km), the runtime's illumination and the camera (for its field). */
  /* The target as a facet model (metres) in the nadir-Sun attitude, or null for the sphere. */
  setModel(model, scene) {
    if (model !== this.modelSrc) {
      this.modelSrc = model;
      if (this.modelMesh) { this.scene.remove(this.modelMesh); this.modelMesh.geometry.dispose(); this.modelMesh = null; }
      if (model) {
        const g = new THREE.BufferGeometry();
        const pos = [];
        for (const t of model.tris) for (const k of t) pos.push(...model.verts[k]);
        g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
        g.computeVertexNormals();
        this.modelMesh = new THREE.Mesh(g, new THREE.MeshLambertMaterial({ color: 0xe8d9a8, emissive: 0x3a3630, side: THREE.DoubleSide }));
        this.modelRadius = Math.max(...model.verts.map((v) => Math.hypot(...v)));
        this.scene.add(this.modelMesh);
      }
    }
    this.target.visible = !model;
    if (model) {
      const [x, y, z] = nadirSunAttitude(scene.target_km, scene.sun_km).map((a) => v3(a));
      this.modelMesh.quaternion.setFromRotationMatrix(new THREE.Matrix4().makeBasis(x, y, z));
    }
  }

  update(scene, illum, cam, model = null) {
    this.setModel(model, scene);
    const re = 6378.137; const r = 1 / re;
    const s = v3(scene.sun_km, 1).normalize();
    this.sunLight.position.copy(s.clone().multiplyScalar(50));
    this.sunArrow.setDirection(s);
    this.sunArrow.position.copy(s.clone().multiplyScalar(1.05));
    this.sunDot.position.copy(s.clone().multiplyScalar(SUN_DRAW_R));
    if (scene.moon_km) {
      this.moon.visible = true;
      this.moon.position.copy(v3(scene.moon_km, 1).normalize().multiplyScalar(MOON_DRAW_R));
    } else this.moon.visible = false;
    // shadow cones along -s: umbra radius R (1 - x / L_u), penumbra R (1 + x / L_p) (x behind the Earth)
    const dSun = Math.hypot(...scene.sun_km);
    const rs = 695700;
    const lu = (re * dSun) / (rs - re) / re;   // umbra length, Earth radii
    const lp = (re * dSun) / (rs + re) / re;   // distance from the Earth to the penumbra's apex
    const len = CONE_LEN_R;
    this.umbra.geometry.dispose();
    this.umbra.geometry = new THREE.CylinderGeometry(1, Math.max(0, 1 - len / lu), len, 64, 1, true);
    this.penumbra.geometry.dispose();
    this.penumbra.geometry = new THREE.CylinderGeometry(1.001, 1 + len / lp, len, 64, 1, true);
    for (const m of [this.umbra, this.penumbra]) {
      m.quaternion.setFromUnitVectors(new THREE.Vector3(0, -1, 0), s.clone().negate());
      m.position.copy(s.clone().multiplyScalar(-len / 2));
    }
    const t = v3(scene.target_km, r);
    this.target.position.copy(t);
    if (this.modelMesh) this.modelMesh.position.copy(t);
    this.target.material.color.set(illum && illum.shadow.region === 2 ? 0x555566 : 0xf4f4f4);
    this.tgtPos = t;
    if (scene.observer_km) {
      const o = v3(scene.observer_km, r);
      this.observer.visible = true; this.frustum.visible = true;
      this.observer.position.copy(o);
      this.obsPos = o;
      // the field: a pyramid from the observer to the target's distance, the diagonal field
      const fwd = t.clone().sub(o); const dist = fwd.length(); fwd.normalize();
      let up = o.clone().normalize();
      if (Math.abs(up.dot(fwd)) > 0.99) up = new THREE.Vector3(1, 0, 0);
      const right = new THREE.Vector3().crossVectors(fwd, up).normalize();
      const u = new THREE.Vector3().crossVectors(right, fwd);
      const half = Math.tan((cam ? cam.fov_rad : 0.2) / 2) * dist / Math.SQRT2;
      const c = o.clone().add(fwd.clone().multiplyScalar(dist));
      const corners = [[1, 1], [-1, 1], [-1, -1], [1, -1]].map(([a, b]) => c.clone().add(right.clone().multiplyScalar(a * half)).add(u.clone().multiplyScalar(b * half)));
      const pts = [];
      for (let k = 0; k < 4; k++) pts.push(o, corners[k], corners[k], corners[(k + 1) % 4]);
      this.frustum.geometry.dispose();
      this.frustum.geometry = new THREE.BufferGeometry().setFromPoints(pts);
    } else {
      this.observer.visible = false; this.frustum.visible = false; this.obsPos = null;
    }
    if (this.focus === 'target') this.controls.target.copy(t);
    if (!this.placed) { this.placed = true; this.sunDir = s; this.setFocus(this.focus); return; }
    this.controls.update();
    this.draw();
  }

  /** 'earth': orbit around the Earth; 'target': around the target, close. */
  setFocus(focus) {
    this.focus = focus;
    if (focus === 'target' && this.tgtPos) {
      const near = this.obsPos ? Math.max(this.obsPos.distanceTo(this.tgtPos) * 3, 2e-4) : 0.05;
      this.controls.target.copy(this.tgtPos);
      const away = this.tgtPos.clone().normalize().multiplyScalar(near * 0.6);
      const side = new THREE.Vector3(0, 1, 0).cross(this.tgtPos).normalize().multiplyScalar(near);
      this.camera.position.copy(this.tgtPos).add(away).add(side);
    } else {
      // look across the terminator: from the side of the Sun's direction, a little above
      this.controls.target.set(0, 0, 0);
      const s = this.sunDir ?? new THREE.Vector3(1, 0, 0);
      const side = new THREE.Vector3(0, 1, 0).cross(s).normalize();
      this.camera.position.copy(side.multiplyScalar(4.2).add(s.clone().multiplyScalar(2.2)).add(new THREE.Vector3(0, 1.8, 0)));
    }
    this.controls.update();
    this.draw();
  }

  draw() {
    // markers keep a constant size on screen
    const px = (p) => this.camera.position.distanceTo(p) * 0.012;
    if (this.tgtPos) this.target.scale.setScalar(px(this.tgtPos));
    if (this.tgtPos && this.modelMesh) this.modelMesh.scale.setScalar((px(this.tgtPos) * 4) / this.modelRadius);
    if (this.obsPos) this.observer.scale.setScalar(px(this.obsPos) * 1.4);
    this.renderer.render(this.scene, this.camera);
  }
}
