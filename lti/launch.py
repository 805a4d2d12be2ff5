"""A launch's ``id_token`` checked as LTI 1.3 (the IMS Security Framework) says, before
anything is stored: the platform's signature (its JWKS fetched and cached, by key id),
``iss`` and ``aud`` of a registered platform, ``exp`` and ``iat``, the one-use ``state``
and the ``nonce`` it was issued with, a registered deployment, LTI version 1.3.0 and a
message type the tool takes. Anything else is refused in words (LtiError).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cache

import jwt

from mechanisms.messages import Text

from . import store
from .store import LtiError, Platform

CLAIM = "https://purl.imsglobal.org/spec/lti/claim/"
DEEP = "https://purl.imsglobal.org/spec/lti-dl/claim/"
AGS = "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint"
RESOURCE = "LtiResourceLinkRequest"
DEEP_LINKING = "LtiDeepLinkingRequest"
INSTRUCTOR = ("http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor",
              "http://purl.imsglobal.org/vocab/lis/v2/membership#Administrator",
              "http://purl.imsglobal.org/vocab/lis/v2/institution/person#Administrator")
LEEWAY = 60  # s of clock difference allowed between the platform and the tool


@dataclass(frozen=True)
class Launch:
    """What the tool keeps of a checked launch (a user's ``sub`` and role, never a name)."""

    platform: Platform
    deployment: str
    kind: str  # RESOURCE or DEEP_LINKING
    sub: str
    instructor: bool
    context: str
    resource_link: str
    custom: dict = field(default_factory=dict)
    lineitem: str | None = None  # AGS: where this link's scores go
    deep_return: str | None = None  # deep linking: where the chosen link goes back to
    deep_data: str | None = None
    locale: str = "en"  # the app's language for the user: "sr" for a Serbian (or kin) locale


@cache
def _keys(jwks_url: str) -> jwt.PyJWKClient:
    """The platform's keys, fetched once and kept (fetched again for a key id not seen)."""
    return jwt.PyJWKClient(jwks_url, cache_keys=True, lifespan=3600, timeout=10)


def checked(id_token: str, state: str, url: str | None = None) -> Launch:
    """The launch ``id_token`` carries, checked; ``state`` (the login's) is used up."""
    platform_id, nonce = store.take_state(state, url)
    found = store.platform_by_id(platform_id, url)
    try:
        key = _keys(found.jwks_url).get_signing_key_from_jwt(id_token)
        claims = jwt.decode(id_token, key.key, algorithms=["RS256"], audience=found.client_id,
                            issuer=found.issuer, leeway=LEEWAY,
                            options={"require": ["exp", "iat", "iss", "aud", "sub", "nonce"]})
    except jwt.PyJWKClientError as exc:
        raise LtiError(Text("lti.token", why=f"the platform's keys: {exc}")) from None
    except jwt.PyJWTError as exc:
        raise LtiError(Text("lti.token", why=str(exc))) from None
    return _launch(found, claims, nonce)


def _launch(found: Platform, claims: dict, nonce: str) -> Launch:
    """The claims of a signed, unexpired token for this tool, held to LTI's rules."""
    if claims.get("nonce") != nonce:
        raise LtiError(Text("lti.token", why="the nonce is not the login's"))
    azp = claims.get("azp")
    if azp is not None and azp != found.client_id:
        raise LtiError(Text("lti.token", why="azp is another client"))
    deployment = str(claims.get(CLAIM + "deployment_id", ""))
    if deployment not in found.deployments:
        raise LtiError(Text("lti.deployment", deployment=deployment or "—"))
    if claims.get(CLAIM + "version") != "1.3.0":
        raise LtiError(Text("lti.token", why="LTI version is not 1.3.0"))
    kind = claims.get(CLAIM + "message_type")
    if kind not in (RESOURCE, DEEP_LINKING):
        raise LtiError(Text("lti.token", why=f"message type {kind!r} is not one this tool takes"))
    roles = claims.get(CLAIM + "roles") or []
    context = (claims.get(CLAIM + "context") or {}).get("id", "")
    link = (claims.get(CLAIM + "resource_link") or {}).get("id", "")
    if kind == RESOURCE and not link:
        raise LtiError(Text("lti.token", why="no resource link"))
    deep = claims.get(DEEP + "deep_linking_settings") or {}
    ags = claims.get(AGS) or {}
    return Launch(found, deployment, kind, str(claims["sub"]),
                  any(role in INSTRUCTOR for role in roles), str(context), str(link),
                  dict(claims.get(CLAIM + "custom") or {}), ags.get("lineitem"),
                  deep.get("deep_link_return_url"), deep.get("data"),
                  "sr" if _locale(claims).startswith(("sr", "bs", "hr", "me")) else "en")


def _locale(claims: dict) -> str:
    """The user's language: the launch presentation's locale (where Moodle puts it), or
    OpenID's ``locale``."""
    shown = (claims.get(CLAIM + "launch_presentation") or {}).get("locale")
    return str(shown or claims.get("locale") or "").lower()
