"""The strings tables: every key in every language, none unused, notation kept in Latin."""

import re
from pathlib import Path

import pytest

from mechanisms import load_preset, preset_ids
from ui.i18n import LANGUAGES, member_labels, num, t, table

ROOT = Path(__file__).resolve().parents[1]
SOURCES = [ROOT / "app.py", *ROOT.glob("pages/*.py"), *ROOT.glob("ui/*.py"), *ROOT.glob("figures/*.py"),
           ROOT / "methods" / "practice.py",  # (practice's hints, shared with the command line)
           *ROOT.glob("mechanisms/*.py"), *ROOT.glob("solvers/*.py"), *ROOT.glob("exams/*.py"),
           *ROOT.glob("classes/*.py"), *ROOT.glob("lti/*.py"),
           ROOT / "methods" / "plans.py", ROOT / "methods" / "three_positions.py",
           ROOT / "reports" / "fitting.py"]  # (their messages)


def message_families() -> set[str]:
    """The messages' keys made from a name (``Text(f"why_open.{kind}")``): each family from
    the table in the code that names its members."""
    from classes.store import METHODS
    from mechanisms import limits
    from mechanisms.loader import TOML_REASONS
    from methods.practice import DIAGNOSES
    from solvers.diagnostics import WHY_OPEN
    from ui.numbers import REASONS
    gears = (ROOT / "mechanisms" / "gears.py").read_text()
    return ({f"scene.lists.{what}" for _, what, _ in (*limits.LINKAGE, *limits.GEARS,
                                                      *limits.ROTOR, ("", "book", 0))}
            | {f"scene.array.{what}" for what in re.findall(
                r'_array\((?:[^()]|\([^()]*\))*?"(\w+)"\)', gears)}
            | {f"why_open.{kind}" for kind in (*WHY_OPEN, "other")}
            | {f"num.{reason}" for reason in REASONS}
            | {f"class.method_{method}" for method in METHODS}
            | {f"class.diagnosis_{d}" for d in DIAGNOSES}
            | {f"class.mistake_{d}" for d in DIAGNOSES if d not in ("ok", "none")}
            | {f"toml.{key}" for key in (*TOML_REASONS.values(), "other")})


def used_keys() -> set[str]:
    """Every quoted string in the app's code that looks like a key ("area.name"), the rules
    a scene's reader fails with (``r.fail(key, "missing")`` is ``scene.missing``), and the
    messages' families."""
    text = "\n".join(p.read_text() for p in SOURCES)
    keys = set(re.findall(r"""["']([a-z][a-z0-9_]*\.[A-Za-z0-9_.]+)["']""", text))
    rules = {f"scene.{rule}" for rule in re.findall(r'fail\([^()]*?, "(\w+)"', text)}
    places = set(re.findall(r'fail\("([^"]+)"', text))  # a scene file's keys: "driver.type"
    files = {k for k in keys if k.endswith((".py", ".toml", ".js", ".json", ".db"))}
    results = {k for k in keys if k.split(".")[0] in RESULT_HEADS}  # a result's key, not a message's
    return (keys - places - files - results - LIBRARY_NAMES) | rules | message_families()


# ASGI's message type, Streamlit's option, LTI's claims as a refusal names them
LIBRARY_NAMES = {"http.request", "server.address", "context.id", "resource_link.id"}

# the heads of a result's key (reports.values: "driving.torque", "members.3.omega"), which no
# message key shares
RESULT_HEADS = ("driving", "members", "points", "reactions", "sliders", "corrections", "travel")


def test_every_language_has_the_same_keys():
    keys = set(table("en"))
    for language in LANGUAGES:
        assert set(table(language)) == keys, language


def test_every_key_is_used_and_every_used_key_exists():
    keys, used = set(table("en")), used_keys()
    assert not used - keys, f"missing in the tables: {sorted(used - keys)}"
    assert not keys - used, f"unused keys: {sorted(keys - used)}"


def test_placeholders_agree_across_languages():
    for key, english in table("en").items():
        wanted = set(re.findall(r"\{(\w+)\}", english))
        for language in LANGUAGES:
            assert set(re.findall(r"\{(\w+)\}", table(language)[key])) == wanted, (language, key)


def test_cyrillic_is_transliterated_but_notation_and_units_stay_latin():
    text = t("traj.R_b", language="sr-cyrl")
    assert "R_b" in text and "[m]" in text and "лан" in text  # lančanik → ланчаник
    assert t("traj.length", language="sr-cyrl", link="AB", member=3).startswith("AB (члан 3)")


def test_numbers_use_the_languages_decimal_separator():
    assert num(0.25, language="sr") == "0,25" and num(0.25, language="en") == "0.25"


def test_roman_numerals_and_single_letters_stay_latin_in_cyrillic():
    """A class or plane number (III, II) must not turn into ИИИ."""
    for key, text in table("sr").items():
        for word in re.findall(r"[^\s⟨⟩{}\[\]()]+", KEEP_OUT.sub("", text)):
            assert not re.fullmatch(r"(I{1,3}|IV|V|VI{1,3})[.,]?", word), (key, word)


KEEP_OUT = re.compile(r"⟨[^⟩]*⟩|\{[^}]*\}|\[[^\]]*\]")


