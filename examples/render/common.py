# SPDX-License-Identifier: MIT
"""Reading the planner's CSV files (input and output) into numpy arrays."""
from __future__ import annotations

import csv
import datetime as _dt
import re

import numpy as np

FLAG_SPLIT = re.compile(r"[+|;\s]+")


def read_csv(path: str) -> dict:
    """Columns of a CSV as lists of strings (header row first)."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty file")
    head = [h.strip() for h in rows[0]]
    cols = {h: [] for h in head}
    for r in rows[1:]:
        if not r:
            continue
        for h, v in zip(head, r + [""] * (len(head) - len(r))):
            cols[h].append(v.strip())
    return cols


def floats(col, default=np.nan) -> np.ndarray:
    out = np.full(len(col), default, dtype=float)
    for i, v in enumerate(col):
        if v != "":
            try:
                out[i] = float(v)
            except ValueError:
                pass
    return out


def vec(cols: dict, name: str) -> np.ndarray | None:
    if f"{name}_x" not in cols:
        return None
    return np.column_stack([floats(cols[f"{name}_{a}"]) for a in "xyz"])


def times(ids) -> np.ndarray | None:
    """ISO UTC ids -> numpy datetime64 (None when an id is not a time)."""
    out = []
    for s in ids:
        try:
            out.append(_dt.datetime.fromisoformat(s.replace("Z", "+00:00"))
                       .replace(tzinfo=None))
        except ValueError:
            return None
    return np.array(out, dtype="datetime64[ms]")


def flag_sets(col) -> list[set]:
    return [set(x for x in FLAG_SPLIT.split(v) if x) for v in col]


def intervals(mask: np.ndarray):
    """(start, stop) index pairs of the runs of True in mask (stop exclusive)."""
    m = np.concatenate([[False], np.asarray(mask, bool), [False]])
    d = np.diff(m.astype(int))
    return list(zip(np.nonzero(d == 1)[0], np.nonzero(d == -1)[0]))


def scene_inputs(cols: dict, rows=None) -> dict:
    """Arguments for orbillum.illuminate/expose from an input CSV (optionally some rows)."""
    idx = np.arange(len(cols["id"] if "id" in cols else cols["sun_x"]))
    if rows is not None:
        idx = idx[rows]
    out = {"sun": vec(cols, "sun")[idx], "target": vec(cols, "target")[idx]}
    moon = vec(cols, "moon")
    obs = vec(cols, "observer")
    out["moon"] = None if moon is None else moon[idx]
    out["observer"] = None if obs is None else obs[idx]
    for k in ("earth_albedo", "target_albedo", "target_radius_m"):
        if k in cols:
            out[k] = floats(cols[k])[idx]
    if "terms" in cols:
        dflt = "all" if moon is not None else "sun+earth"
        out["terms"] = [cols["terms"][i] or dflt for i in idx]
    if "target_shape" in cols:  # as the planner: empty is the sphere
        out["target_shape"] = [cols["target_shape"][i] or None for i in idx]
    if "q_w" in cols:  # as the planner: a row with all four empty is the identity
        q = np.column_stack([floats(cols[k]) for k in ("q_w", "q_x", "q_y", "q_z")])[idx]
        q[np.isnan(q).all(axis=1)] = (1.0, 0.0, 0.0, 0.0)
        out["attitude_q"] = q
    return out
