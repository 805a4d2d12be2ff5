"""Write a scene back to TOML (the download of the current scene, with the user's changes).

The output uses the same format the loader reads (docs/scene-format.md), so a downloaded
scene uploads again unchanged.

Written by hand rather than with a TOML library (tomli-w 1.2 was tried): a library writes
every array of tables as ``[[pairs]]`` blocks and cannot keep one pair per line before the
first table, the layout the presets, the documentation and a student reading the file
share; and scene links (mechanisms/link.py) deflate this layout with a fixed dictionary,
so changing it would lengthen every link. Strings go through ``json.dumps`` (a JSON string
is a valid TOML basic string), numbers through ``repr``.
"""

from __future__ import annotations

import json
import math

from .gears import GearTrain
from .rotor import Rotor
from .point_forms import written
from .schema import Member, Scene


def _s(text: str) -> str:
    return json.dumps(text, ensure_ascii=False)  # a JSON string is a valid TOML basic string


def _n(value: float) -> str:
    return repr(float(value))


def _v(z: complex) -> str:
    return f"[{_n(z.real)}, {_n(z.imag)}]"


def _point(member: Member, name: str, z: complex) -> str:
    """An extra point in the form its author gave it (mechanisms.point_forms)."""
    form = member.forms.get(name, "offset")
    value = written(form, z, member.length) if form != "offset" else None
    if isinstance(value, dict) and "distances" in value:
        d1, d2 = value["distances"]
        return f"{{ distances = [{_n(d1)}, {_n(d2)}], side = {_s(value['side'])} }}"
    if isinstance(value, dict):
        r, angle = value["polar"]
        return f"{{ polar = [{_n(r)}, {_n(angle)}] }}"
    return _v(z)


def _identity(scene) -> list[str]:
    """The top-level keys every kind of scene shares."""
    out = [f"id = {_s(scene.id)}", f"title = {_s(scene.title)}", f"title_sr = {_s(scene.title_sr)}",
           f"source = {_s(scene.source)}", f"note = {_s(scene.note)}"]
    out += [f"{key} = {_s(getattr(scene, key))}" for key in ("source_sr", "note_sr")
            if getattr(scene, key)]
    return out


def to_toml(scene: Scene) -> str:
    out = _identity(scene)
    if scene.layout_assumed:
        out.append("layout_assumed = true")
    if scene.gravity:
        out.append(f"gravity = {_n(scene.gravity)}")
    if not scene.inertia:
        out.append("inertia = false")
    out.append("\npairs = [")
    for p in scene.pairs:
        if p.on_slot:
            out.append(f'  {{ type = "circular", guide = {p.members[0]}, slider = {p.members[1]}, '
                       f'point = {_s(p.on_slot)}, centre = {_s(p.point)}, name = {_s(p.name)} }},')
        elif p.kind == "revolute":
            out.append(f'  {{ type = "revolute", members = [{p.members[0]}, {p.members[1]}], '
                       f'point = {_s(p.point)}, name = {_s(p.name)} }},')
        else:
            out.append(f'  {{ type = "prismatic", guide = {p.members[0]}, slider = {p.members[1]}, '
                       f'point = {_s(p.point)}, through = {_s(p.through)}, '
                       f'angle = {_n(math.degrees(p.angle))}, '
                       f'slider_angle = {_n(math.degrees(p.slider_angle))}, name = {_s(p.name)} }},')
    out.append("]\n\n[frame]")
    out += [f"{name} = {_v(z)}" for name, z in scene.frame.items()]
    d = scene.driver
    out.append(f'\n[driver]\ntype = "{d.kind}"')
    if d.kind == "rotating":
        out += [f"at = {_n(math.degrees(d.at))}", f"omega = {_n(d.speed)}", f"epsilon = {_n(d.accel)}"]
    else:
        out += [f"at = {_n(d.at)}", f"velocity = {_n(d.speed)}", f"acceleration = {_n(d.accel)}"]
    if scene.travel:
        tr = scene.travel
        out += ["\n[travel]", f"speed = {_n(tr.speed)}", f"wheel_radius = {_n(tr.wheel_radius)}",
                f"sprocket_wheel = {_n(tr.sprocket_wheel)}",
                f"sprocket_crank = {_n(tr.sprocket_crank)}", f"angle = {_n(math.degrees(tr.angle))}"]
    for number, m in scene.members.items():
        out.append(f"\n[members.{number}]")
        if m.label:
            out.append(f"label = {_s(m.label)}")
        out.append("points = [" + ", ".join(_s(p) for p in m.axis) + "]")
        if m.length is not None:
            out.append(f"length = {_n(m.length)}")
        extra = [f"{name} = {_point(m, name, z)}" for name, z in m.points.items()
                 if name not in m.axis]
        if extra:
            out.append("extra = { " + ", ".join(extra) + " }")
        if m.mass:
            out.append(f"mass = {_n(m.mass)}")
        if m.centre is not None:
            out.append(f"centre = {_v(m.centre)}")
        if m.gyration:
            out.append(f"gyration = {_n(m.gyration)}")
    if scene.assembly:
        out.append("\n[assembly]")
        out += [f'"{a}-{b}" = {sign}' for (a, b), sign in scene.assembly.items()]
    for f in scene.forces:
        out += ["\n[[forces]]", f"member = {f.member}", f"point = {_s(f.point)}",
                f"magnitude = {_n(f.magnitude)}", f"angle = {_n(math.degrees(f.angle))}",
                f"follows_member = {'true' if f.follows_member else 'false'}"]
        if f.label:
            out.append(f"label = {_s(f.label)}")
    for m in scene.moments:
        out += ["\n[[moments]]", f"member = {m.member}", f"value = {_n(m.value)}"]
    if scene.scales:
        out.append("\n[scales]")
        out += [f"{k} = {_n(v)}" for k, v in scene.scales.items()]
    if scene.guess:
        out.append("\n[guess]")
        out += [f"{_s(k)} = {_v(z)}" for k, z in scene.guess.items()]
    if scene.special:
        out.append("\n[special]")
        out += [f"{_s(k)} = [{a}, {b}]" for k, (a, b) in scene.special.items()]
    if scene.fit:
        f = scene.fit
        out += ["\n[fit]", "unknowns = [" + ", ".join(map(_s, f.unknowns)) + "]",
                "start = [" + ", ".join(map(_n, f.start)) + "]",
                "used = [" + ", ".join(map(_s, f.used)) + "]", f"residual = {_n(f.residual)}"]
        if f.chose:
            out.append("chose = [" + ", ".join(map(_s, f.chose)) + "]")
    out += _book(scene.book, scene.book_notes, scene.book_notes_sr)
    if scene.book_slips:
        out.append("\n[book_slips]")
        out += [f"{_s(k)} = {_s(v)}" for k, v in scene.book_slips.items()]
    return "\n".join(out) + "\n"


