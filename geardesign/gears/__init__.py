"""Gear code shared by the calculators (spur, planetary, novikov, pzdn, worm, bevel, the
drive and the sweep): modules here depend on no calculator.

:mod:`.geometry`: the external pair (GOST 16532-70), basic rack, tip thickness, the
array form of the pair (``pair_core``); :mod:`.span`: base tangent length and the teeth
spanned; :mod:`.internal`: the internal pair (GOST 19274-73 / ISO 21771) and its shaper
cutter; :mod:`.internal_formulas`: the internal pair's pressure angle, tip interference and
tip thickness; :mod:`.losses`: the tooth loss factor of a mesh."""
