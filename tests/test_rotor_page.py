"""Chapter 7 page driven as a user would (AppTest)."""

import pytest

from .test_pages import arrows, chart, charts, linked, page, typed


def rotor_page(**state):
    return page("pages/rotor_balancing.py", lang="en", **state)


def corrections(at):
    """The results table (the first table with a "quantity" column; the editor comes first)."""
    return next(d.value for d in at.dataframe if "quantity" in d.value.columns)


def exact(at, plane: str, quantity: str) -> float:
    table = corrections(at)
    row = table[(table["plane"] == plane) & (table["quantity"] == quantity)].iloc[0]
    return float(row["exact"].split()[0])


def test_task_7_1_shows_exact_beside_the_book():
    at = rotor_page(scene="zbirka-7.1")
    assert not at.exception
    assert exact(at, "I", "mass") == pytest.approx(0.35408, abs=1e-5)
    assert corrections(at).loc[0, "book"] == "0.354 kg"


def test_a_bigger_correction_radius_needs_a_proportionally_smaller_mass():
    at = rotor_page(scene="zbirka-7.1")
    before = exact(at, "I", "mass")
    typed(at, "valueI", 400.0).run()  # r_I from 200 mm to 400 mm
    assert exact(at, "I", "mass") == pytest.approx(before / 2, rel=1e-4)


def test_planes_at_the_same_place_get_a_message_not_a_traceback():
    at = rotor_page(scene="zbirka-7.1")
    typed(at, "xII", 450.0).run()
    assert not at.exception
    assert "same axial position" in at.error[0].value


def test_static_mode_uses_one_plane():
    at = rotor_page(scene="zbirka-7.2")
    at.radio(key="mode").set_value("static").run()
    assert not at.exception
    assert set(corrections(at)["plane"]) == {"I"}


@pytest.mark.parametrize("tab, key", [("V polygon (moments)", "vpoly"), ("U polygon (forces)", "upoly"),
                                      ("End view", "end"), ("Rotor in 3D", "3d")])
def test_every_task_draws_every_view_and_only_the_open_one(tab, key):
    for task in range(1, 7):
        at = rotor_page(scene=f"zbirka-7.{task}", tab=tab)
        assert not at.exception
        (drawn,) = charts(at)  # the other tabs do not run
        assert drawn == key
        if key.endswith("poly"):
            assert len(arrows(chart(at, key))) >= 4  # 3 masses + the closing vector


def test_a_student_checks_a_graphical_answer():
    at = rotor_page(scene="zbirka-7.1", self_open=True)
    at.text_input(key="self_value").input("0,354").run()  # a comma on an English page
    assert "decimal sign is a point" in at.error[-1].value and not at.success
    at.text_input(key="self_value").input("0.354").run()  # the first quantity: m_I [kg]
    assert at.success[0].value.startswith("Right")
    at.text_input(key="self_value").input("0.356").run()  # within the task's drawing: ±0.0025 kg
    assert at.success[0].value.startswith("Right") and "what a drawing" in at.success[0].value
    at.text_input(key="self_value").input("0.358").run()  # as `check` says: outside it
    assert at.warning and not at.success
    at.text_input(key="self_value").input("0.5").run()
    assert at.warning[-1].value.startswith("The sign is right, but the size is not.")
    at.text_input(key="self_value").input("abc").run()
    assert "` abc ` is not one number" in at.error[-1].value and not at.warning


def test_a_link_carries_the_mass_table():
    """A link with a third mass in its table balances that rotor, not the book's."""
    own = linked("pages/rotor_balancing.py", scene="zbirka-7.1", lang="en")
    rows = own.dataframe[0].value.to_numpy().tolist() + [[0.2, 100.0, 45.0, 150.0]]
    text = ";".join(",".join(f"{float(v):g}" for v in row) for row in rows)  # cells are text
    at = linked("pages/rotor_balancing.py", scene="zbirka-7.1", lang="en", masses=text)
    assert not at.exception
    assert len(at.dataframe[0].value) == len(rows)
    assert exact(at, "I", "mass") != pytest.approx(exact(own, "I", "mass"))
