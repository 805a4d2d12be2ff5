"""Scene files: every preset loads; broken files get a message naming file, key and rule."""

import pytest

from mechanisms import SceneError, load_preset, parse_scene, preset_ids



def fourbar_text(**changes) -> str:
    text = """
pairs = [
  { type = "revolute", members = [1, 2], point = "O" },
  { type = "revolute", members = [2, 3], point = "A" },
  { type = "revolute", members = [3, 4], point = "B" },
  { type = "revolute", members = [4, 1], point = "D" },
]
[frame]
O = [0.0, 0.0]
D = [0.4, 0.0]
[driver]
type = "rotating"
omega = 10.0
[members.2]
points = ["O", "A"]
length = 0.1
[members.3]
points = ["A", "B"]
length = 0.35
[members.4]
points = ["D", "B"]
length = 0.3
"""
    for old, new in changes.items():
        old = old.replace("_", " ")
        assert old in text
        text = text.replace(old, new)
    return text


def test_every_preset_loads_with_title_and_source():
    ids = preset_ids()
    assert {"analitika-2.1", "analitika-2.2", "four-bar-crank-rocker", "slider-crank",
            "scotch-yoke", "tangent-slotted-crank"} <= set(ids)
    for pid in ids:
        scene = load_preset(pid)
        assert scene.id == pid and scene.title and scene.source and scene.note


def test_the_plain_fourbar_text_is_valid():
    assert parse_scene(fourbar_text()).lengths == {2: 0.1, 3: 0.35, 4: 0.3}


@pytest.mark.parametrize("old, new, message", [
    ("length = 0.35", "length = -0.2", "four.toml: members.3.length must be > 0, got -0.2"),
    ("length = 0.35", "lenght = 0.35", "members.3.lenght is not a known key (did you mean 'length'?)"),
    ("length = 0.35", "length = nan", "members.3.length must be a finite number"),
    ("length = 0.35", 'length = "long"', "members.3.length must be a number"),
    ("D = [0.4, 0.0]", "D = [0.0, 0.0]", "frame.D coincides with frame.O"),
    ("omega = 10.0", "", "driver.omega is missing"),
    ('type = "rotating"', 'type = "spinning"', "driver.type must be 'rotating' or 'linear'"),
    ('members = [4, 1], point = "D"', 'members = [4, 7], point = "D"',
     "pairs[3].members names member 7, which is not defined"),
    ('members = [4, 1], point = "D"', 'members = [4, 1], point = "Q"', "pairs[3].point must be a point of member 4"),
    ('[members.2]', '[members.1]', "members.1 must be numbered 2, 3"),
])
def test_broken_files_say_which_key_and_rule(old, new, message):
    with pytest.raises(SceneError) as err:
        parse_scene(fourbar_text().replace(old, new), source="four.toml")
    assert message in str(err.value)


def test_not_utf8_too_big_and_not_toml_are_refused_plainly():
    with pytest.raises(SceneError, match="not UTF-8"):
        parse_scene(b"title = \"\xff\xfe\"")
    with pytest.raises(SceneError, match="must be under"):
        parse_scene(b"#" * 2_000_000)
    with pytest.raises(SceneError, match="not valid TOML"):
        parse_scene("pairs = [")


def test_a_one_point_member_needs_a_prismatic_pair():
    text = fourbar_text().replace('points = ["D", "B"]\nlength = 0.3', 'points = ["B"]')
    text = text.replace('{ type = "revolute", members = [4, 1], point = "D" },', "")
    with pytest.raises(SceneError, match="members.4.points has one point"):
        parse_scene(text)


def test_scene_files_are_never_executed(tmp_path):
    """A string that would be code stays a string: the loader only parses TOML."""
    marker = tmp_path / "ran"
    text = fourbar_text().replace('points = ["O", "A"]',
                                  f'label = "__import__(\'os\').mkdir(\'{marker}\')"\npoints = ["O", "A"]')
    scene = parse_scene(text)
    assert "__import__" in scene.members[2].label and not marker.exists()


def test_overriding_a_length_moves_extra_points_with_the_link():
    scene = load_preset("analitika-2.1")
    longer = scene.with_(lengths={3: 1.2})
    assert longer.members[3].points["B"] == pytest.approx(0.9)
    assert scene.members[3].points["B"] == pytest.approx(0.45)


def test_a_letter_on_two_members_must_be_a_joint():
    text = fourbar_text().replace('length = 0.3\n', 'length = 0.3\nextra = { A = [0.1, 0.1] }\n')
    with pytest.raises(SceneError, match="members.4.points uses the letter A of member 2"):
        parse_scene(text)


def test_loads_are_read_in_si_units():
    (force,) = load_preset("slider-crank").forces
    assert force.member == 4 and force.point == "B" and force.magnitude == 200.0
    assert force.angle == pytest.approx(3.141592653589793)


@pytest.mark.parametrize("pid", preset_ids("rotor"))
def test_a_downloaded_rotor_uploads_again_unchanged(pid):
    from mechanisms import parse_document
    from mechanisms.writer import rotor_to_toml

    rotor = load_preset(pid)
    assert parse_document(rotor_to_toml(rotor)) == rotor


@pytest.mark.parametrize("pid", preset_ids("linkage"))
def test_a_downloaded_scene_uploads_again_unchanged(pid):
    from mechanisms.writer import to_toml
    from solvers import solve

    base = load_preset(pid)
    first = min(base.lengths)  # the crank, or the first link after a driving slider
    scene = base.with_(lengths={first: base.lengths[first] * 1.01})
    again = parse_scene(to_toml(scene))
    assert again.lengths == pytest.approx(scene.lengths)
    assert again.driver.speed == pytest.approx(scene.driver.speed)
    a, b = solve(scene), solve(again)
    for name, p in a.points.items():
        assert complex(b.points[name].z[0]) == pytest.approx(complex(p.z[0]), abs=1e-12)


@pytest.mark.parametrize("pid", preset_ids("gears"))
def test_a_downloaded_gear_train_uploads_again_unchanged(pid):
    from mechanisms import parse_document
    from mechanisms.writer import gears_to_toml

    train = load_preset(pid)
    assert parse_document(gears_to_toml(train)) == train
