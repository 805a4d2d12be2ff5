"""Reconstruct a missing figure from the book's printed values, by least squares.

The collection's figures are missing, but its solutions print lengths, speeds and
accelerations read off the plans. A preset's ``[fit]`` names the numbers its text does not
give (paths into its document: ``frame.G.0``, ``driver.at``, ``pairs.0.angle``) and the
printed values they are fitted to; the other printed values are predictions that test the
reconstruction. The book prints magnitudes, so magnitudes are compared, each relative to
its printed value. A fit whose residual is above the book's precision is not a
reconstruction, and the check page says so.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from mechanisms.loader import SceneError, build_document, preset_document
from mechanisms.messages import Text
from mechanisms.schema import Fit
from solvers.budget import Unsolvable
from solvers.structure import StructureError

from .values import exact_values

MISS = 10.0  # the misfit of a value where the trial mechanism does not assemble


@dataclass(frozen=True)
class Found:
    values: tuple[float, ...]  # the unknowns, in the fit's order
    residual: float  # root mean square of the relative misfits of the used values
    converged: bool


def set_path(doc: dict, path: str, value: float) -> None:
    """doc["frame"]["G"][0] = value for frame.G.0 (an index where the table is a list)."""
    *where, last = path.split(".")
    table = doc
    for key in where:
        table = table[int(key)] if isinstance(table, list) else table[key]
    if isinstance(table, list):
        table[int(last)] = value
    else:
        table[last] = value


def misfits(doc: dict, fit: Fit, book: dict[str, float], values) -> np.ndarray:
    """(|exact| − |printed|)/|printed| for each used value, with the unknowns at ``values``."""
    trial = copy.deepcopy(doc)
    for path, value in zip(fit.unknowns, values):
        set_path(trial, path, float(value))
    trial.pop("fit", None)
    try:
        exact = exact_values(build_document(trial, source="fit"))
    except (Unsolvable, StructureError, SceneError, ValueError):
        return np.full(len(fit.used), MISS)
    return np.array([(abs(exact.get(k, math.inf)) - abs(book[k])) / abs(book[k])
                     if math.isfinite(exact.get(k, math.inf)) else MISS for k in fit.used])


def refit(preset_id: str) -> Found:
    """The preset's fit made again from its starting values (what a test reproduces)."""
    doc = preset_document(preset_id)
    scene = build_document(doc, source=preset_id)
    fit = scene.fit
    if fit is None:
        raise SceneError(Text("scene.no_fit", task=preset_id))
    result = least_squares(lambda x: misfits(doc, fit, scene.book, x), np.array(fit.start),
                           x_scale="jac", xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=2000)
    residual = float(np.sqrt(np.mean(result.fun ** 2)))
    return Found(tuple(float(v) for v in result.x), residual, bool(result.success))
