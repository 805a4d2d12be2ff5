"""Each task opens as the book poses it: on a fresh load a chapter page's scene is the preset
exactly, so "Book vs exact" shows its table (not the notice that something changed), and
the kinetostatics page's switches are the task's own; after a change the notice names it
and "As in the book" brings the table back."""

from __future__ import annotations

import tomllib

import pytest

from mechanisms import load_preset, preset_ids
from mechanisms.loader import build_document
from mechanisms.writer import to_toml
from ui.i18n import t

from .test_pages import page, typed

LINKAGES_WITH_BOOK = [p for p in preset_ids()
                      if load_preset(p).book and hasattr(load_preset(p), "pairs")]
PAGES = ("pages/velocity_plans.py", "pages/kinetostatics.py")


def notice(at, lang: str = "en") -> list[str]:
    return [i.value for i in at.info if i.value.startswith(t("book.changed", lang))]


def compared(at, lang: str = "en") -> bool:
    """The book's table is there and the notice is not."""
    return t("plans.book_title", lang) in [h.value for h in at.header] and not notice(at, lang)


@pytest.mark.parametrize("preset", LINKAGES_WITH_BOOK)
def test_a_fresh_load_compares_with_the_book_at_once(preset):
    scene = load_preset(preset)
    at = page(PAGES[0], lang="en", scene=preset, tab=t("plans.tab_accuracy", "en"))
    assert not at.exception and compared(at), notice(at)
    at = page(PAGES[1], lang="en", scene=preset)
    assert not at.exception and compared(at), notice(at)
    assert at.toggle(key="inertia").value == scene.inertia
    assert at.toggle(key="gravity").value == (scene.gravity > 0)


def test_the_kinetostatics_tasks_state_whether_inertia_counts():
    """5.1, 5.2 and the lecture leave inertia out; 5.3 and 5.4 count it."""
    said = {p: load_preset(p).inertia for p in
            ("zbirka-5.1", "zbirka-5.2", "predavanja-kinetostatika", "zbirka-5.3", "zbirka-5.4")}
    assert said == {"zbirka-5.1": False, "zbirka-5.2": False, "predavanja-kinetostatika": False,
                    "zbirka-5.3": True, "zbirka-5.4": True}
    text = to_toml(load_preset("zbirka-5.1"))
    assert "inertia = false" in text  # and it survives a download and upload
    assert build_document(tomllib.loads(text), source="x").inertia is False


@pytest.mark.parametrize("lang", ["en", "sr"])
def test_a_change_is_named_and_one_click_brings_the_book_back(lang):
    at = page(PAGES[1], lang=lang, scene="zbirka-5.1")
    assert compared(at, lang)
    at.slider(key="at").set_value(100.0).run()
    said = [i.value for i in at.info if i.value.startswith(t("book.changed", lang))]
    assert said and "φ₂ = 100°" in said[0] and ("50,286°" if lang == "sr" else "50.286°") in said[0]
    at.toggle(key="inertia").set_value(True).run()
    typed(at, "F0", 80.0, lang).run()
    said = [i.value for i in at.info if i.value.startswith(t("book.changed", lang))][0]
    assert t("book.diff_inertia_on", lang) in said and "80 N" in said
    at.select_slider(key="steps").set_value(72).run()  # not the task's: it stays
    next(b for b in at.button if b.key == "book_restore").click().run()
    assert not at.exception and not [i for i in at.info if i.value.startswith(
        t("book.changed", lang))]
    assert at.toggle(key="inertia").value is False and at.select_slider(key="steps").value == 72
    assert at.header and t("plans.book_title", lang) in [h.value for h in at.header]


def _notice(at, lang: str) -> str:
    said = [i.value for i in at.info if i.value.startswith(t("book.changed", lang))]
    return said[0] if said else ""


