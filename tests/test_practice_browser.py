"""Practice in a real browser: on the plans page a student drags the new arrow's tip on the
sheet — to the right place (ok), then to a wrong one (the diagnosis shown)."""

import pytest

from cli.practice import steps_for
from mechanisms import load_preset

from .test_browser import keep, open_page, wait_idle
from .test_builder_browser import SHAPES, drag_shape, shapes

pytestmark = pytest.mark.browser


def drag_tip(page, to: complex) -> None:
    """Drag the sheet's red circle to ``to`` (cm on the paper)."""
    drag_shape(page, "tip", to)


def test_dragging_the_tip_on_the_plans_page_is_checked_on_release(app_url, browser, tmp_path):
    page = open_page(browser, f"{app_url}/velocity_plans?lang=en&scene=zbirka-3.1", (1600, 1100))
    page.get_by_text("Practise", exact=True).click()
    page.wait_for_selector(".mehanizmi-plot .shapelayer path", timeout=30_000)
    wait_idle(page)
    step = steps_for(load_preset("zbirka-3.1"), "plans")[0]
    tip = (step.tail + complex(step.expected)) / step.scale  # cm on the paper
    drag_tip(page, tip)
    page.get_by_text("Right, within what a drawing").wait_for(timeout=30_000)
    shot = tmp_path / "practice-plans-ok-en.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)

    page.get_by_role("button", name="Next step").click()
    wait_idle(page)
    second = steps_for(load_preset("zbirka-3.1"), "plans")[1]
    start = second.tail / second.scale
    fresh = start + (1.0 + 0.5j)  # the new step's circle, before the student moves it
    page.wait_for_function(f"() => Math.hypot(({SHAPES})()['tip'][0] - {fresh.real}, "
                           f"({SHAPES})()['tip'][1] - {fresh.imag}) < 1e-9", timeout=30_000)
    reversed_tip = start - complex(second.expected) / second.scale
    drag_tip(page, reversed_tip)
    page.get_by_text("the arrow points the other way").wait_for(timeout=30_000)
    assert abs(shapes(page)["tip"] - reversed_tip) < 0.05  # where the mouse let go
    assert page.locator("[data-testid='stException']").count() == 0
    shot = tmp_path / "practice-plans-sense-en.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)
