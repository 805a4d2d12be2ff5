"""The builder page, and every linkage page opened from a link that carries a scene (AppTest)."""

import pytest
from streamlit.testing.v1 import AppTest

from mechanisms import load_preset, preset_ids
from mechanisms.link import decode, encode
from mechanisms.loader import build_scene
from mechanisms.sketch import template, template_ids
from solvers.diagnostics import solve_instant
from ui.i18n import LANGUAGES, t

from .test_pages import ROOT, charts, page

PAGE = "pages/builder.py"
LINKAGE_PAGES = ["pages/trajectories.py", "pages/velocity_plans.py", "pages/assur_groups.py",
                 "pages/kinetostatics.py"]


def start(option: str, lang: str = "en") -> AppTest:
    at = page(PAGE, lang=lang)
    at.selectbox(key="build_start").set_value(option).run()
    next(b for b in at.button if b.label == t("build.start", "en")).click().run()
    return at


def drawn(at: AppTest) -> dict[str, complex]:
    shapes = charts(at)["build_fig"]["figure"]["layout"]["shapes"]
    return {s["name"]: complex((s["x0"] + s["x1"]) / 2, (s["y0"] + s["y1"]) / 2) for s in shapes}


@pytest.mark.parametrize("language", list(LANGUAGES))
def test_the_builder_renders_in_every_language(language):
    at = page(PAGE, lang=language)
    assert not at.exception
    assert at.title[0].value.endswith(t("build.title", language=language))
    assert charts(at)["build_fig"]["editable"] is True


@pytest.mark.parametrize("name", template_ids())
def test_every_template_starts_and_is_checked(name):
    at = start(f"template:{name}")
    assert not at.exception and not at.error, [e.value for e in at.error]
    scene = build_scene(template(name))
    formula = next(s.value for s in at.success)
    assert solve_instant(scene, None).structure.formula in formula
    assert set(drawn(at)) == set(scene.point_names)


@pytest.mark.parametrize("pid", preset_ids("linkage"))
def test_every_linkage_preset_starts_drawn_where_the_preset_puts_it(pid):
    at = start(f"preset:{pid}")
    assert not at.exception and not at.error, [e.value for e in at.error]
    motion = solve_instant(load_preset(pid), None)
    for name, z in drawn(at).items():
        assert abs(z - complex(motion.points[name].z[0])) < 1e-9, name


def test_the_link_on_the_page_carries_the_built_scene():
    at = start("template:watt-six-bar")
    value = at.code[0].value.removeprefix("s=")
    again = build_scene(template("watt-six-bar"))
    linked = decode(value)
    assert [m.length for m in linked.members.values()] == pytest.approx(
        [m.length for m in again.members.values()])
    assert linked.guess and not linked.assembly  # the branch travels as the drawing
    assert at.get("download_button")  # and the TOML download is there


def test_a_button_opens_the_built_scene_on_the_plans_page():
    at = start("template:slider-crank")
    next(b for b in at.button if b.key == "open_pages/velocity_plans.py").click().run()
    assert not at.exception
    assert at.selectbox(key="scene").value.startswith("link-")
    assert [e.value for e in at.error] == []
    assert {"fig_v", "fig_a", "fig_mech"} <= set(charts(at))  # the plans of the built scene


def linked(path: str, value: str) -> AppTest:
    at = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)
    at.session_state["lang"] = "en"
    at.query_params["s"] = value
    at.run()
    at.switch_page(path).run()
    return at


@pytest.mark.parametrize("path", LINKAGE_PAGES)
def test_every_linkage_page_opens_a_scene_from_its_link(path):
    doc = template("class-iii" if path == "pages/assur_groups.py" else "four-bar")
    for spec in doc["members"].values():
        spec["mass"] = 1.5
    scene = build_scene(doc)
    at = linked(path, encode(scene))
    assert not at.exception and not at.error, [e.value for e in at.error]
    choice = at.selectbox(key="scene")
    assert choice.value.startswith("link-")
    assert t("scene.linked", "en") in choice.format_func(choice.value)


def test_a_student_can_leave_the_linked_scene_for_a_preset_and_come_back():
    at = linked("pages/velocity_plans.py", encode(build_scene(template("four-bar"))))
    mine = at.selectbox(key="scene").value
    at.selectbox(key="scene").set_value("zbirka-2.1").run()
    assert at.selectbox(key="scene").value == "zbirka-2.1" and "s" not in at.query_params
    offered = at.selectbox(key="scene").options  # labels: the linked scene is still offered
    assert any(o.startswith(t("scene.linked", "en")) for o in offered)
    at.selectbox(key="scene").set_value(mine).run()
    assert not at.error and at.query_params["s"].startswith("1")


@pytest.mark.parametrize("value", ["1garbage", "2abc", encode(load_preset("zbirka-2.1"))[:-30],
                                   "1" + "A" * 9000, encode(load_preset("zbirka-7.1"))])
def test_a_bad_link_says_why_and_the_page_shows_its_default_scene(value):
    at = linked("pages/velocity_plans.py", value)
    assert not at.exception
    assert len(at.error) == 1 and "link" in at.error[0].value
    assert at.selectbox(key="scene").value == "analitika-2.1"
    assert "s" not in at.query_params