@pytest.mark.parametrize("lang", ["en", "sr"])
def test_a_changed_rotor_or_gear_task_says_what_differs_and_comes_back(lang, monkeypatch):
    """Task 7.1 with x_I 450 → 440 once showed 0,36213 kg beside the book's 0,354 kg as the
    book's slip (−2,2 %); task 6.1 with v₂ 1 → 2 showed ω 4,878 beside the book's 2,44."""
    monkeypatch.setattr("ui.i18n.current", lambda: lang)  # (AppTest formats choices outside a run)
    rotor = page("pages/rotor_balancing.py", lang=lang, scene="zbirka-7.1")
    assert not _notice(rotor, lang)
    book = "0,354 kg" if lang == "sr" else "0.354 kg"
    assert any(book in str(d.value.to_numpy()) for d in rotor.dataframe)
    typed(rotor, "xI", 440.0, lang).run()
    said = _notice(rotor, lang)
    assert "x_I: 440 mm" in said and "450 mm" in said
    assert not any(book in str(d.value.to_numpy()) for d in rotor.dataframe)  # not beside it
    next(b for b in rotor.button if b.key == "book_restore").click().run()
    assert not _notice(rotor, lang) and any(book in str(d.value.to_numpy()) for d in rotor.dataframe)
    gears = page("pages/planetary_gears.py", lang=lang, scene="zbirka-6.1")
    assert not _notice(gears, lang)
    typed(gears, "in2", 2.0, lang).run()
    said = _notice(gears, lang)
    assert "2 m/s" in said and "1 m/s" in said
    next(b for b in gears.button if b.key == "book_restore").click().run()
    assert not _notice(gears, lang)


def test_a_changed_speed_is_said_with_its_unit():
    """Task 2.1's notice said "the speed of member 2: 17 (the book's task: 15)" (here on the
    kinetostatics page, whose book table is open at once)."""
    at = page(PAGES[1], lang="en", scene="zbirka-5.1")
    at.slider(key="omega").set_value(17.0).run()
    assert "17 s⁻¹" in _notice(at, "en") and "s⁻¹)" in _notice(at, "en")


@pytest.mark.parametrize("lang", ["en", "sr"])
def test_the_hay_tedders_travel_is_compared_and_a_change_named(lang, monkeypatch):
    """Task 1.3 (trajectories): ω_t, ω₂, T, Δt and Δs beside the book's; v_R changed is said
    with its unit, no book value is shown beside the exact one, and the button brings the
    task back."""
    monkeypatch.setattr("ui.i18n.current", lambda: lang)  # (AppTest formats choices outside a run)
    at = page("pages/trajectories.py", lang=lang, scene="zbirka-1.3")
    assert not at.exception and compared(at, lang), _notice(at, lang)
    rows = " ".join(str(d.value.to_numpy()) for d in at.dataframe)
    assert "ω_t [s⁻¹]" in rows and "Δs [m]" in rows
    at.slider(key="vR").set_value(4.5).run()
    said = _notice(at, lang)
    assert ("v_R: 4,5 m/s" if lang == "sr" else "v_R: 4.5 m/s") in said and "3 m/s" in said
    assert t("plans.book_title", lang) in [h.value for h in at.header]
    assert not any("ω_t [s⁻¹]" in str(d.value.to_numpy()) for d in at.dataframe)
    next(b for b in at.button if b.key == "book_restore").click().run()
    assert not at.exception and compared(at, lang) and at.slider(key="vR").value == 3.0


@pytest.mark.parametrize("lang", ["en", "sr", "sr-cyrl"])
def test_every_printed_value_is_named_in_words_and_symbols(lang):
    """Every book row of every preset: its symbol, its unit and its words in the language
    (no result key such as points.E.v or angle_deg₃ left in sight)."""
    from ui.book import quantity, words
    from ui.i18n import _RUN

    _RUN.language = lang
    try:
        for preset in preset_ids():
            for key in getattr(load_preset(preset), "book", {}):
                name, said = quantity(key), words(key)
                assert said and key not in name and "_deg" not in name, (preset, name)
    finally:
        _RUN.language = None


def test_the_plans_pages_book_table_speaks_the_pages_language():
    at = page(PAGES[0], lang="sr", scene="zbirka-3.1", tab=t("plans.tab_accuracy", "sr"))
    rows = " ".join(str(d.value.to_numpy()) for d in at.dataframe)
    assert "v_C [m/s]" in rows and "brzina tačke C" in rows and "ugaona brzina člana" in rows


def test_the_plans_page_names_a_changed_speed_and_brings_the_book_back():
    at = page(PAGES[0], lang="sr", scene="zbirka-3.1", tab=t("plans.tab_accuracy", "sr"))
    assert compared(at, "sr")
    at.slider(key="omega").set_value(12.0).run()
    said = _notice(at, "sr")
    assert "12 s⁻¹" in said and "s⁻¹)" in said
    next(b for b in at.button if b.key == "book_restore").click().run()
    assert not at.exception and compared(at, "sr")
