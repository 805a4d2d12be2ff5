"""The lecturer's variants page, and a student's variant opened on its chapter page by its
code, in a link or typed into the self-check box (AppTest)."""

import math

import pytest

from exams.codes import Settings
from exams.variants import generate, task
from ui.i18n import LANGUAGES, t

from .test_pages import page, typed

PAGE = "pages/variants.py"


def pick(at, pid: str):
    """Choose a task by its position: the box shows titles in the page's language."""
    box = at.selectbox(key="var_task")
    box.select_index(list(box.options).index(next(o for o in box.options if o.startswith(pid + " "))))


def make(at, pid: str, count: int, seed: int, language: str = "en"):
    pick(at, pid)
    typed(at, "var_count", count)
    typed(at, "var_seed", seed).run()
    next(b for b in at.button if b.label == t("var.make", language)).click().run()
    return at


@pytest.mark.parametrize("language", list(LANGUAGES))
def test_a_lecturer_makes_variants_with_sheets_and_key_in_every_language(language):
    at = page(PAGE, lang=language)
    assert not at.exception
    assert at.title[0].value.endswith(t("var.title", language=language))
    make(at, "zbirka-3.1", 4, 42, language)
    assert not at.exception and not at.error, [e.value for e in at.error]
    table = at.dataframe[0].value
    expected = [v.code for v in generate(Settings("zbirka-3.1", 42), 4).variants]
    assert list(table[t("var.col_code", language=language)]) == expected
    assert table[t("var.col_link", language=language)][0] == f"/velocity_plans?v={expected[0]}"
    labels = [b.label for b in at.get("download_button")]
    assert t("var.sheets", language=language) in labels and t("var.key_csv", language=language) in labels
    assert t("var.moodle", language=language) in labels


def test_holding_every_value_says_why_there_are_fewer_variants():
    at = page(PAGE, lang="en")
    pick(at, "zbirka-7.1")
    at.run()
    at.multiselect(key="var_hold_zbirka-7.1").set_value(list(range(len(task("zbirka-7.1").givens)))).run()
    make(at, "zbirka-7.1", 3, 1)
    assert any("same numbers" in w.value for w in at.warning)


def test_a_students_code_in_the_link_opens_their_variant_on_its_page():
    variant = generate(Settings("zbirka-3.1", 42), 3).variants[2]
    at = page("pages/velocity_plans.py", lang="en")
    at.query_params["v"] = variant.code
    at.run()
    assert not at.exception and not at.error, [e.value for e in at.error]
    assert at.selectbox(key="scene").value.startswith("link-")
    assert at.slider(key="at").value == pytest.approx(math.degrees(variant.scene.driver.at))
    assert at.slider(key="omega").value == pytest.approx(variant.scene.driver.speed)


@pytest.mark.parametrize("path", ["pages/velocity_plans.py", "pages/kinetostatics.py",
                                  "pages/assur_groups.py"])
def test_a_variant_with_a_negative_crank_angle_opens_at_that_angle_within_the_slider(path):
    variant = next(v for v in generate(Settings("zbirka-3.1", 1), 5).variants
                   if v.scene.driver.at < 0)  # φ₂ = 3.58° ± 10° gives some below zero
    at = page(path, lang="en")
    at.query_params["v"] = variant.code
    at.run()
    assert not at.exception, at.exception
    assert at.slider(key="at").value == pytest.approx(math.degrees(variant.scene.driver.at) + 360)


def test_a_code_typed_into_the_self_check_opens_the_variant_and_grades_against_it():
    variant = generate(Settings("zbirka-3.1", 42), 2).variants[1]
    at = page("pages/velocity_plans.py", lang="en", self_open=True)
    at.text_input(key="self_code").input(variant.code).run()
    assert not at.error, [e.value for e in at.error]
    assert at.selectbox(key="scene").value.startswith("link-")
    exact = next(a.value for a in variant.key if a.key == "points.E.v")
    quantity = at.selectbox(key="self_quantity")
    quantity.set_value(next(i for i, label in enumerate(quantity.options) if label.startswith("v_E")))
    at.run()
    at.text_input(key="self_value").input(f"{exact:.5f}").run()
    assert at.success, "the variant's own exact v_E is graded correct"


def test_a_damaged_code_or_one_for_another_chapter_says_so():
    at = page("pages/velocity_plans.py", lang="en")
    at.query_params["v"] = "3.1-S42-07Q"
    at.run()
    assert any("damaged" in e.value for e in at.error)
    rotor = generate(Settings("zbirka-7.1", 1), 1).variants[0]
    at = page("pages/velocity_plans.py", lang="en")
    at.query_params["v"] = rotor.code
    at.run()
    assert any(rotor.code in e.value for e in at.error)
