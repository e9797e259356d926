"""The pictures of a result, one module per kind of calculator (:mod:`.gears`,
:mod:`.drive`, :mod:`.charts`), joined by :func:`geardesign.rendering.figures.figures`."""
