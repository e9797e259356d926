"""``geardesign materials [FILTER]`` and ``geardesign bearings [FILTER]``: the built-in data
as a table, JSON, JSON lines, CSV or Markdown.  The libraries are read only when one of these
commands runs.  An unknown name gets a "did you mean" line and exit 2."""

from __future__ import annotations

import csv
import difflib
import io
import sys
from typing import Callable, Optional

import typer

from geardesign import completion as _complete

FORMATS = ("table", "json", "jsonl", "csv", "markdown")


def _key(text: str) -> str:
    return "".join(str(text).split()).replace("-", "").upper()


# ----------------------------------------------------------------------------- rows


def bearing_rows(filter_: Optional[str], bore: Optional[float], kind: Optional[str],
                 maker: Optional[str]) -> list[dict]:
    from geardesign.bearing import catalogue as CAT

    out = []
    k = _key(filter_) if filter_ else ""
    if k and not any(k in _key(x) for b in CAT.bearings()
                     for x in (b.designation, b.maker_designation, b.gost) if x):
        try:      # a written designation: "6208-2RS", "SKF 6208 (GOST 208)"
            row = CAT.read(filter_).row
        except ValueError:
            row = None
        if row is not None:
            k = _key(row.designation)
    for b in CAT.bearings():
        if k and not any(k in _key(x) for x in (b.designation, b.maker_designation, b.gost)
                         if x):
            continue
        if bore is not None and abs(b.d - bore) > 1e-9:
            continue
        if kind is not None and b.type != kind:
            continue
        if maker is not None and b.maker.upper() != maker.upper():
            continue
        out.append({"designation": b.designation, "maker": b.maker,
                    "maker_designation": b.maker_designation, "gost": b.gost or None,
                    "type": b.type, "series": b.series, "d": b.d, "D": b.D, "B": b.B,
                    "C_r": b.C_r, "C_0r": b.C_0r, "C_u": b.C_u, "e": b.e, "Y1": b.Y1, "Y": b.Y,
                    "Y0": b.Y0, "f0": b.f0, "alpha": b.alpha, "n_ref": b.n_ref,
                    "n_lim": b.n_lim, "mass": b.mass, "source": b.cite, "note": b.note or None})
    return out


BEARING_COLUMNS = (("designation", "designation", ""), ("maker", "maker", ""),
                   ("type", "type", ""), ("d", "d", "mm"), ("D", "D", "mm"),
                   ("B", "B/T/H", "mm"), ("C_r", "C_r", "kN"), ("C_0r", "C_0r", "kN"),
                   ("C_u", "C_u", "kN"), ("e", "e", ""), ("Y", "Y", ""),
                   ("n_lim", "n_lim", "min^-1"), ("source", "source", ""))


def material_rows(filter_: Optional[str], family: Optional[str]) -> list[dict]:
    from geardesign.materials import catalog

    k = _key(filter_) if filter_ else ""
    out = []
    for row in catalog.rows():
        names = [row["name"], *row.get("equivalents", []), row["family"], row.get("standard", "")]
        if k and not any(k in _key(x) for x in names if x):
            continue
        if family is not None and row["family"] != family:
            continue
        out.append(row)
    return out


MATERIAL_COLUMNS = (("name", "material", ""), ("family", "family", ""),
                    ("treatment", "treatment", ""), ("hardness", "hardness", ""),
                    ("sigma_T", "σ_T", "MPa"), ("sigma_B", "σ_B", "MPa"),
                    ("sigma_Hlim", "σ_Hlim", "MPa"), ("sigma_Flim", "σ_Flim", "MPa"),
                    ("equivalents", "equivalents", ""), ("source", "source", ""))


# ----------------------------------------------------------------------------- output


def _cell(v, unit: str = "") -> str:
    if v is None:
        return "—"
    if isinstance(v, (list, tuple)):
        return ", ".join(str(x) for x in v) or "—"
    if isinstance(v, float):
        if unit == "kN":
            v = v / 1000.0
        return f"{v:.0f}" if abs(v) >= 1000 else f"{v:.4g}"
    return str(v)


def _render(rows: list[dict], columns, fmt: str) -> str:
    from geardesign.core.render import BOM, csv_cell
    from geardesign.core.result import clean_value
    from geardesign.core.text import json_text

    rows = [{k: clean_value(v) for k, v in r.items()} for r in rows]   # as every renderer
    if fmt == "json":
        return json_text(rows, indent=2) + "\n"
    if fmt == "jsonl":
        return "".join(json_text(r) + "\n" for r in rows)
    if fmt == "csv":
        buf = io.StringIO()
        keys = list(dict.fromkeys(k for r in rows for k in r)) or [c[0] for c in columns]
        w = csv.DictWriter(buf, keys, lineterminator="\n", restval="")
        w.writeheader()
        for r in rows:
            w.writerow({k: csv_cell(_cell(v) if isinstance(v, (list, tuple)) else v)
                        for k, v in r.items()})
        return BOM + buf.getvalue()
    head = [title + (f" ({unit})" if unit else "") for _, title, unit in columns]
    body = [[_cell(r.get(k), unit) for k, _, unit in columns] for r in rows]
    if fmt == "markdown":
        lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
        from geardesign.core.text import md_escape

        lines[0] = "| " + " | ".join(md_escape(h) for h in head) + " |"
        lines += ["| " + " | ".join(md_escape(c) for c in row) + " |" for row in body]
        return "\n".join(lines) + "\n"
    from geardesign.core.render import grid_text

    numbers = {i for i, (key, _, _) in enumerate(columns)
               if all(isinstance(r.get(key), (int, float, type(None))) for r in rows)}
    text = grid_text(head, body, right=numbers, whole={0})
    return text.strip("\n") + f"\n{len(rows)} rows\n"


