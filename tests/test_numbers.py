"""The one parser of typed numbers (ui/numbers.py): Serbian reads a comma and a point alike,
English reads a point and refuses a comma, nothing that is not one number is taken, and a
number shown and read back is the same float."""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ui.i18n import LANGUAGES
from ui.numbers import Refused, check, literal, parse, refusal, shown

SERBIAN = ("sr", "sr-cyrl")


@pytest.mark.parametrize("language", SERBIAN)
@pytest.mark.parametrize("text, value", [
    ("0,35", 0.35), ("0.35", 0.35), ("10,5", 10.5), ("1,25", 1.25), ("273,58", 273.58),
    ("3,1", 3.1), ("-12,5", -12.5), ("\u221212,5", -12.5), (" 7 ", 7.0), (",5", 0.5),
    ("5,", 5.0), ("1,5e-3", 1.5e-3), ("+2", 2.0), ("1E3", 1000.0)])
def test_serbian_reads_a_comma_and_a_point_alike(language, text, value):
    assert parse(text, language) == value


@pytest.mark.parametrize("text, value", [("0.35", 0.35), ("-12.5", -12.5), (".5", 0.5),
                                         ("1.5e-3", 1.5e-3), ("42", 42.0)])
def test_english_reads_a_point(text, value):
    assert parse(text, "en") == value


@pytest.mark.parametrize("text", ["0,35", "1,000", "3,1"])
def test_english_refuses_a_comma_rather_than_guess(text):
    with pytest.raises(Refused) as refused:
        parse(text, "en")
    assert refused.value.reason == "comma"


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("text, reason", [
    ("0,3,5", "not_number"), ("1.2.3", "not_number"), ("abc", "not_number"), ("", "empty"),
    ("   ", "empty"), ("1.000,5", "not_number"), ("1 000", "not_number"), ("nan", "not_number"),
    ("inf", "not_number"), ("1e999", "not_number"), ("0x10", "not_number"), ("5-", "not_number"),
    ("--5", "not_number"), ("1_000", "not_number"), ("½", "not_number"), ("٣", "not_number")])
def test_anything_but_one_number_is_refused(language, text, reason):
    with pytest.raises(Refused) as refused:
        parse(text, language)
    assert refused.value.reason == reason


def test_a_range_and_whole_numbers_are_checked_not_clamped():
    assert check("3", "en", minimum=1, maximum=5, integer=True) == 3.0
    for text, reason in (("0", "below"), ("6", "above"), ("2.5", "integer")):
        with pytest.raises(Refused) as refused:
            check(text, "en", minimum=1, maximum=5, integer=True)
        assert refused.value.reason == reason


@given(st.floats(allow_nan=False, allow_infinity=False), st.sampled_from(list(LANGUAGES)))
def test_a_number_shown_reads_back_exactly(value, language):
    assert parse(shown(value, language), language) == value


def test_serbian_shows_a_decimal_comma():
    assert shown(0.35, "sr") == "0,35" and shown(0.35, "sr-cyrl") == "0,35"
    assert shown(0.35, "en") == "0.35" and shown(100.0, "sr") == "100"
    assert shown(30, "sr", integer=True) == "30"


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_message_names_the_field_and_repeats_the_text(language):
    text = refusal("Dužina [m]", Refused("not_number", "0,3,5"), language)
    assert text.startswith("Dužina [m]") and "` 0,3,5 `" in text
    below = refusal("m", Refused("below", "-1", 0.5), language)
    assert ("0,5" if language in SERBIAN else "0.5") in below


def test_a_typed_text_is_shown_literally_and_bounded():
    assert literal("**x** $y$") == "` **x** $y$ `"
    assert literal("a`b") == "`` a`b ``"
    assert len(literal("9" * 10_000)) < 50
    assert "\x00" not in literal("1\x002") and literal("") == "“”"
    assert not math.isnan(parse(" 1 ", "en"))
