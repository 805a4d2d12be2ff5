"""Book vs exact in chromium: task 5.1 opened with the position and inertia changed names
both, and "As in the book" puts the page back to the task — its switches included, which
sit outside the fragment the button is in (AppTest runs a click as a whole page and could
not see that)."""

import pytest

from .test_browser import keep, open_page, wait_idle

pytestmark = pytest.mark.browser


def test_as_in_the_book_brings_the_task_back(app_url, browser, tmp_path):
    page = open_page(browser, f"{app_url}/kinetostatics?lang=sr&scene=zbirka-5.1&at=80"
                              "&inertia=true", (1400, 1000))
    notice = page.get_by_text("Ovde se razlikuje")
    notice.wait_for(timeout=30_000)
    said = page.locator("[data-testid='stAlertContentInfo']").filter(has_text="Ovde se").inner_text()
    assert "80°" in said and "50,286°" in said and "inercijalna" in said
    button = page.get_by_role("button", name="Kao u zbirci")
    button.scroll_into_view_if_needed()
    shot = tmp_path / "book-notice-5.1-sr.png"
    page.screenshot(path=str(shot))
    keep(shot)
    button.click()
    page.get_by_text("slaže se").first.wait_for(state="attached", timeout=30_000)  # the table
    wait_idle(page)
    assert not page.get_by_role("switch", name="Inercijalne sile i momenti").is_checked()
    assert "inertia=false" in page.url and "at=50.2857" in page.url
    assert notice.count() == 0
