"""A set of variants as a Moodle question bank (Moodle XML), each wrong answer a student
usually gives answered with the app's own diagnosis.

One *cloze* (embedded answers) question per variant, not one numerical question per asked
value: a variant is one exercise — its given numbers, its drawing, several asked values that
build on one another — and Moodle's quiz draws one question at random from a category, so
"a random question from this category" hands each student one whole variant. A numerical
question holds one number; a variant split into several would be drawn apart.

Each asked value is a NUMERICAL part whose answers come, in order, from the one judge
(``methods.judge``, the practice grader of a scalar step): the key (100 %, the judge's
tolerance as Moodle's absolute tolerance), then the usual mistakes in the order the judge
tries them — a term left out, the sign reversed, a power of ten — each 0 % with the hint
practice gives for it, then 0 (no size: "go back to the equation"), the right sign but
another size (up to 10⁹ times the key), and last a catch-all. Moodle takes the first answer whose
[value − tolerance, value + tolerance] holds the response, as the grader takes the first
diagnosis that fits, so the same response gets the same words in both.

Numbers in the XML keep a decimal point (Moodle's format); the words follow the language.
Written against what Moodle's importer reads, in moodle/moodle at commit 00055ef6abc8:
``question/format/xml/format.php`` (``import_multianswer``: ``name/text``, ``questiontext``
with its ``file name path encoding="base64"`` elements, ``generalfeedback``, ``penalty``;
the category question's ``category/text``) and the cloze syntax of
``question/type/multianswer/questiontype.php`` (``NUMBER_REGEX``: a point or comma, an
optional exponent; a part's feedback after ``#``, with ``}``, ``~``, ``#``, ``/``, ``"`` and the
backslash itself escaped by a backslash).
"""

from __future__ import annotations

import base64
import html
import math
from collections.abc import Callable
from dataclasses import dataclass
from xml.sax.saxutils import escape

from exams.sheets import drawing_svg, length_scale
from exams.judged import judged_steps
from exams.variants import Answer, Variant, VariantSet, symbol
from figures.balancing import end_view_figure, side_view_figure
from figures.gears import schematic_figure
from figures.svg import figure_svg
from mechanisms.gears import GearTrain
from mechanisms.messages import Text
from mechanisms.rotor import Rotor
from methods.practice import TURNS, Step, Verdict, hint_texts, scalar_mistakes
from solvers.balancing import unit

WIDE = 1e9  # "the right sign, another size": up to this many times the key (wider, and a float
# no longer tells a small response on the other side of 0 from the interval's edge)
WORDS = {
    "en": {"category": "Variants of {task} (seed {seed}, ± {spread} %)", "variant": "Variant",
           "given": "Given", "find": "Find", "code": "Code",
           "decimal": "Write a decimal with a point: 3.8266 (this Moodle's English reads a "
                      "comma as a thousands separator).",
           "drawing": "The mechanism at the asked instant, drawn at U_L = {u} m/cm",
           "end_view": "The rotor seen along its axis: each mass's radius r at its angle φ "
                       "from the z axis, counter-clockwise (mm)",
           "side_view": "The rotor from the side: the masses at their axial positions x and "
                        "the correction planes I and II (mm; not to one scale across)",
           "train": "The train in half-section: each gear's pitch radius about its axis, "
                    "carriers as arms (m)"},
    "sr": {"category": "Varijante zadatka {task} (seme {seed}, ± {spread} %)",
           "variant": "Varijanta", "given": "Dato", "find": "Odrediti", "code": "Kod",
           "decimal": "Decimalni broj pišite zarezom, 3,8266, ako je Moodle na srpskom; ako je "
                      "na engleskom, tačkom, 3.8266 (zarez bi tamo odvajao hiljade).",
           "drawing": "Mehanizam u traženom položaju, nacrtan u razmeri U_L = {u} m/cm",
           "end_view": "Rotor gledan duž ose: poluprečnik r svake mase pod njenim uglom φ od "
                       "ose z, suprotno kretanju kazaljke na satu (mm)",
           "side_view": "Rotor sa strane: mase na svojim položajima x duž ose i ravni korekcije "
                        "I i II (mm; popreko nije u istoj razmeri)",
           "train": "Prenosnik u polupreseku: podeoni poluprečnik svakog zupčanika oko njegove "
                    "ose, nosači kao krakovi (m)"},
}


