"""Reduce the REXS attribute database of one version to what geardesign writes and reads.

The REXS database (one XML file per version and language, ``rexs_schema_<version>_en.xml``,
published by the FVA in the rexs-api-cpp and rexs-api-java repositories, Apache License 2.0,
see docs/references.md [REXS-DB]) lists ~1500 attributes.  geardesign needs, for the
component types it writes, each attribute's id, unit and value type (and an enum's values)
and which attributes belong to which component type; this script keeps exactly that and
writes it as JSON into the package::

    python tools/rexs_database_extract.py rexs_schema_1.5_en.xml \
        geardesign/rexs/rexs_database_1.5.json

It is run by hand when a version is added; the JSON is package data.
"""

from __future__ import annotations

import json
import sys
import xml.etree.ElementTree as ET

COMPONENTS = (
    "gear_unit", "gear_casing", "shaft", "shaft_section", "cylindrical_gear",
    "cylindrical_stage", "cylindrical_gear_flank", "cylindrical_stage_gear_data",
    "rolling_bearing_with_catalog_geometry", "concept_bearing", "external_load", "material",
    "lubricant", "worm_gear", "worm_wheel", "worm_stage", "worm_stage_gear_data",
    "planetary_stage", "planet_carrier", "ring_gear", "planet_shaft", "central_shaft",
    "bevel_stage", "bevel_gear", "bevel_stage_gear_data",
)
"""Component types whose attributes are kept (those the exporter writes and the importer
reads)."""


def extract(source: str) -> dict:
    root = ET.parse(source).getroot()   # the FVA's own file, read by hand: trusted input
    units = {u.get("id"): u.get("name") for u in root.iter("unit")}
    types = {t.get("id"): t.get("name") for t in root.iter("valueType")}
    mapping: dict[str, list[str]] = {c: [] for c in COMPONENTS}
    for m in root.iter("componentAttributeMapping"):
        if m.get("componentId") in mapping:
            mapping[m.get("componentId")].append(m.get("attributeId"))
    wanted = {a for attrs in mapping.values() for a in attrs}
    attributes = {}
    for a in root.iter("attribute"):
        aid = a.get("attributeId")
        if aid not in wanted:
            continue
        entry = {"unit": units.get(a.get("unit"), ""), "type": types.get(a.get("valueType"))}
        enums = [e.get("value") for e in a.iter("enumValue")]
        if enums:
            entry["enum"] = enums
        attributes[aid] = entry
    relations = sorted({r.get("relationId") for r in root.iter("relation")})
    return {"version": root.get("version"),
            "source": "FVA REXS database rexs_schema_%s_en.xml (rexs-api-cpp, models/), "
                      "Apache License 2.0; reduced by tools/rexs_database_extract.py"
                      % root.get("version"),
            "relation_types": relations,
            "components": {c: sorted(v) for c, v in mapping.items()},
            "attributes": dict(sorted(attributes.items()))}


if __name__ == "__main__":
    src, dst = sys.argv[1:3]
    with open(dst, "w", encoding="utf-8") as fh:
        json.dump(extract(src), fh, indent=0, sort_keys=False, ensure_ascii=False)
        fh.write("\n")
