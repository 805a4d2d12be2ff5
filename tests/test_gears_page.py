"""Chapter 6 page (AppTest): every book train renders; inputs change the answer; no tracebacks."""

import re

import pytest

from mechanisms import preset_ids

from .test_pages import charts, linked, page, typed


def read(equation: str, lang: str) -> str:
    """A page's LaTeX with decimal points: a Serbian page writes every decimal as {,}."""
    if lang.startswith("sr"):
        assert not re.search(r"\d\.\d", equation), equation
    return equation.replace("{,}", ".")

@pytest.mark.parametrize("pid", preset_ids("gears"))
@pytest.mark.parametrize("tab", ["Train in half-section", "Velocity diagram (Kutzbach)"])
def test_every_train_draws_its_views(pid, tab):
    at = page("pages/planetary_gears.py", lang="en", scene=pid, tab=tab)
    assert not at.exception
    assert len(charts(at)) == 1


def test_doubling_the_input_doubles_every_speed():
    at = page("pages/planetary_gears.py", lang="en", scene="zbirka-6.8")
    before = at.dataframe[1].value
    typed(at, "in5", 200.0).run()
    after = at.dataframe[1].value
    for b, a in zip(before["ω [s⁻¹]"], after["ω [s⁻¹]"]):
        assert float(a) == pytest.approx(2 * float(b), rel=1e-4)


def test_a_degenerate_ratio_reads_as_infinite():
    at = page("pages/planetary_gears.py", lang="en", scene="zbirka-6.4", ra=4, rb=3)
    assert "does not rotate" in [m.value for m in at.metric][0]


def test_angular_velocities_are_read_off_the_pole_rays_as_in_the_book():
    """U_ω = U_v/(H·U_L): with 0.1 m/cm, 1 m/s per cm and H = 2 cm, 5 s⁻¹ per cm of intercept."""
    at = page("pages/planetary_gears.py", lang="en", scene="zbirka-6.8",
              tab="Velocity diagram (Kutzbach)")
    typed(at, "UL", 0.1).run()
    typed(at, "Uv", 1.0).run()
    typed(at, "H", 2.0).run()
    table = next(d.value for d in at.dataframe if "intercept x [cm]" in d.value.columns)
    carrier = table[table["member"] == 5].iloc[0]
    assert float(carrier["intercept x [cm]"]) == pytest.approx(100.0 / 5.0)


def test_a_link_carries_the_edited_meshes_and_inputs():
    """Doubling every first radius in the link's table and ω₅ changes the speeds as the
    Willis equations of the edited train say; the link keeps both."""
    own = linked("pages/planetary_gears.py", scene="zbirka-6.8", lang="en")
    rows = "6,7,0.03,0.025,0;4,3,0.02,0.05,3;2,8,0.12,0.01,0;9,10,0.05,0.045,0"
    at = linked("pages/planetary_gears.py", scene="zbirka-6.8", lang="en", meshes=rows, in5=200)
    assert not at.exception
    speeds = at.dataframe[1].value.set_index("member")["ω [s⁻¹]"].astype(float)
    before = own.dataframe[1].value.set_index("member")["ω [s⁻¹]"].astype(float)
    assert speeds.iloc[3] == pytest.approx(2 * before.iloc[3])  # the carrier: ω₅ doubled
    assert speeds.iloc[2] != pytest.approx(2 * before.iloc[2])  # planet 4: radii changed too
    assert at.query_params["meshes"] == rows.replace(",3;", ",1;")  # (the ring a yes: 1)
    assert "meshes" not in own.query_params  # the scene's own table keeps the link short


def test_a_broken_table_in_a_link_falls_back_to_the_scene():
    at = linked("pages/planetary_gears.py", scene="zbirka-6.8", lang="en", meshes="1,x;2")
    assert not at.exception and not at.error


@pytest.mark.parametrize("lang", ["sr", "en", "sr-cyrl"])
def test_the_willis_equations_are_written_stage_by_stage(lang):
    closed = page("pages/planetary_gears.py", lang=lang, scene="zbirka-6.1")
    assert not closed.latex  # closed, the panel costs a rerun nothing
    at = page("pages/planetary_gears.py", lang=lang, scene="zbirka-6.1", willis_open=True)
    assert not at.exception
    equations = [read(x.value, lang) for x in at.latex]
    assert any(r"i^{2}_{4,5}" in e and "-0.28125" in e for e in equations)
    assert any(r"i^{13}_{10,12}" in e for e in equations)
    assert any(r"i_{6,10} = \frac{\omega_{6}}{\omega_{10}}" in e for e in equations)
    radii = {"en": "from the radii", "sr": "iz poluprečnika", "sr-cyrl": "из полупречника"}[lang]
    assert any(rf"\text{{{radii}: }} {{-0.28125}}" in e for e in equations)


@pytest.mark.parametrize("lang", ["sr", "en", "sr-cyrl"])
def test_the_stages_combine_speed_by_speed_into_the_chosen_total_ratio(lang):
    """Task 6.1 the book's way: from ω2 = v/R through the shafts, the fixed-axes meshes and
    each carrier's stage, each step under a caption in the reader's language; the last line is
    the total ratio between the members picked above, with the page's own metric's digits."""
    at = page("pages/planetary_gears.py", lang=lang, scene="zbirka-6.1", willis_open=True)
    at.selectbox(key="ra").set_value(6).run()
    at.selectbox(key="rb").set_value(12).run()
    assert not at.exception
    equations = [read(x.value.strip("$\n"), lang) for x in at.latex]
    first = equations.index(r"\omega_{2} = \frac{v}{R} = \frac{1}{0.41} = 2.439")
    assert equations[first + 2] == r"\omega_{6} = \omega_{2} = 2.439"  # one body with carrier 2
    assert equations[-1].startswith(r"i_{6,12} = \frac{\omega_{6}}{\omega_{12}}")
    ratio = at.metric[0].value.replace(",", ".")
    assert equations[-1].endswith(f"= {float(ratio):.5g}")
    shaft = {"en": "Same shaft", "sr": "Isto vratilo", "sr-cyrl": "Исто вратило"}[lang]
    assert sum(shaft in c.value for c in at.caption) == 3  # 6 = 2, 8 = 7, 13 = 5


@pytest.mark.parametrize("pid", preset_ids("gears"))
@pytest.mark.parametrize("lang, fixed", [("en", "fixed"), ("sr", "nepokretan")])
def test_a_fixed_member_is_said_fixed_once_in_the_legend_and_in_the_table(pid, lang, fixed):
    """Whether a member is fixed comes from the train's ``fixed`` alone: a label that said it
    too read "4 ring (fixed) — fixed" in the legend. The drawing's legend and the ω table
    name each member alike."""
    from mechanisms import load_preset

    train = load_preset(pid)
    at = page("pages/planetary_gears.py", lang=lang, scene=pid)
    assert not at.exception
    legend = {trace["name"] for trace in next(iter(charts(at).values()))["figure"]["data"]
              if trace.get("name") and trace.get("showlegend", True)}
    table = set(at.dataframe[1].value.iloc[:, 0])  # (the first: the meshes editor)
    for n in train.members:
        names = {name for name in legend | table if re.match(rf"{n}\b", name)}
        assert len(names) == 1, names  # (the legend's and the table's the same)
        name = names.pop()
        assert name.count(fixed) == (1 if n in train.fixed else 0), name
