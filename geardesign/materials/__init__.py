"""Materials, in one place: data tables (TOML files beside this module) and the functions
that read them.  Each family has its own module: gear steels (GOST 21354-87 strength
data), worm-wheel bronzes and cast irons, spring steels, ...  Calculators name a material
from these tables or give its properties directly; explicit values override table values.
"""
