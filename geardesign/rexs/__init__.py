"""REXS exchange: ``geardesign import MODEL.rexs`` writes a spec (drive, planetary, worm) from
a REXS gear unit, ``geardesign export SPEC.toml --format rexs`` writes a spec's gear unit as
REXS 1.5 (docs/rexs.md).  Nothing is imported here: the commands import their modules when
run."""
