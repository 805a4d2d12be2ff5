"""Book vs exact: every value a preset quotes from the textbook, beside the value computed here.

The book's printed answers carry slips (a swapped digit, a copied angle, a lost sign) and
the rounding of its intermediate steps. A printed value *agrees* when it matches the exact
one to within one unit of its last printed digit, is *close* when it is off by less than
3 % (rounded intermediate values, or a drawing read off to its precision; for angles,
by at most 2°, a protractor's reading), and *differs* otherwise — most likely a slip, explained where the preset's ``[book_notes]`` can tell. A preset whose figure is missing and
whose layout is assumed (``layout_assumed``) says *layout* instead of *differs*: its
printed values belong to a geometry nobody can see. A preset whose figure was
reconstructed by fitting (``[fit]``) marks the values it was fitted to: the others are
predictions, and only they test the reconstruction. Where a preset writes down the
book's own miscalculation of a value (``[book_slips]``: the formula the book used, e.g. a_D
divided by DC where ε needs the tangential part), that formula is evaluated on the exact
values: a printed value it reproduces is a *slip* — the layout is right, the book's
arithmetic is not.
"""

from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal

from mechanisms.formula import evaluate

from .values import exact_values

CLOSE = 0.03
CLOSE_ANGLE = 2.0  # degrees
PRECISION = 0.02  # the book reads plans to about 2 %: a fit that misses by more reconstructs nothing


@dataclass(frozen=True)
class BookRow:
    key: str  # e.g. "members.4.omega"
    book: float
    exact: float | None  # None when the scene does not produce that value
    verdict: str  # "agrees", "close", "slip", "differs", "layout" or "missing"
    note: str = ""
    note_sr: str = ""  # the note in Serbian (Latin, notation in ⟨⟩)
    # with a fitted figure: "fitted" (the fit was made to it), "chose" (it picked the layout
    # among equal fits) or "predicted" (a test of the reconstruction); "" without a fit
    role: str = ""
    slip: float | None = None  # the book's own formula ([book_slips]) on the exact values

    @property
    def difference(self) -> float | None:
        return None if self.exact is None else self.book - self.exact


def printed_unit(value: float) -> float:
    """One unit of the last digit as printed: 8.148 → 0.001, 118.0 → 1."""
    exponent = Decimal(repr(value)).normalize().as_tuple().exponent
    return 10.0 ** min(int(exponent), 0)


def verdict(key: str, book: float, exact: float) -> str:
    diff = book - exact
    angle = key.endswith("angle_deg")
    if angle:
        diff = (diff + 180.0) % 360.0 - 180.0
    if abs(diff) <= printed_unit(book) * 1.000001:
        return "agrees"
    limit = CLOSE_ANGLE if angle else CLOSE * max(abs(exact), 1e-12)
    return "close" if abs(diff) <= limit else "differs"


def check(scene) -> list[BookRow]:
    """Every printed value of the preset against the exact solution of its data."""
    exact = exact_values(scene)
    notes, notes_sr = getattr(scene, "book_notes", {}), getattr(scene, "book_notes_sr", {})
    fit = getattr(scene, "fit", None)
    slips = getattr(scene, "book_slips", {})
    rows = []
    for key, book in scene.book.items():
        value = exact.get(key)
        found = "missing" if value is None else verdict(key, book, value)
        slip = evaluate(slips[key], exact) if key in slips else None
        if found == "differs" and slip is not None and verdict(key, book, slip) != "differs":
            found = "slip"
        unfitted = fit is not None and fit.residual > PRECISION
        if found == "differs" and (getattr(scene, "layout_assumed", False) or unfitted):
            found = "layout"
        rows.append(BookRow(key, book, value, found, notes.get(key, ""), notes_sr.get(key, ""),
                            _role(fit, key), slip))
    return rows


def _role(fit, key: str) -> str:
    if fit is None:
        return ""
    return "fitted" if key in fit.used else "chose" if key in fit.chose else "predicted"
