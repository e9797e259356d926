"""Files of a sweep: the candidate dataset (CSV, or Parquet through pyarrow), the TOML text of
an emitted variant spec, and the plot of the Pareto front (matplotlib).  Heavy libraries are
imported only by the run that writes such a file."""

from __future__ import annotations

import math
from pathlib import Path


class DatasetWriter:
    """Writes the candidate rows chunk by chunk (bounded memory): ``.csv`` with the standard
    library, ``.parquet`` with pyarrow (one row group per chunk).  The file appears under its
    name only when complete (:class:`geardesign.core.io.AtomicFile`)."""

    def __init__(self, path: Path):
        from geardesign.core.io import AtomicFile

        self.path = Path(path)
        self.kind = self.path.suffix.lower()
        self.writer = None
        self.fh = None
        if self.kind == ".parquet":
            import pyarrow  # noqa: F401  (fail early when missing)
        self.file = AtomicFile(self.path)
        self.tmp = self.file.tmp
        if self.kind != ".parquet":
            self.fh = open(self.tmp, "w", newline="", encoding="utf-8-sig")   # with BOM

    def write(self, cols: dict) -> None:
        if self.kind == ".parquet":
            import pyarrow as pa
            import pyarrow.parquet as pq

            table = pa.table({k: v for k, v in cols.items()})
            if self.writer is None:
                self.writer = pq.ParquetWriter(self.tmp, table.schema)
            self.writer.write_table(table)
            return
        import csv

        w = csv.writer(self.fh)
        keys = list(cols)
        if self.writer is None:
            w.writerow(keys)
            self.writer = True
        n = len(cols[keys[0]])
        for i in range(n):
            w.writerow([_cell(cols[k][i]) for k in keys])

    def close(self, complete: bool = True) -> None:
        """Close the file; put it in place when ``complete``, else remove it (a sweep that
        stopped half-way leaves no half dataset)."""
        try:
            if self.kind == ".parquet":
                if self.writer is not None:
                    self.writer.close()
            elif self.fh is not None:
                self.fh.close()
        finally:
            if complete and (self.writer is not None or self.kind != ".parquet"):
                self.file.commit()
            else:
                self.file.abort()


def _cell(v):
    if isinstance(v, bool) or type(v).__name__ in ("bool_", "bool"):
        return int(bool(v))
    f = float(v)
    return "" if not math.isfinite(f) else repr(f)


def _toml_scalar(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, str):
        from geardesign.core.text import toml_string

        return toml_string(v)
    if isinstance(v, list):
        return "[" + ", ".join(_toml_scalar(x) for x in v) + "]"
    raise TypeError(type(v))


def toml_text(data: dict) -> str:
    """A spec dict (tables of scalars, nested tables, arrays of tables) as TOML text."""
    lines: list[str] = []

    def table(d: dict, path: str) -> None:
        simple = {k: v for k, v in d.items() if not isinstance(v, dict) and not (
            isinstance(v, list) and v and all(isinstance(x, dict) for x in v))}
        if path:
            lines.append(f"\n[{path}]")
        for k, v in simple.items():
            if v is not None:
                lines.append(f"{_key(k)} = {_toml_scalar(v)}")
        for k, v in d.items():
            sub = f"{path}.{_key(k)}" if path else _key(k)
            if isinstance(v, dict):
                table(v, sub)
            elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
                for item in v:
                    lines.append(f"\n[[{sub}]]")
                    for kk, vv in item.items():
                        if vv is not None:
                            lines.append(f"{_key(kk)} = {_toml_scalar(vv)}")

    table(data, "")
    return "\n".join(lines).lstrip("\n") + "\n"


def _key(k: str) -> str:
    """A bare TOML key (ASCII letters, digits, ``_``, ``-``) or a quoted one."""
    return k if k and k.isascii() and k.replace("_", "").replace("-", "").isalnum() \
        else _toml_scalar(k)


def plot_front(summary: dict, sw, path: Path) -> None:
    """The ranked variants and the Pareto front in the plane of the first two objectives."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from geardesign.spur.sweep import OBJECTIVES

    names = list(sw.objectives[:2]) if len(sw.objectives) > 1 else [sw.objectives[0], "margin"]
    (c1, _, u1, d1), (c2, _, u2, d2) = OBJECTIVES[names[0]], OBJECTIVES[names[1]]
    import textwrap

    import numpy as np

    fig, ax = plt.subplots(figsize=(7.5, 5.5), layout="constrained")
    for block, style, label in ((summary["head"], "o", "ranked (number: rank)"),
                                (summary["front"], "s", "Pareto front")):
        if block is not None and len(block["index"]):
            order = np.argsort(block[c1], kind="stable")
            ax.plot(block[c1][order], block[c2][order], style, label=label, ms=4,
                    linestyle="-" if "front" in label else "none")
            if "front" not in label:      # the ranked points carry their rank
                for k, (x, y) in enumerate(zip(block[c1], block[c2])):
                    ax.annotate(str(k + 1), (x, y), textcoords="offset points",
                                xytext=(4, 4), fontsize=7)
    # long axis titles wrapped, so that the constrained layout keeps them inside the figure
    ax.set_xlabel(textwrap.fill(f"{d1} [{u1}]", 60))
    ax.set_ylabel(textwrap.fill(f"{d2} [{u2}]", 40))
    ax.grid(True, alpha=0.3)
    ax.legend()
    from geardesign.core.io import atomic_path

    try:
        with atomic_path(path) as tmp:
            fig.savefig(tmp, format=Path(path).suffix.lower()[1:])
    finally:
        plt.close(fig)
