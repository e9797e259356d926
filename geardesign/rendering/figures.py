"""The pictures of a result for the report, as inline SVG: ``figures(res)`` maps a
section key (``""`` for the top of the report, after the summary) to a list of
:class:`Figure`.  Drawn from the result alone (its rows and tables, the spur pair's
geometry), never recomputed; a kind without a picture gets none.

* spur/helical pair: the tooth profiles in mesh with the pitch, base, tip and root circles
  and the line of action (:func:`geardesign.spur.export.profile_svg`);
* shaft: shear force, bending moment and torque, and deflection along the shaft, the
  critical sections marked;
* drive: the power flow motor → stages → output (torque, speed, ratio, efficiency of
  each stage) and the heat balance (losses per stage and kind, sump temperature);
* sweep: the ranked variants and the Pareto front in the plane of the first two
  objectives, each point labelled with its rank;
* worm: the pair in the mid-plane of the wheel, to scale;
* planetary: the layout to scale (sun, planets on the carrier circle, ring or rings);
* pzdn: the start-up torques and speeds; geneva: the motion law and the load over the
  crank angle; novikov: stresses and loads over the contact phases; ball clutch: the
  limit torque against speed; epicycle rim: the Mathieu stability chart.

The pictures of each kind are drawn in :mod:`geardesign.rendering.pictures`.
"""

from __future__ import annotations

from geardesign.rendering.pictures import charts as C
from geardesign.rendering.pictures import drive as D
from geardesign.rendering.pictures import gears as G
from geardesign.rendering.pictures.base import Figure

__all__ = ["Figure", "figures", "has_figure", "plot_svg"]

_BY_KIND = {"worm": G.worm_figures, "spur": G.spur_figures, "planetary": G.planetary_figures,
            "drive": D.drive_figures, "shaft": C.shaft_figures, "sweep": C.sweep_figures,
            "pzdn": C.pzdn_figures, "geneva": C.geneva_figures, "novikov": C.novikov_figures,
            "ball_clutch": C.ball_clutch_figures, "epicycle_rim": C.epicycle_rim_figures}


def figures(res) -> dict:
    """The figures of ``res`` by section key (``""``: after the summary)."""
    make = _BY_KIND.get(res.kind)
    if make is None:
        return {}
    try:
        out = make(res)
    except (KeyError, TypeError, ValueError, ZeroDivisionError, OverflowError):
        return {}          # a picture never stops the report
    return {k: [f for f in v if f.svg] for k, v in out.items()}


def has_figure(res) -> bool:
    return any(figures(res).values())


def plot_svg(res) -> str | None:
    """Every picture of ``res`` in one SVG document (``--plot FILE.svg``), or None when
    its kind has none."""
    from geardesign.rendering.svg import stack_svg

    figs = [f for fs in figures(res).values() for f in fs]
    if not figs:
        return None
    return stack_svg([f.svg for f in figs], [f.caption for f in figs])
