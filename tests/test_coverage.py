"""Coverage of the course's texts: every task listed once, every textbook preset among them,
and the check page's per-chapter counts equal to the presets' own verdicts."""

from collections import Counter

from mechanisms import load_preset, preset_ids
from mechanisms.coverage import tasks
from reports.textbook import check
from ui.book import quantity
from ui.i18n import t

from .test_pages import page


def test_every_textbook_preset_is_a_listed_task_and_every_task_is_listed_once():
    listed = [task.preset for task in tasks()]
    assert len(listed) == len(set(listed))
    textbook = {pid for pid in preset_ids() if pid.startswith(("zbirka-", "analitika-", "predavanja-"))}
    assert textbook == {task.preset for task in tasks() if task.covered}
    assert all(task.reason["en"] and task.reason["sr"] for task in tasks() if not task.covered)
    assert Counter(task.chapter for task in tasks() if task.preset.startswith("zbirka"))["3"] == 6


def test_the_check_page_counts_tasks_presets_and_verdicts_per_chapter():
    at = page("pages/textbook_check.py", lang="en")
    assert not at.exception
    table = at.dataframe[0].value.set_index(t("check.col_chapter", "en"))
    for chapter in ("2", "5"):
        mine = [task for task in tasks() if task.chapter == chapter]
        verdicts = Counter(r.verdict for task in mine if task.covered
                           for r in check(load_preset(task.preset)))
        row = table.loc[chapter]
        assert row[t("check.col_tasks", "en")] == len(mine)
        assert row[t("check.col_presets", "en")] == sum(task.covered for task in mine)
        assert row[t("check.agrees", "en")] == verdicts["agrees"]
        assert row[t("check.layout", "en")] == verdicts["layout"]


def test_the_check_page_marks_what_was_fitted_what_chose_the_layout_and_what_is_predicted():
    at = page("pages/textbook_check.py", lang="en")
    roles = next(d.value for d in at.dataframe  # (rows named as the course writes them)
                 if t("check.col_role", "en") in d.value.columns
                 and quantity("members.3.epsilon") in set(d.value[t("check.col_quantity", "en")])
                 and quantity("points.F.v") in set(d.value[t("check.col_quantity", "en")]))
    role = dict(zip(roles[t("check.col_quantity", "en")], roles[t("check.col_role", "en")]))
    assert role[quantity("points.C.v")] == t("check.fitted", "en")
    assert role[quantity("members.6.epsilon")] == t("check.chose", "en")
    assert role[quantity("points.F.v")] == t("check.predicted", "en")
    captions = " ".join(c.value for c in at.caption)
    assert t("check.fit_chose", "en", chose=2) in captions
