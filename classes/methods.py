"""What a class can practise: each method with the page that practises it. One table that
every surface reads — the store's methods, the lecturer's form, a student's seat and link,
LTI's picker and the command line — where five had kept their own (a method added to one
and not another opened no page, or the wrong panel)."""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Method:
    page: str  # the page that practises it (its URL path)
    panel: str  # the key of its practice panel on that page
    scenes: str  # the presets a lecturer picks from: "linkage", "gears" or "rotor"
    sheet: str = ""  # the string of its printable sheet's title ("": none)
    drawable: bool = False  # its steps are drawn on the page's plan
    link: dict[str, str] = field(default_factory=dict)  # what its link adds to the page's


METHODS: dict[str, Method] = {
    "compass": Method("trajectories", "pr_compass", "linkage", "practice.sheet_compass", True,
                      {"view": "compass"}),
    "plans": Method("velocity_plans", "pr_plans", "linkage", "practice.sheet_plans", True),
    "forces": Method("kinetostatics", "pr_forces", "linkage", "practice.sheet_forces", True),
    "lever": Method("kinetostatics", "pr_lever", "linkage"),
    "willis": Method("planetary_gears", "pr_willis", "gears"),
    "balance": Method("rotor_balancing", "pr_balance", "rotor", "practice.sheet_rotor", True),
}
