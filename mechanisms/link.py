"""A scene as one URL-safe parameter (``?s=…``), so that any page's link carries the mechanism.

The parameter is the scene's TOML text (``mechanisms.writer``), deflated and written in
URL-safe base64 without padding, after a one-letter format version. Decoding goes through
the same loader, size limit and validation as an uploaded file: a link is never a second,
looser way in. The format is documented in ``docs/links.md``.

Version ``1`` deflates with a preset dictionary of the words every scene file repeats; a
small scene's text is mostly those words, so its link comes out about a third shorter.
The dictionary is part of the format: never change it, add a version instead.
"""

from __future__ import annotations

import base64
import binascii
import urllib.parse
import zlib

from .loader import MAX_BYTES, SceneError, parse_document
from .messages import Text
from .writer import to_text

PARAMETER = "s"
VERSION = "1"
MAX_CHARS = 8_000  # longer than any course mechanism needs; refused before decoding
_DICTIONARY = (
    b'title_sr = ""\nsource = ""\nnote = ""\n\npairs = [\n'
    b'  { type = "prismatic", guide = 1, slider = 2, point = "B", through = "O", angle = 0.0, '
    b'slider_angle = 0.0, name = "1-2" },\n'
    b'  { type = "revolute", members = [1, 2], point = "A", name = "A" },\n'
    b'  { type = "revolute", members = [2, 3], point = "B", name = "B" },\n]\n\n'
    b'[frame]\nO = [0.0, 0.0]\n\n[driver]\ntype = "rotating"\nat = 60.0\nomega = 10.0\n'
    b'epsilon = 0.0\n\n[members.2]\nlabel = "crank"\npoints = ["O", "A"]\nlength = 0.1\n'
    b'\n[members.3]\nlabel = "coupler"\npoints = ["A", "B"]\nlength = 0.35\n'
    b'extra = { M = [0.2, 0.05] }\nmass = 1.0\ncentre = [0.1, 0.0]\ngyration = 0.1\n'
    b'\n[members.4]\nlabel = "rocker"\n\n[[forces]]\nmember = 4\npoint = "C"\nmagnitude = 100.0\n'
    b'angle = 0.0\nfollows_member = false\n\n[[moments]]\nmember = 4\nvalue = 10.0\n'
    b'\n[guess]\n"A" = [0.05, 0.0866]\n"B" = [0.3, 0.25]\n"C" = [0.2, 0.1]\n'
    b'\n[scales]\nL = 0.01\nv = 0.1\na = 1.0\n'
)


def encode(scene) -> str:
    """The ``s=`` value for a scene: version letter + base64url(deflate(TOML))."""
    packer = zlib.compressobj(9, zlib.DEFLATED, -15, zdict=_DICTIONARY)
    packed = packer.compress(to_text(scene).encode("utf-8")) + packer.flush()
    return VERSION + base64.urlsafe_b64encode(packed).decode("ascii").rstrip("=")


def parameter(text: str) -> str:
    """The ``s=`` value out of what a user pastes: a whole URL, ``s=…`` or the value alone."""
    text = text.strip()
    if "?" in text or text.startswith(f"{PARAMETER}="):
        query = urllib.parse.parse_qs(text.split("?", 1)[-1], keep_blank_values=True)
        values = query.get(PARAMETER)
        if not values:
            raise SceneError(Text("link.no_parameter", parameter=PARAMETER))
        return values[0]
    return text


def decode(text: str, default_id: str = "link"):
    """The scene a link carries, checked like an uploaded file; SceneError says what is wrong."""
    value = parameter(text)
    if len(value) > MAX_CHARS:
        raise SceneError(Text("link.too_long", parameter=PARAMETER, size=len(value),
                              most=MAX_CHARS))
    if not value or value[0] != VERSION:
        raise SceneError(Text("link.format", found=repr(value[:1]), version=VERSION))
    body = value[1:]
    try:
        packed = base64.urlsafe_b64decode(body + "=" * (-len(body) % 4))
        unpacker = zlib.decompressobj(-15, zdict=_DICTIONARY)
        data = unpacker.decompress(packed, MAX_BYTES + 1)  # a bounded inflate: no zip bomb
    except (binascii.Error, ValueError, zlib.error):
        raise SceneError(Text("link.damaged")) from None
    if len(data) > MAX_BYTES:
        raise SceneError(Text("link.too_big", most=MAX_BYTES))
    if not unpacker.eof:
        raise SceneError(Text("link.cut"))
    return parse_document(data, source="link", default_id=default_id)
