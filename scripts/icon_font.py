"""Streamlit's Material Symbols font cut down to the icons this app can show.

Streamlit ships every Material Symbol (4,052 glyphs, 375 kB as woff2) and a page asks for
the whole font as soon as it draws one icon (the sidebar's button, an expander's arrow): on a
phone over a mobile link that was a fifth of a first visit's bytes. An icon is a ligature:
the text ``expand_more`` drawn in this font becomes the arrow. So the font is cut to the
glyphs whose names appear anywhere in Streamlit's scripts (a superset of the icons its front
end draws) or as ``:material/…:`` in our code, with the ligatures that make them; the result
is about a tenth of the size. A name the cut leaves out would show as its word, so the cut
keeps every candidate and tests/test_serve.py checks the icons on our pages.
"""

from __future__ import annotations

import hashlib
import io
import re
from functools import cache
from pathlib import Path

from fontTools import subset
from fontTools.ttLib import TTFont

import streamlit

STATIC = Path(streamlit.__file__).parent / "static" / "static"
ROOT = Path(__file__).resolve().parents[1]
OUR_CODE = ("app.py", "pages", "ui")
FONT = re.compile(r"^/static/media/MaterialSymbols-[A-Za-z]+\.[\w-]+\.woff2$")
WORD = re.compile(r"[a-z][a-z0-9_]{1,60}")


@cache
def ours() -> set[str]:
    """Every ``:material/…:`` icon of our code (read once a process: the server names the
    cut by them on every request for the font)."""
    words: set[str] = set()
    for place in OUR_CODE:
        for source in [ROOT / place] if place.endswith(".py") else (ROOT / place).rglob("*.py"):
            words |= set(re.findall(r":material/([a-z0-9_]+):", source.read_text()))
    return words


def candidates() -> set[str]:
    """Every word of Streamlit's scripts, and every ``:material/…:`` icon of ours."""
    words = ours()
    for script in (STATIC / "js").glob("*.js"):
        words |= set(WORD.findall(script.read_text(encoding="utf-8", errors="ignore")))
    return words


def cut(font: bytes, names: set[str]) -> bytes:
    """The woff2 ``font`` with only the glyphs named in ``names`` and the letters that spell
    them (the ligatures from those letters to those glyphs are kept, no others)."""
    face = TTFont(io.BytesIO(font))
    kept = sorted(names & set(face.getGlyphOrder()))
    options = subset.Options()
    options.flavor = "woff2"
    options.layout_features = ["*"]
    options.layout_closure = False  # the letters must not pull in every other ligature
    options.notdef_outline = True
    options.glyph_names = True  # (a few kB: tests and a reader can see which icons are in)
    options.name_IDs = ["*"]
    letters = "".join(sorted(set("".join(kept)) | set("abcdefghijklmnopqrstuvwxyz0123456789_")))
    cutter = subset.Subsetter(options)
    cutter.populate(glyphs=kept, text=letters)
    cutter.subset(face)
    out = io.BytesIO()
    face.flavor = "woff2"
    face.save(out)
    return out.getvalue()


def cut_path(font: Path) -> Path:
    """Where the cut of Streamlit's ``font`` is kept, named after it and after our icons: a
    new Streamlit or a new icon of ours, a new cut (an icon missing from an older cut
    showed as its name)."""
    mark = hashlib.sha256(" ".join(sorted(ours())).encode()).hexdigest()[:8]
    return ROOT / "static" / f"cut-{mark}-{font.name}"


def main() -> None:
    """Cut each Material Symbols font of the installed Streamlit once (about 5 s)."""
    names = None
    for font in sorted((STATIC / "media").glob("MaterialSymbols-*.woff2")):
        target = cut_path(font)
        if target.exists():
            continue
        for older in target.parent.glob(f"cut-*-{font.name}"):
            older.unlink()
        names = names if names is not None else candidates()
        target.parent.mkdir(exist_ok=True)
        target.write_bytes(cut(font.read_bytes(), names))
        print(f"{font.name}: {font.stat().st_size // 1024} kB → {target.stat().st_size // 1024} kB")


if __name__ == "__main__":
    main()
