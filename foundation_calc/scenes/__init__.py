"""Scene files: one TOML file per design, validated by pydantic models.

:func:`load_scene` reads a file, looks at its ``kind`` and validates it with that kind's model;
the model module of a kind is imported only when a file of that kind is read.
"""

from foundation_calc.scenes.files import read_toml
from foundation_calc.scenes.kinds import KINDS
from foundation_calc.scenes.loading import load_scene, parse_scene

__all__ = ["KINDS", "load_scene", "parse_scene", "read_toml"]