def _book(book: dict[str, float], notes: dict[str, str], notes_sr: dict[str, str]) -> list[str]:
    out = []
    if book:
        out.append("\n[book]")
        out += [f"{_s(k)} = {_n(v)}" for k, v in book.items()]
    for name, table in (("book_notes", notes), ("book_notes_sr", notes_sr)):
        if table:
            out.append(f"\n[{name}]")
            out += [f"{_s(k)} = {_s(v)}" for k, v in table.items()]
    return out


def rotor_to_toml(rotor: Rotor) -> str:
    out = ['kind = "rotor"', *_identity(rotor), f'mode = "{rotor.mode}"']
    if rotor.omega is not None:
        out.append(f"omega = {_n(rotor.omega)}")
    out.append("\n[planes]")
    out += [f"{plane} = {_n(x)}" for plane, x in rotor.planes.items()]
    for m in rotor.masses:
        out += ["\n[[masses]]", f"mass = {_n(m.mass)}", f"radius = {_n(m.radius)}",
                f"angle = {_n(math.degrees(m.angle))}", f"x = {_n(m.x)}"]
    for plane, c in rotor.corrections.items():
        out.append(f"\n[corrections.{plane}]")
        for q in ("mass", "radius", "angle"):
            value = getattr(c, q)
            if value is not None:
                out.append(f"{q} = {_n(math.degrees(value) if q == 'angle' else value)}")
    if rotor.bearings:
        out.append("\n[bearings]")
        out += [f"{k} = {_n(v)}" for k, v in rotor.bearings.items()]
    out += _book(rotor.book, rotor.book_notes, rotor.book_notes_sr)
    return "\n".join(out) + "\n"


def gears_to_toml(train: GearTrain) -> str:
    out = ['kind = "gears"', *_identity(train), "", "meshes = ["]
    for m in train.meshes:
        ring = f", internal = {m.internal}" if m.internal is not None else ""
        bevel = ", bevel = true" if m.bevel else ""
        out.append(f"  {{ members = [{m.members[0]}, {m.members[1]}], "
                   f"radii = [{_n(m.radii[0])}, {_n(m.radii[1])}]{ring}{bevel} }},")
    out.append("]")
    out.append("shafts = [" + ", ".join("[" + ", ".join(map(str, s)) + "]" for s in train.shafts) + "]")
    out.append("fixed = [" + ", ".join(map(str, train.fixed)) + "]")
    out.append("inputs = [")
    for i in train.inputs:
        if i.velocity is None:
            out.append(f"  {{ member = {i.member}, omega = {_n(i.omega)} }},")
        else:
            out.append(f"  {{ member = {i.member}, velocity = {_n(i.velocity)}, "
                       f"radius = {_n(i.radius)} }},")
    out.append("]")
    for n, m in train.members.items():
        out.append(f"\n[members.{n}]")
        if m.label:
            out.append(f"label = {_s(m.label)}")
        if m.carrier is not None:
            out.append(f"carrier = {m.carrier}")
        if m.axis:
            out.append(f"axis = {_n(m.axis)}")
        if m.x is not None:
            out.append(f"x = {_n(m.x)}")
    if train.points:
        out.append("\n[points]")
        out += [f"{name} = [{m}, {_n(r)}]" for name, (m, r) in train.points.items()]
    out += _book(train.book, train.book_notes, train.book_notes_sr)
    return "\n".join(out) + "\n"


def to_text(scene: Scene | Rotor | GearTrain) -> str:
    """The TOML text of a scene of any kind (what a download, an upload and a link share)."""
    writer = {Rotor: rotor_to_toml, GearTrain: gears_to_toml}.get(type(scene), to_toml)
    return writer(scene)
