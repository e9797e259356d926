"""Ranking of a sweep's feasible candidates: the ranked head by the objectives and the
Pareto front of the first two, merged chunk by chunk, and whether the best sits on the edge
of a varied range."""

from __future__ import annotations

import numpy as np

from geardesign.spur.sweep_input import OBJECTIVES, Sweep

def _keys(sel: dict, sw: Sweep) -> list:
    """Sort keys, most significant first: the objectives in order, then the candidate index
    (a stable, machine-independent order)."""
    keys = [sel["index"]]
    for name in reversed(sw.objectives):
        col, sign, _, _ = OBJECTIVES[name]
        keys.append(sign * sel[col])
    return keys


def _rank(sel: dict, sw: Sweep) -> dict:
    if not len(sel["index"]):
        return sel
    order = np.lexsort(_keys(sel, sw))[: sw.top]
    return {k: v[order] for k, v in sel.items()}


def _front(sel: dict, sw: Sweep) -> dict:
    """The non-dominated candidates of the first two objectives (one objective: the best).
    Sorted by the first objective; a candidate enters when it improves on the second."""
    if not len(sel["index"]):
        return sel
    names = sw.objectives[:2]
    c1, s1, _, _ = OBJECTIVES[names[0]]
    if len(names) == 1:
        order = np.lexsort((sel["index"], s1 * sel[c1]))[:1]
        return {k: v[order] for k, v in sel.items()}
    c2, s2, _, _ = OBJECTIVES[names[1]]
    f1, f2 = s1 * sel[c1], s2 * sel[c2]
    order = np.lexsort((sel["index"], f2, f1))
    f2s = f2[order]
    best = np.minimum.accumulate(f2s)
    keep = np.ones(len(order), dtype=bool)
    keep[1:] = f2s[1:] < best[:-1]
    return {k: v[order[keep]] for k, v in sel.items()}


def _merge(a: dict, b: dict) -> dict:
    if a is None:
        return b
    return {k: np.concatenate([a[k], b[k]]) for k in a}


RANGE_COLUMNS = {"gear.module": "m_n", "gear.z1": "z1", "gear.z2": "z2", "gear.x1": "x1",
                 "gear.x2": "x2", "gear.helix_angle": "helix_angle", "gear.face_width": "b_w",
                 "gear.center_distance": "a_w", "gear.accuracy_grade": "accuracy_grade",
                 "gear.bearing_scheme": "bearing_scheme"}
"""The column of the ranked variants that holds each varied key's value."""

EDGE_SAMPLE = 0.02
"""In a sample (not a grid), a value within this part of its range of an end is at it."""


def range_edges(sw: Sweep, head: dict | None) -> list[str]:
    """The varied keys (of more than one value) whose value in the first ranked variant is
    an end of their range, as "gear.helix_angle = 15 at the top of 0 … 15"."""
    if head is None or not len(head["index"]):
        return []
    out = []
    for d in sw.dims:
        col = RANGE_COLUMNS.get(d.key)
        if col is None or col not in head or d.high <= d.low:
            continue
        v = float(head[col][0])
        tol = (EDGE_SAMPLE if sw.samples else 1e-9) * (d.high - d.low)
        for end, word in ((d.high, "top"), (d.low, "bottom")):
            if abs(v - end) <= tol:
                out.append(f"{d.key} = {v:.6g} at the {word} of {d.low:g} … {d.high:g}")
                break
    return out




class Summary:
    """The merged summary of evaluated chunks: counts, failures by check, the ranked head and
    the Pareto front.  Merging is associative and the order of a tie is the candidate index,
    so any split of the candidates into chunks and tasks gives the same summary."""

    def __init__(self, sw: Sweep) -> None:
        self.sw = sw
        self.counts = {"evaluated": 0, "valid": 0, "passed": 0, "feasible": 0}
        self.fails: dict = {}
        self.head = self.front = None

    def add(self, res: dict) -> None:
        """Merge one chunk's (or task's) summary ``res``."""
        for k in self.counts:
            self.counts[k] += res["counts"][k]
        for k, v in res["fails"].items():
            self.fails[k] = self.fails.get(k, 0) + v
        self.head = _rank(_merge(self.head, res["head"]), self.sw)
        self.front = _front(_merge(self.front, res["front"]), self.sw)

    def result(self) -> dict:
        return {"counts": dict(self.counts), "fails": dict(self.fails), "head": self.head,
                "front": self.front}
