"""Plot of the start-up transient (link torques and speeds against time) to a PNG or SVG
file.  matplotlib is an optional extra: it is imported only here, inside
:func:`write_plot`, and a clear :class:`PlotError` says how to get it when it is missing.
"""

from __future__ import annotations

from pathlib import Path

from geardesign.core.io import atomic_path

FORMATS = (".png", ".svg")


class PlotError(RuntimeError):
    """The plot cannot be written (matplotlib missing, unknown file type, no history)."""


def _history(result_or_data) -> dict:
    """The ``history`` block (time histories) and the resisting moments, from a pzdn
    :class:`~geardesign.core.result.Result`, its JSON document, or a plain dict with the
    arrays ``t``, ``T12``, ``T13`` (and optionally ``omega1..3``, ``T2``, ``T3``)."""
    data = result_or_data
    if hasattr(data, "document"):
        data = data.document()
    if "results" in data:
        res = data["results"]
        hist = dict(res.get("history") or {})
        model = res.get("startup_model") or {}
        hist.setdefault("T2", model.get("T2"))
        hist.setdefault("T3", model.get("T3"))
        data = hist
    if not data.get("t") or not data.get("T12"):
        raise PlotError("no start-up time history to plot: the result has no "
                        "history (mode = \"startup\" with startup.history_points > 0)")
    return data


def write_plot(result_or_data, path) -> Path:
    """Write the start-up time histories to ``path`` (``.png`` or ``.svg``), atomically
    (temporary file and rename).  Returns the path written."""
    path = Path(path)
    if path.suffix.lower() not in FORMATS:
        raise PlotError("the plot file must end in .png or .svg")
    h = _history(result_or_data)
    try:
        import matplotlib
    except ImportError:
        raise PlotError("matplotlib is not installed, so no plot can be written; install it "
                        "with `pip install matplotlib` (an optional extra of geardesign), or "
                        "leave the plot out") from None
    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8.0, 6.0), tight_layout=True)
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    ax1.plot(h["t"], h["T12"], label="T12 (link 1-2)")
    ax1.plot(h["t"], h["T13"], label="T13 (link 1-3)")
    for key, style in (("T2", ":"), ("T3", "--")):
        if h.get(key) is not None:
            ax1.axhline(h[key], color="grey", linestyle=style, linewidth=0.8,
                        label=f"{key} (resisting moment)")
    ax1.set_ylabel("link torque, N·m")
    ax1.grid(True, linewidth=0.3)
    ax1.legend(loc="best", fontsize=8)
    for key in ("omega1", "omega2", "omega3"):
        if h.get(key):
            ax2.plot(h["t"], h[key], label=f"ω{key[-1]}")
    ax2.set_xlabel("time, s")
    ax2.set_ylabel("speed, rad/s")
    ax2.grid(True, linewidth=0.3)
    if ax2.lines:
        ax2.legend(loc="best", fontsize=8)
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format=path.suffix.lower()[1:])
    return path
