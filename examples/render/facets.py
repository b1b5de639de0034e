# SPDX-License-Identifier: MIT
"""OBJ facet models for the camera view: geometry only (loading, attitude, the
runtime's facets of the triangles, ray casting); the light is the runtime's.

Only what the view needs: ``v`` and ``f`` records of a Wavefront OBJ file
(polygons are fanned into triangles; texture/normal indices are ignored). Each
triangle becomes one facet of the runtime (oi_facet, through the binding): its
normal from the winding (counter-clockwise seen from outside; a closed mesh
wound the other way round throughout is turned), its area, one-sided when each
of its edges is shared with another triangle (a closed surface; a panel
modelled as two sheets back to back is closed too), two-sided when it lies on
an open sheet. The runtime does
not model shadowing between facets (a facet hidden from a source by another is
still lit: exact for convex bodies only), and neither does the picture.

Attitude ("nadir-sun"): body +z towards the Earth's centre, body +x towards the
Sun projected on the plane normal to nadir, +y = z x x. Solar panels modelled
along +-y with normals along +-x then face the Sun as well as a yaw-steering
nadir-pointing satellite can.
"""
from __future__ import annotations

import numpy as np


#: barycentric tolerance of the ray-triangle test: a ray on the edge two
#: triangles share hits one of them despite rounding
EDGE_EPS = 1e-12


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


def attitude_quaternion(rot: np.ndarray) -> np.ndarray:
    """Unit quaternion (w, x, y, z) of a rotation matrix whose columns are the
    body axes in the input frame (body -> input, oi_scene.attitude_q).

    Shepperd (1978), "Quaternion from rotation matrix", J. Guidance and
    Control 1(3), 223: from the largest of the four squared components.
    """
    m = np.asarray(rot, dtype=float)
    tr = np.trace(m)
    cand = np.array([tr, m[0, 0], m[1, 1], m[2, 2]])
    k = int(np.argmax(cand))
    if k == 0:
        w = 0.5 * np.sqrt(1.0 + tr)
        q = [w, (m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w),
             (m[1, 0] - m[0, 1]) / (4 * w)]
    else:
        i, j, l = k - 1, k % 3, (k + 1) % 3
        v = np.zeros(3)
        v[i] = 0.5 * np.sqrt(1.0 + 2 * m[i, i] - tr)
        v[j] = (m[j, i] + m[i, j]) / (4 * v[i])
        v[l] = (m[l, i] + m[i, l]) / (4 * v[i])
        w = (m[l, j] - m[j, l]) / (4 * v[i])
        q = [w, v[0], v[1], v[2]]
    q = np.array(q)
    return q / np.linalg.norm(q)


def triangle_facets(verts: np.ndarray, tris: np.ndarray, albedo_diffuse: float,
                    albedo_specular: float = 0.0, shininess: float = 0.0) -> list[dict]:
    """One runtime facet (a dict for orbillum.Shape) per triangle, body frame."""
    a, b, c = (verts[tris[:, k]] for k in range(3))
    cr = np.cross(b - a, c - a)
    area = 0.5 * np.linalg.norm(cr, axis=1)
    if (area <= 0).any():
        raise ValueError(f"triangle {int(np.argmin(area))} has no area")
    # welded edges: a triangle on an open sheet (an edge no other triangle has) is two-sided
    key = np.round(verts, 9)
    edges = {}
    for t in tris:
        for u, v in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            e = tuple(sorted((tuple(key[u]), tuple(key[v]))))
            edges[e] = edges.get(e, 0) + 1
    # a closed mesh wound inwards (negative enclosed volume): its normals turned outwards
    closed = all(c >= 2 for c in edges.values())
    if closed and np.sum(np.einsum("ij,ij->i", a, np.cross(b, c))) < 0:
        cr = -cr
    out = []
    for t, n, ar in zip(tris, cr, area):
        open_edge = any(edges[tuple(sorted((tuple(key[u]), tuple(key[v]))))] == 1
                        for u, v in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])))
        out.append({"normal": n / np.linalg.norm(n), "area_m2": float(ar),
                    "two_sided": bool(open_edge), "albedo_diffuse": albedo_diffuse,
                    "albedo_specular": albedo_specular, "shininess": shininess})
    return out


def merge_facets(facets: list[dict]) -> list[dict]:
    """Facets of equal normal, sides and reflectances summed into one (the
    runtime's flux is linear in the area, so the sum is exact): the whole
    model as one oi_shape of at most OI_FACETS_MAX facets."""
    groups = {}
    for f in facets:
        k = (tuple(np.round(f["normal"], 9)), f["two_sided"], f["albedo_diffuse"],
             f["albedo_specular"], f["shininess"])
        if k in groups:
            groups[k]["area_m2"] += f["area_m2"]
        else:
            groups[k] = dict(f)
    return list(groups.values())


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
        # edges belong to both triangles (EDGE_EPS): no ray through the crack of a shared edge
        hit = (ok & (u >= -EDGE_EPS) & (v >= -EDGE_EPS) & (u + v <= 1 + EDGE_EPS) & (t > 0)
               & (t < best_t))
        best_t[hit] = t[hit]
        best_f[hit] = k
    hit = best_f >= 0
    return hit.reshape(shape), best_f.reshape(shape), best_t.reshape(shape)
