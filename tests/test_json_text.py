"""geardesign.core.text.json_text writes, indented, the very text of the standard library's
``json.dumps(..., indent=..., ensure_ascii=False, allow_nan=False)`` with the raw controls
and bidi marks escaped, or raises the same error, over random nested documents (plain
data written by its own encoder, anything else left to the standard library)."""

from __future__ import annotations

import enum
import json
import math
import re

from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.text import json_text

RAW = re.compile("[\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069\u2028\u2029]")


def reference(obj, indent):
    """The standard library's text, raw characters escaped (or its exception)."""
    try:
        text = json.dumps(obj, indent=indent, ensure_ascii=False, allow_nan=False)
    except (TypeError, ValueError) as exc:
        return type(exc), str(exc)
    return RAW.sub(lambda m: f"\\u{ord(m.group(0)):04x}", text)


def ours(obj, indent):
    try:
        return json_text(obj, indent=indent)
    except (TypeError, ValueError) as exc:
        return type(exc), str(exc)


class Colour(enum.IntEnum):
    RED = 1


TEXT = st.text(st.characters(codec="utf-8") | st.sampled_from(
    "\x00\n\"\\\x7f\x85\x9f\u061c\u200e\u202e\u2066\u2028\u2029°σ✔"), max_size=8)
NUMBER = st.floats(allow_nan=False, allow_infinity=False) | st.integers() | st.floats()
LEAF = st.none() | st.booleans() | NUMBER | TEXT
KEY = TEXT | st.integers(-5, 5) | st.floats(allow_nan=False) | st.booleans() | st.none()
ODD = st.sampled_from([Colour.RED, 1 + 2j, {1, 2}, b"x", math.nan])
PLAIN = st.recursive(LEAF, lambda inner: st.lists(inner, max_size=5)
                     | st.lists(inner, max_size=3).map(tuple)
                     | st.dictionaries(TEXT, inner, max_size=5), max_leaves=40)
ANY = st.recursive(LEAF | ODD, lambda inner: st.lists(inner, max_size=4)
                   | st.dictionaries(KEY, inner, max_size=4), max_leaves=30)


@settings(max_examples=400, deadline=None)
@given(PLAIN, st.integers(0, 4))
def test_plain_documents_are_the_standard_librarys_text(doc, indent):
    assert ours(doc, indent) == reference(doc, indent)


@settings(max_examples=300, deadline=None)
@given(ANY, st.sampled_from([None, 0, 1, 2]))
def test_any_document_gives_the_standard_librarys_text_or_error(doc, indent):
    assert ours(doc, indent) == reference(doc, indent)


def test_a_circular_document_is_refused_as_the_standard_library_does():
    doc: dict = {"a": [1.0]}
    doc["a"].append(doc)
    assert ours(doc, 2) == reference(doc, 2)


def test_every_raw_character_is_escaped_in_keys_values_and_flat_tables():
    for c in "\x7f\x80\x85\x9f\u061c\u200e\u200f\u202a\u202e\u2066\u2069\u2028\u2029":
        for doc in ({c: None}, {"a": c}, [c], {"a": [c, {"b": c}]}, c):
            for indent in (None, 0, 2):
                assert ours(doc, indent) == reference(doc, indent)
                assert c not in ours(doc, indent)
