"""geardesign: design calculations for mechanical drives.

Each calculator is a package (``geardesign.spur``, ...) of pure functions on plain data;
``geardesign.core`` holds what they share: spec schemas and validation, the result model,
checks and the renderers.  The command line (``geardesign.cli``) is a thin layer on top.
"""

__version__ = "0.1.0"
