"""Levers of the drive advice (:mod:`geardesign.core.advice`): a stage fails (``STAGE_i``)
and its own report advises a change of the stage spec (``gear.face_width = ...``).  The
drive writes that change at the drive's own key path (``stage[0].gear.face_width``) and
re-rates the whole drive with it, so that the stage's loads, efficiencies and the heat
balance follow; a stage read from a file is changed in that file, which the drive spec
cannot name: no fix.  Candidates: the fixes of the stage's failed checks merged into one
change (where they do not set a key differently), then each on its own."""

from __future__ import annotations

from geardesign.core.advice import Lever

MAX_STAGES = 12
"""Stages whose advice is carried up (a drive has a few)."""


def _stage_fixes(i: int):
    def gen(data: dict, res):
        stages = data.get("stage") or []
        # the stage reports follow the inline stages one for one up to the first file
        inline = 0
        for st in stages:
            if not isinstance(st, dict) or st.get("file") is not None:
                break
            inline += 1
        reports = [r for key, _, r in res.parts if key == "stage_reports"]
        if i >= min(inline, len(reports)):
            return
        fixes = []
        for c in reports[i].failed:
            if c.fix and c.fix not in fixes:
                fixes.append(c.fix)
        if not fixes:
            return
        merged: dict = {}
        for fix in fixes:
            for k, v in fix:
                merged.setdefault(k, v)
        consistent = all(merged[k] == v for fix in fixes for k, v in fix)
        prefix = f"stage[{i}]."
        if consistent and len(fixes) > 1:
            yield tuple((prefix + k, v) for k, v in merged.items())
        for fix in fixes:
            yield tuple((prefix + k, v) for k, v in fix)
    return gen


LEVERS = tuple(Lever((f"STAGE_{i + 1}",), _stage_fixes(i),
                     f"the change stage {i + 1}'s report advises, at the drive's key path")
               for i in range(MAX_STAGES))
