"""The tool's own RSA key: made once, kept readable by its owner alone, its public half
published as a JWKS (``/lti/jwks``) for the platform to check what the tool signs — a deep
linking response, a client assertion for the gradebook's token.

It also keys the lecturer keys of the classes launches make (an HMAC of the link): the
store keeps only a class key's hash, so an instructor's launch derives the key again
instead of reading it from the store (a stolen database still opens no class).
"""

from __future__ import annotations

import hashlib
import hmac
import json
import os
import time
import uuid
from functools import cache
from pathlib import Path

import jwt
from cryptography.hazmat.primitives import serialization
from cryptography.hazmat.primitives.asymmetric import rsa
from jwt.algorithms import RSAAlgorithm

from classes.store import DATA

ALGORITHM = "RS256"


def key_path() -> Path:
    """Where the private key lives (``MEHANIZMI_LTI_KEY``, or data/lti/tool-key.pem)."""
    return Path(os.environ.get("MEHANIZMI_LTI_KEY", DATA / "lti" / "tool-key.pem"))


@cache
def _private(path: Path):
    """The key at ``path``, made there the first time (folder 700, file 600). Written aside
    and linked into place: the app processes of a deployment start together, and the first
    one's key is everyone's (a link fails if the name is taken; no half-written key is read)."""
    if not path.exists():
        path.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
        made = rsa.generate_private_key(public_exponent=65537, key_size=2048)
        pem = made.private_bytes(serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
                                 serialization.NoEncryption())
        aside = path.with_name(f".{path.name}.{os.getpid()}")
        descriptor = os.open(aside, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
        with os.fdopen(descriptor, "wb") as file:
            file.write(pem)
        try:
            os.link(aside, path)
        except FileExistsError:
            pass  # another process made it first: theirs is the key
        finally:
            aside.unlink()
    return serialization.load_pem_private_key(path.read_bytes(), password=None)


def private_key():
    return _private(key_path())


def kid() -> str:
    """The key's id: its public key's SHA-256 (a new key, a new id)."""
    public = private_key().public_key().public_bytes(
        serialization.Encoding.DER, serialization.PublicFormat.SubjectPublicKeyInfo)
    return hashlib.sha256(public).hexdigest()[:16]


def jwks() -> dict:
    """The public key as a JSON Web Key Set."""
    key = json.loads(RSAAlgorithm.to_jwk(private_key().public_key()))
    return {"keys": [{**key, "kid": kid(), "alg": ALGORITHM, "use": "sig"}]}


def sign(claims: dict, lifetime: int = 300) -> str:
    """``claims`` as a JWT the tool signs, with ``iat``, ``exp`` and a ``jti`` of its own."""
    now = int(time.time())
    body = {"iat": now, "exp": now + lifetime, "jti": uuid.uuid4().hex, **claims}
    return jwt.encode(body, private_key(), algorithm=ALGORITHM, headers={"kid": kid()})


def verify(token: str) -> dict:
    """The claims of a JWT this tool signed (``sign``), unexpired; ``jwt.PyJWTError`` if
    not (another key, tampered, expired, not a JWT)."""
    return jwt.decode(token, private_key().public_key(), algorithms=[ALGORITHM],
                      options={"require": ["exp", "iat", "jti"]})


def lecturer_key(link: str) -> str:
    """The lecturer key of the class a resource link made: the same for every launch."""
    secret = private_key().private_numbers().d.to_bytes(256, "big")
    return hmac.new(secret, f"class-key:{link}".encode(), hashlib.sha256).hexdigest()[:32]