@dataclass(frozen=True)
class Choice:
    """One answer of a NUMERICAL part: responses within ``tolerance`` of ``value`` (any
    response when ``value`` is None) get ``fraction`` % and the hint of ``diagnosis``."""

    diagnosis: str
    value: float | None
    tolerance: float
    fraction: int
    hint: tuple[Text, ...]


def asked_steps(variant: Variant) -> list[tuple[Answer, Step]]:
    """Each asked value of the variant as the judge's step (exams.judged: the one table)."""
    return [(answer, step) for answer, step in judged_steps(variant.scene, variant.key)
            if answer.asked]


def choices(step: Step) -> list[Choice]:
    """The answers of one asked value, in the order Moodle must try them."""
    exact = float(step.expected)
    out = [Choice("ok", exact, step.tolerance, 100, _hint(step, Verdict("ok")))]
    if step.unit == "°":  # a direction a whole turn away is the same (methods.practice)
        out += [Choice("ok", exact + 360.0 * k, step.tolerance, 100, _hint(step, Verdict("ok")))
                for n in range(1, TURNS + 1) for k in (-n, n)]
    out += [Choice(m.diagnosis, m.value, m.width, 0,
                   _hint(step, Verdict(m.diagnosis, ratio=m.ratio, term=m.term, unit=m.unit)))
            for m in scalar_mistakes(step)]
    if abs(exact) > step.tolerance and step.unit != "°":  # the right sign, another size: (0, WIDE·|x|] on its side
        out.append(Choice("wrong", 0.0, 0.0, 0, _hint(step, Verdict("wrong"))))  # (0 is no size)
        half = math.copysign(WIDE * abs(exact) / 2, exact)
        out.append(Choice("length", half, abs(half), 0, _hint(step, Verdict("length"))))
    out.append(Choice("wrong", None, 0.0, 0, _hint(step, Verdict("wrong"))))
    return out


def _hint(step: Step, verdict: Verdict) -> tuple[Text, ...]:
    """Practice's hint for the verdict, in the same words (methods.practice.hint_texts)."""
    return hint_texts(step, verdict)


def matching(parts: list[Choice], response: float) -> Choice | None:
    """Moodle's rule: the first answer whose interval holds the response (the catch-all
    holds any)."""
    for choice in parts:
        if choice.value is None or abs(response - choice.value) <= choice.tolerance:
            return choice
    return None


def moodle_xml(found: VariantSet, title: str, language: str,
               lookup: Callable[[str], str]) -> str:
    """The set as one Moodle XML file: a category named by task, seed and spread, then one
    cloze question per variant. ``lookup(key)`` gives a string of ``locales/`` in the
    language (the hints); ``language`` "sr" writes the given numbers with a decimal comma."""
    s = found.settings
    w = WORDS["sr" if language.startswith("sr") else "en"]
    category = w["category"].format(task=s.task, seed=s.seed, spread=s.spread)
    out = ['<?xml version="1.0" encoding="UTF-8"?>', "<quiz>",
           '  <question type="category">',
           f"    <category><text>$course$/top/{escape(category)}</text></category>",
           f'    <info format="html"><text>{escape(category)}</text></info>',
           "  </question>"]
    for variant in found.variants:
        out += _question(variant, title, language, w, lookup)
    out.append("</quiz>")
    return "\n".join(out) + "\n"


