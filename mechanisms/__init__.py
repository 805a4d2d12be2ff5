"""Scenes as data: the schema, the TOML loader with validation, and the presets."""

from .loader import (SceneError, load_any, load_preset, load_scene, parse_document, parse_scene,
                     preset_ids)
from .schema import DRIVER, FRAME, Driver, Force, Member, Moment, Pair, Scene

__all__ = ["DRIVER", "FRAME", "Driver", "Force", "Member", "Moment", "Pair", "Scene",
           "SceneError", "load_any", "load_preset", "load_scene", "parse_document", "parse_scene",
           "preset_ids"]
