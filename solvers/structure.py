"""Structural analysis: degrees of freedom and decomposition into the driver and Assur groups.

The course builds a mechanism from the frame and the driving member by adding Assur
groups (structural groups with zero mobility). Solving follows the same order, so the
decomposition found here is also the solving order of the kinematics core.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

from mechanisms.messages import Joined, Text
from mechanisms.schema import DRIVER, FRAME, Pair, Scene

from .budget import bounded, check

DYAD_KINDS = ("RRR", "RRP", "RPR", "PRP", "RPP")
ROMAN = {1: "I", 2: "II", 3: "III", 4: "IV"}


class StructureError(ValueError):
    """The scene's structure cannot be solved; the message says why."""


@dataclass(frozen=True)
class Group:
    """An Assur group: its members and pairs in solving (loop) order.

    For a class II dyad ``members = (j, k)`` and ``pairs = (outer_j, inner, outer_k)``,
    oriented so that ``kind`` reads as the course names it (RRR, RRP, RPR, PRP, RPP).
    """

    members: tuple[int, ...]
    pairs: tuple[Pair, ...]
    kind: str
    cls: int
    order: int

    @property
    def name(self) -> str:
        return "-".join(str(m) for m in sorted(self.members))

    @property
    def attached_to(self) -> set[int]:
        """The already-known members this group hangs on."""
        own = set(self.members)
        return {m for p in self.pairs for m in p.members if m not in own}

    def label(self) -> str:
        return f"{ROMAN[self.cls]}({','.join(str(m) for m in sorted(self.members))})"


@dataclass(frozen=True)
class Structure:
    moving_members: int
    lower_pairs: int
    higher_pairs: int
    dof: int
    driver: Pair
    groups: tuple[Group, ...]

    @property
    def formula(self) -> str:
        """The structural formula, e.g. ``I(1,2) → II(3,4) → II(5,6)``."""
        return " → ".join([f"I({FRAME},{DRIVER})"] + [g.label() for g in self.groups])

    def groups_for(self, members: set[int]) -> tuple[Group, ...]:
        """The groups (in solving order) needed to know the given members."""
        needed: set[str] = set()
        wanted = set(members)
        for group in reversed(self.groups):
            if wanted & set(group.members):
                needed.add(group.name)
                wanted |= group.attached_to
        return tuple(g for g in self.groups if g.name in needed)


def degrees_of_freedom(scene: Scene) -> int:
    """W = 3n − 2p₅ − p₄ (n moving members, p₅ lower pairs, p₄ higher pairs)."""
    return 3 * len(scene.members) - 2 * len(scene.pairs)


@bounded
def decompose(scene: Scene) -> Structure:
    """Find the driver and the Assur groups in solving order, or explain why not."""
    dof = degrees_of_freedom(scene)
    driver = scene.pair(scene.driver.pair)
    if dof != 1:
        raise StructureError(_dof_message(scene, dof))
    known = {FRAME, DRIVER}
    extra = [p for p in scene.pairs if set(p.members) <= known and p is not driver]
    if extra:
        raise StructureError(Text("structure.driver_twice", first=driver.name, second=extra[0].name))
    remaining = set(scene.members) - known
    groups = []
    while remaining:
        group = _find_dyad(scene, known, remaining) or _find_triad(scene, known, remaining)
        if group is None:
            raise StructureError(_stuck_message(scene, known, remaining))
        groups.append(group)
        known |= set(group.members)
        remaining -= set(group.members)
    return Structure(len(scene.members), len(scene.pairs), 0, dof, driver, tuple(groups))


def _pairs_between(scene: Scene, a: set[int], b: set[int]) -> list[Pair]:
    return [p for p in scene.pairs
            if (p.members[0] in a and p.members[1] in b) or (p.members[1] in a and p.members[0] in b)]