def _question(variant: Variant, title: str, language: str, w: dict,
              lookup: Callable[[str], str]) -> list[str]:
    comma = language.startswith("sr")
    text = [f"<p><strong>{_h(title)}</strong> — {_h(w['variant'])} {variant.index}, "
            f"{_h(w['code'])} <code>{_h(variant.code)}</code></p>",
            f"<p><strong>{_h(w['given'])}</strong></p><ul>"]
    text += [f"<li>{_h(g.label)} = {_h(_number(value, comma))} {_h(g.unit)}</li>"
             for g, value in variant.given]
    text.append("</ul>")
    files = []
    for name, svg, caption in pictures(variant, w, comma, lookup):
        text.append(f"<p>{_h(caption)}</p>"
                    f'<p><img src="@@PLUGINFILE@@/{name}" alt="{_h(caption)}"></p>')
        files.append(f'<file name="{name}" path="/" encoding="base64">'
                     f"{base64.b64encode(svg.encode('utf-8')).decode('ascii')}</file>")
    text.append(f"<p><strong>{_h(w['find'])}</strong> <em>{_h(w['decimal'])}</em></p><ul>")
    for answer, step in asked_steps(variant):
        text.append(f"<li>{_h(symbol(answer.key))} = {_cloze(choices(step), lookup, comma)} "
                    f"{_h(answer.unit)}</li>")
    text.append("</ul>")
    body = "".join(text).replace("]]>", "]]]]><![CDATA[>")
    return ['  <question type="cloze">',
            f"    <name><text>{escape(variant.code)}</text></name>",
            f'    <questiontext format="html"><text><![CDATA[{body}]]></text>{"".join(files)}'
            "</questiontext>",
            '    <generalfeedback format="html"><text></text></generalfeedback>',
            "    <penalty>0.3333333</penalty>", "    <hidden>0</hidden>",
            f"    <idnumber>{escape(variant.code)}</idnumber>",
            "  </question>"]


def pictures(variant: Variant, w: dict, comma: bool,
             lookup: Callable[[str], str]) -> list[tuple[str, str, str]]:
    """The variant's drawings as (file name, SVG, caption), as its page draws them: a
    linkage at its instant to U_L; a rotor seen along its axis and from the side (its
    masses only: the corrections are asked); a gear train in half-section."""
    def t(key: str, **values) -> str:  # figures' translator, from the file's language
        return lookup(key).format(**values)

    scene = variant.scene
    if variant.drawn:
        scale = length_scale(scene, variant.drawn)
        return [(f"{variant.code}.svg", drawing_svg(scene, variant.drawn, scale),
                 w["drawing"].format(u=_number(scale, comma)))]
    if isinstance(scene, Rotor):
        masses = [(f"m{i + 1}", m.radius * unit(m.angle), m.x) for i, m in enumerate(scene.masses)]
        end = end_view_figure([(n, v) for n, v, _ in masses], [], "", t)
        side = side_view_figure(masses, scene.planes, t)
        return [(f"{variant.code}-end.svg", figure_svg(end, 9.0, axes=True), w["end_view"]),
                (f"{variant.code}-side.svg", figure_svg(side, 14.0, height=6.0), w["side_view"])]
    if isinstance(scene, GearTrain):
        return [(f"{variant.code}.svg", figure_svg(schematic_figure(scene, "", t), 12.0),
                 w["train"])]
    return []


def _cloze(parts: list[Choice], lookup: Callable[[str], str], comma: bool) -> str:
    """One NUMERICAL part in Moodle's cloze syntax: {1:NUMERICAL:=x:tol#…~%0%y:tol#…~%0%*#…}."""
    answers = []
    for choice in parts:
        hint = " ".join(t.render(lambda k: _plain(lookup(k)), comma) for t in choice.hint)
        fraction = "=" if choice.fraction == 100 else f"%{choice.fraction}%"
        value = "*" if choice.value is None else f"{choice.value!r}:{choice.tolerance!r}"
        answers.append(f"{fraction}{value}#{_cloze_text(hint)}")
    return "{1:NUMERICAL:" + "~".join(answers) + "}"


def _plain(text: str) -> str:
    return text.replace("⟨", "").replace("⟩", "")


def _cloze_text(text: str) -> str:
    """A feedback inside a cloze part: HTML-escaped, and Moodle's cloze marks escaped."""
    text = _h(text)
    for mark in ("\\", "}", "#", "~", "/", '"'):
        text = text.replace(mark, "\\" + mark)
    return text


def _h(text) -> str:
    return html.escape(_plain(str(text)))


def _number(value: float, comma: bool) -> str:
    text = f"{value:.6g}"
    return text.replace(".", ",") if comma else text

