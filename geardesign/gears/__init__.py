"""Gear code shared by the calculators (spur, planetary, novikov, pzdn, the drive and the
sweep): modules here depend on no calculator.  :mod:`.losses`: the tooth loss factor of a
mesh."""