def _fail(line: str) -> None:
    from geardesign.core.text import escape_controls

    sys.stderr.write(escape_controls(line) + "\n")
    raise typer.Exit(2)


def _hint(word: str, names: list[str]) -> str:
    keyed = {_key(n): n for n in names if n}
    close = difflib.get_close_matches(_key(word), list(keyed), 3, 0.5)
    return (" (did you mean " + ", ".join(f'"{keyed[c]}"' for c in close) + "?)") if close else ""


# ----------------------------------------------------------------------------- commands


def register(app: typer.Typer, choose_format: Callable, finite: Callable) -> None:
    """Add the two browsing commands to the command line (called from :mod:`geardesign.cli`);
    ``choose_format(fmt, None)`` picks the format as the other commands do; ``finite`` is the
    callback that refuses a float option of ``nan`` or ``inf``."""

    @app.command("bearings")
    def bearings_cmd(
            filter_: Optional[str] = typer.Argument(None, metavar="[FILTER]",
                                                    help="Part of a designation: 62, NU 2, "
                                                         "302, 7208 (ISO, maker's or GOST)."),
            bore: Optional[float] = typer.Option(None, "--bore", min=0.0, callback=finite,
                                                 help="Bore diameter d (mm)."),
            type_: Optional[str] = typer.Option(None, "--type", help="Bearing type, e.g. "
                                                "tapered_roller.",
                                                autocompletion=_complete.bearing_types),
            maker: Optional[str] = typer.Option(None, "--maker", help="SKF, NTN.",
                                                autocompletion=_complete.bearing_makers),
            format: Optional[str] = typer.Option(None, "--format", "-f",
                                                 help="table, json, jsonl, csv, markdown.")
    ) -> None:
        """List the built-in bearing catalogue (ratings in kN in the table, N in JSON), with
        the catalogue and page each row was read from."""
        from geardesign.bearing import catalogue as CAT

        fmt = _format(format, choose_format)
        if type_ is not None and type_ not in CAT.types():
            _fail(f'geardesign bearings: --type "{type_}" is not a bearing type'
                  f'{_hint(type_, CAT.types())}; types: {", ".join(CAT.types())}')
        if maker is not None and maker.upper() not in {m.upper() for m in CAT.makers()}:
            _fail(f'geardesign bearings: --maker "{maker}" is not in the catalogue; makers: '
                  f'{", ".join(CAT.makers())}')
        rows = bearing_rows(filter_, bore, type_, maker)
        if not rows:
            if filter_:
                close = CAT.close_matches(filter_)
                hint = (" (did you mean " + ", ".join(f'"{c}"' for c in close) + "?)"
                        if close else "")
                _fail(f'geardesign bearings: no bearing matches "{filter_}"{hint}'
                      + (f" with d = {bore:g} mm" if bore is not None else ""))
            _fail("geardesign bearings: no bearing matches these options" +
                  (f"; catalogue bores of this type: "
                   + ", ".join(f"{x:g}" for x in CAT.bores(type_)) if type_ else ""))
        sys.stdout.write(_render(rows, BEARING_COLUMNS, fmt))

    @app.command("materials")
    def materials_cmd(
            filter_: Optional[str] = typer.Argument(None, metavar="[FILTER]",
                                                    help="Part of a name: 42CrMo4, 40Kh, "
                                                         "4140, VG 220, bronze."),
            family: Optional[str] = typer.Option(None, "--family", help="gear_steel, "
                                                 "worm_wheel, oil.",
                                                 autocompletion=_complete.material_families),
            format: Optional[str] = typer.Option(None, "--format", "-f",
                                                 help="table, json, jsonl, csv, markdown.")
    ) -> None:
        """List the built-in material library (gear steels, worm-wheel materials, oils)
        with the source of each row and its equivalent grades."""
        from geardesign.materials import catalog

        fmt = _format(format, choose_format)
        if family is not None and family not in catalog.families():
            _fail(f'geardesign materials: --family "{family}" is unknown'
                  f'{_hint(family, list(catalog.families()))}; families: '
                  f'{", ".join(catalog.families())}')
        rows = material_rows(filter_, family)
        if not rows:
            names = [r["name"] for r in catalog.rows()] + [
                e for r in catalog.rows() for e in r.get("equivalents", [])]
            _fail(f'geardesign materials: no material matches "{filter_}"'
                  f'{_hint(filter_ or "", names)}')
        sys.stdout.write(_render(rows, MATERIAL_COLUMNS, fmt))


def _format(value: Optional[str], choose_format: Callable) -> str:
    if value is None:
        fmt = choose_format(None, None)
        return fmt if fmt in FORMATS else "json"
    if value.lower() not in FORMATS:
        _fail(f'geardesign: --format "{value}" is not one of {", ".join(FORMATS)}')
    return value.lower()