def _find_dyad(scene: Scene, known: set[int], remaining: set[int]) -> Group | None:
    for j, k in combinations(sorted(remaining), 2):
        inner = _pairs_between(scene, {j}, {k})
        outer_j = _pairs_between(scene, {j}, known)
        outer_k = _pairs_between(scene, {k}, known)
        if len(inner) == len(outer_j) == len(outer_k) == 1:
            pairs = (outer_j[0], inner[0], outer_k[0])
            kind = "".join(p.letter for p in pairs)
            if kind not in DYAD_KINDS:
                j, k, pairs, kind = k, j, pairs[::-1], kind[::-1]
            if kind not in DYAD_KINDS:
                raise StructureError(Text("structure.only_prismatic", first=j, second=k, kind=kind))
            return Group((j, k), pairs, kind, cls=2, order=2)
    return None


def _find_triad(scene: Scene, known: set[int], remaining: set[int]) -> Group | None:
    """A class III group: a ternary member joined to three binary members (6 pairs).

    Members are ``(ternary, *binaries)``; pairs go leg by leg, ``(outer, inner)`` for each
    binary member; ``kind`` reads the legs the same way, e.g. ``RR-RR-PR`` (a slider on a
    fixed guide as the third leg).
    """
    for tried, quad in enumerate(combinations(sorted(remaining), 4)):
        if tried % 512 == 0:
            check()
        members = set(quad)
        if len(_pairs_between(scene, members, members | known)) != 6:
            continue
        inner = _pairs_between(scene, members, members)
        degree = {m: sum(m in p.members for p in inner) for m in quad}
        centre = max(quad, key=degree.get)
        binaries = sorted(members - {centre})
        if degree[centre] != 3 or any(degree[m] != 1 for m in binaries):
            continue
        legs = [(_pairs_between(scene, {b}, known), _pairs_between(scene, {b}, {centre}))
                for b in binaries]
        if any(len(outer) != 1 or len(mid) != 1 for outer, mid in legs):
            continue
        pairs = tuple(p for outer, mid in legs for p in (outer[0], mid[0]))
        kind = "-".join(outer[0].letter + mid[0].letter for outer, mid in legs)
        return Group((centre, *binaries), pairs, kind, 3, order=3)
    return None


def _dof_message(scene: Scene, dof: int) -> Text:
    n, p = len(scene.members), len(scene.pairs)
    if dof > 1:
        return Text("structure.free", n=n, p=p, dof=dof, free=dof - 1, loose=_loose(scene))
    return Text("structure.locked", n=n, p=p, dof=dof, extra=1 - dof, loose=_loose(scene))


def _loose(scene: Scene) -> Text:
    counts = {m: sum(m in p.members for p in scene.pairs) for m in scene.members}
    single = [str(m) for m, c in counts.items() if c < 2 and m != DRIVER]
    if single:
        return Text("structure.single_pair", members=", ".join(single))
    return Text("structure.pairs_per_member",
                counts=", ".join(f"{m}: {c}" for m, c in counts.items()))


def _stuck_message(scene: Scene, known: set[int], remaining: set[int]) -> Text:
    details = [Text("structure.member_pairs", member=m,
                    solved=len(_pairs_between(scene, {m}, known)),
                    unsolved=len(_pairs_between(scene, {m}, remaining - {m})))
               for m in sorted(remaining)]
    return Text("structure.stuck", known=", ".join(map(str, sorted(known))),
                remaining=", ".join(map(str, sorted(remaining))),
                details=Joined(details),
                hint=Text("structure.higher_class") if len(remaining) >= 4 else "")


def loose_joints(scene: Scene) -> list[tuple[str, int]]:
    """Joints left unconnected while building: (point, member) for each end of a member's
    axis, and each frame point, that no pair uses (a guide's ``through`` point counts).
    Extra points of a member (a coupler point) are meant to be free and are not listed."""
    used = {(p.point, m) for p in scene.pairs for m in p.members}
    used |= {(p.through, p.members[0]) for p in scene.pairs if p.kind == "prismatic"}
    ends = [(name, FRAME) for name in scene.frame]
    ends += [(name, n) for n, m in scene.members.items() for name in m.axis]
    return [(name, member) for name, member in ends if (name, member) not in used]
