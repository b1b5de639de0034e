# SPDX-License-Identifier: MIT
"""OBJ facet models for the camera view: loading, attitude, ray casting.

Only what the view needs: ``v`` and ``f`` records of a Wavefront OBJ file
(polygons are fanned into triangles; texture/normal indices are ignored), flat
shading with the facet normal turned towards the viewer (thin plates such as
solar panels are seen from both sides), no self-shadowing (a facet hidden from
a source by another facet is still lit: exact for convex bodies only).

Attitude ("nadir-sun"): body +z towards the Earth's centre, body +x towards the
Sun projected on the plane normal to nadir, +y = z x x. Solar panels modelled
along +-y with normals along +-x then face the Sun as well as a yaw-steering
nadir-pointing satellite can.
"""
from __future__ import annotations

import numpy as np


def load_obj(path: str) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (V, 3) in the file's units (metres here) and triangles (F, 3) indices."""
    verts, tris = [], []
    with open(path, encoding="utf-8") as f:
        for lineno, line in enumerate(f, 1):
            p = line.split()
            if not p or p[0].startswith("#"):
                continue
            if p[0] == "v":
                if len(p) < 4:
                    raise ValueError(f"{path}:{lineno}: a vertex needs x y z")
                verts.append([float(x) for x in p[1:4]])
            elif p[0] == "f":
                idx = []
                for q in p[1:]:
                    k = int(q.split("/")[0])
                    idx.append(k - 1 if k > 0 else len(verts) + k)
                if len(idx) < 3:
                    raise ValueError(f"{path}:{lineno}: a face needs 3 vertices or more")
                for j in range(1, len(idx) - 1):
                    tris.append([idx[0], idx[j], idx[j + 1]])
    v = np.array(verts, dtype=float)
    t = np.array(tris, dtype=int)
    if v.size == 0 or t.size == 0:
        raise ValueError(f"{path}: no vertices or faces")
    if t.min() < 0 or t.max() >= len(v):
        raise ValueError(f"{path}: a face refers to a vertex that does not exist")
    return v, t


def nadir_sun_attitude(target_km: np.ndarray, sun_km: np.ndarray) -> np.ndarray:
    """Rotation matrix whose columns are the body x, y, z axes in the inertial frame."""
    z = -target_km / np.linalg.norm(target_km)
    s = sun_km - target_km
    s = s / np.linalg.norm(s)
    x = s - (s @ z) * z
    if np.linalg.norm(x) < 1e-9:  # Sun along nadir: any x
        x = np.cross(z, [1.0, 0.0, 0.0] if abs(z[0]) < 0.9 else [0.0, 1.0, 0.0])
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    return np.column_stack([x, y, z])


def cast(origin: np.ndarray, dirs: np.ndarray, tri_xyz: np.ndarray):
    """Nearest hit of rays origin + t dirs (dirs (..., 3) unit) on triangles (F, 3, 3).

    Moller & Trumbore (1997), "Fast, minimum storage ray-triangle intersection",
    J. Graphics Tools 2(1), 21. Returns (hit mask, facet index, t).
    """
    shape = dirs.shape[:-1]
    d = dirs.reshape(-1, 3)
    best_t = np.full(d.shape[0], np.inf)
    best_f = np.full(d.shape[0], -1)
    for k, (a, b, c) in enumerate(tri_xyz):
        e1, e2 = b - a, c - a
        pv = np.cross(d, e2)
        det = pv @ e1
        ok = np.abs(det) > 1e-30
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        tv = origin - a
        u = (pv @ tv) * inv
        qv = np.cross(tv, e1)
        v = (d @ qv) * inv
        t = (qv @ e2) * inv
        hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0) & (t < best_t)
        best_t[hit] = t[hit]
        best_f[hit] = k
    hit = best_f >= 0
    return hit.reshape(shape), best_f.reshape(shape), best_t.reshape(shape)