def test_every_preset_has_a_serbian_title_and_cyrillic_keeps_its_notation():
    from mechanisms import load_preset, preset_ids
    from ui.i18n import _to_cyrillic

    for pid in preset_ids():
        scene = load_preset(pid)
        assert scene.title_sr, pid
    cyr = _to_cyrillic(load_preset("zbirka-1.3").title_sr)
    assert "⟨E⟩" in cyr and "Превртач" in cyr


def test_units_in_brackets_hold_no_words():
    """[…] stays Latin in Cyrillic, so it may hold units only, never a Serbian word."""
    for key, text in table("sr").items():
        for inside in re.findall(r"\[([^\]]*)\]", re.sub(r"⟨[^⟩]*⟩", "", text)):
            rest = re.sub(r"\{\w+\}|(?<![A-Za-z])(rad|cm|mm|kg|ms|m|s|N|W)(?![A-Za-z])", "", inside)
            assert not re.search(r"[A-Za-zčćšđžČĆŠĐŽ]", rest), (key, inside)


def test_point_letters_in_serbian_titles_are_marked_as_notation():
    """A bare "CD" in a title would turn into Cyrillic "ЦД"; notation must sit in ⟨…⟩."""
    from mechanisms import load_preset, preset_ids

    for pid in preset_ids():
        title = re.sub(r"⟨[^⟩]*⟩", "", load_preset(pid).title_sr)
        assert not re.search(r"\b[A-Z]{1,4}\d*\b", title), (pid, title)


NOTATION = re.compile(r"[A-Z]{1,4}['′₀-₉0-9]*[.,;:)]?|[A-Za-z]+[₀-₉]+[.,;:)]?")


def test_serbian_preset_texts_keep_their_notation_latin():
    """Every preset has its note and source in Serbian, and the letters of points, members
    and quantities (AB, S₃, m₃) sit in ⟨⟩ so Cyrillic leaves them as the course writes them."""
    for pid in preset_ids():
        scene = load_preset(pid)
        assert scene.note_sr and scene.source_sr, pid
        prose = KEEP_OUT.sub("", scene.note_sr + ". " + scene.title_sr)
        prose = re.sub(r"(^|[.:;]\s+)(U|I|A|O|K|S)\s", r"\1", prose)  # u, i, a, … opening a sentence
        for word in re.findall(r"[^\s⟨⟩(]+", prose):
            assert not NOTATION.fullmatch(word), (pid, word)


def test_every_preset_member_label_has_its_serbian_words():
    """Legends and tables name members by their labels: each preset label is in the labels
    table, with notation in ⟨⟩; an unknown label (an uploaded scene's) stays as written."""
    labels = member_labels("sr")
    for pid in preset_ids():
        for member in getattr(load_preset(pid), "members", {}).values():
            if member.label:
                assert member.label in labels, (pid, member.label)
    for english, serbian in labels.items():
        for word in re.findall(r"[^\s⟨⟩()]+", KEEP_OUT.sub("", serbian)):
            assert not NOTATION.fullmatch(word), (english, word)
    assert t("fig.member", language="sr-cyrl", number=3, member_label="slider C") == "3 клизач C"
    assert t("fig.member", language="sr", number=3, member_label="my part") == "3 my part"
    assert t("fig.member", language="en", number=2, member_label="crank") == "2 crank"


def test_every_book_note_has_its_serbian_note_with_notation_and_decimals_kept():
    """The textbook check's "why" column: each English note of every preset has a Serbian
    one, its notation in ⟨⟩ (Cyrillic keeps it Latin) and its decimals written with a comma."""
    noted = 0
    for pid in preset_ids():
        scene = load_preset(pid)
        notes, serbian = getattr(scene, "book_notes", {}), getattr(scene, "book_notes_sr", {})
        assert set(serbian) == set(notes), pid
        for key, text in serbian.items():
            noted += 1
            prose = KEEP_OUT.sub("", text)
            assert not re.search(r"\d\.\d", prose.replace("3.3", "")), (pid, key, text)  # task 3.3
            for word in re.findall(r"[^\s⟨⟩(]+", re.sub(r"(^|[.:;]\s+)(U|I|A|O|K|S)\s", r"\1", prose)):
                assert not NOTATION.fullmatch(word), (pid, key, word)
    assert noted >= 60


def test_a_serbian_note_must_translate_an_english_one():
    from mechanisms.loader import parse_document
    from ui.i18n import message

    text = (ROOT / "mechanisms/presets/zbirka-6.2.toml").read_text()
    with pytest.raises(Exception) as caught:
        parse_document(text + '\n[book_notes_sr.x]\n', source="6.2.toml")
    bad = text.replace("[book_notes_sr]", '[book_notes_sr]\n"members.9.omega" = "bez para"')
    with pytest.raises(Exception) as caught:
        parse_document(bad, source="6.2.toml")
    assert "book_notes_sr.members.9.omega" in str(caught.value)
    assert "nema englesku napomenu" in message(caught.value, "sr")


def test_file_formats_and_keys_stay_latin_in_cyrillic():
    """SVG, PNG, CSV, Esc … are names a reader finds on a key or a file, not Serbian words."""
    for key, text in table("sr-cyrl").items():
        for transliterated in ("СВГ", "ПНГ", "Есц", "ЦСВ", "ЈСОН", "ХТМЛ", "ТОМЛ", "ПДФ"):
            assert transliterated not in text, (key, text)
