"""mechanisms.messages: a sentence kept as its key and values, written in the reader's
language only when shown (docs/i18n.md)."""

from pathlib import Path

from mechanisms.loader import parse_document
from mechanisms.messages import Joined, Text, text_of
from ui.i18n import message

ROOT = Path(__file__).resolve().parents[1]


def test_a_message_is_english_for_the_command_line_and_serbian_on_a_page():
    said = Text("form.no_triangle", d1=0.1, d2=0.25, length=0.5)
    assert str(said) == ("distances 0.1 m and 0.25 m cannot close a triangle with the member's "
                         "length 0.5 m (each side must be at most the sum of the other two)")
    assert message(said, "sr").startswith("rastojanja 0,1 m i 0,25 m ne mogu zatvoriti trougao")
    assert message(said, "sr-cyrl").startswith("растојања 0,1 m и 0,25 m")  # units stay Latin


def test_values_nest_and_join_without_a_comma_that_could_be_decimal():
    ranges = Joined([Text("driver.angles", lo=10.5, hi=20.0), Text("driver.angle", angle=30.0)])
    assert str(ranges) == "φ₂ ∈ [10.5°, 20°]; φ₂ = 30°"
    assert message(ranges, "sr") == "φ₂ ∈ [10,5°; 20°]; φ₂ = 30°"
    assert message(Text("form.distances_positive", value=[0.5, -1.0]), "sr").endswith("[0,5; -1]")


def test_a_scene_error_names_file_key_and_value_in_either_language():
    text = (ROOT / "mechanisms/presets/zbirka-2.1.toml").read_text()
    bad = text.replace("length = 0.41", "length = -0.2", 1)  # member 3, the coupler
    assert bad != text
    try:
        parse_document(bad, source="t.toml")
    except ValueError as error:
        assert str(error) == "t.toml: members.3.length must be > 0, got -0.2"
        assert message(error, "sr") == "t.toml: members.3.length mora biti > 0, a dato je -0,2"
        assert isinstance(text_of(error), Text)
    else:
        raise AssertionError("a negative length was accepted")
    assert message(ValueError("plain"), "sr") == "plain"  # an error raised with a string
