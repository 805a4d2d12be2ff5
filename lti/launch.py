"""A launch's ``id_token`` checked as LTI 1.3 (the IMS Security Framework) says, before
anything is stored: the platform's signature (its JWKS fetched and cached, by key id),
``iss`` and ``aud`` of a registered platform, ``exp`` and ``iat``, the one-use ``state``
and the ``nonce`` it was issued with, a registered deployment, LTI version 1.3.0 and a
message type the tool takes. Anything else is refused in words (LtiError).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from functools import cache

import jwt

from mechanisms.messages import Text

from . import store
from .store import LtiError, Platform, web_address

CLAIM = "https://purl.imsglobal.org/spec/lti/claim/"
DEEP = "https://purl.imsglobal.org/spec/lti-dl/claim/"
AGS = "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint"
LINEITEM_SCOPE = "https://purl.imsglobal.org/spec/lti-ags/scope/lineitem"  # (to make one)
RESOURCE = "LtiResourceLinkRequest"
DEEP_LINKING = "LtiDeepLinkingRequest"
INSTRUCTOR = ("http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor",
              "http://purl.imsglobal.org/vocab/lis/v2/membership#Administrator",
              "http://purl.imsglobal.org/vocab/lis/v2/institution/person#Administrator")
LEEWAY = 60  # s of clock difference allowed between the platform and the tool
MOST = 255  # characters of an identifier (LTI: a context's and a resource link's id; OIDC: sub)
LONG = 2048  # characters of a login's hint or state (the tool's signed state is ~600)
_LOG = logging.getLogger(__name__)


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
    lineitems: str | None = None  # AGS: the platform's container, where the tool may make one
    deep_return: str | None = None  # deep linking: where the chosen link goes back to
    deep_data: str | None = None
    locale: str = "en"  # the app's language for the user: "sr" for a Serbian (or kin) locale


@cache
def _keys(jwks_url: str) -> jwt.PyJWKClient:
    """The platform's keys, fetched once and kept (fetched again for a key id not seen)."""
    return jwt.PyJWKClient(jwks_url, cache_keys=True, lifespan=3600, timeout=10)


def identifier(value, name: str, most: int = MOST) -> str:
    """The one rule for every identifier a platform sends (``iss``, ``client_id``, ``sub``,
    a deployment, a context, a resource link, a login's hints and state): text, not empty,
    at most ``most`` characters (LTI's 255 for ids), no control character — PostgreSQL
    refuses a NUL (a launch once ended in a 500 there), a newline breaks a log line.
    Refused in words (LtiError) before anything is stored."""
    if not isinstance(value, str) or not value:
        raise LtiError(Text("lti.identifier", name=name, why=Text("lti.why_empty")))
    if len(value) > most:
        raise LtiError(Text("lti.identifier", name=name, why=Text("lti.why_long", most=most)))
    if any(ord(c) < 32 or ord(c) == 127 for c in value):
        raise LtiError(Text("lti.identifier", name=name, why=Text("lti.why_control")))
    return value


def checked(id_token: str, state: str, url: str | None = None) -> Launch:
    """The launch ``id_token`` carries, checked whole — the login's ``state`` (signed by
    the tool), the platform's signature, every claim — and only then the state used up
    (a tampered token, or one carrying another login's nonce, leaves it to the honest
    launch)."""
    said = store.read_state(identifier(state, "state", LONG))
    found = store.platform_by_id(said.platform_id, url)
    try:
        key = _keys(found.jwks_url).get_signing_key_from_jwt(id_token)
        claims = jwt.decode(id_token, key.key, algorithms=["RS256"], audience=found.client_id,
                            issuer=found.issuer, leeway=LEEWAY,
                            options={"require": ["exp", "iat", "iss", "aud", "sub", "nonce"]})
    except jwt.PyJWKClientError as exc:
        _LOG.warning("a launch's keys could not be read from %s: %s", found.jwks_url, exc)
        raise LtiError(Text("lti.keys")) from None
    except jwt.PyJWTError as exc:
        _LOG.warning("a launch's token was refused: %s", exc)
        raise LtiError(Text("lti.token", why=Text("lti.why_signature"))) from None
    except (ValueError, TypeError, OSError) as exc:  # an answer that is no key set (a login page)
        _LOG.warning("a launch's keys at %s are not a JSON key set: %s", found.jwks_url,
                     str(exc)[:200])
        raise LtiError(Text("lti.keys")) from None
    launch = _launch(found, _typed(claims), said.nonce)
    store.use_state(said, url)
    return launch


# the claims the tool reads, and the type each must have: a claim of another type (a
# platform's bug, or a forged token signed by it) is refused in words, never a traceback
TYPES = {CLAIM + "custom": dict, CLAIM + "launch_presentation": dict, CLAIM + "context": dict,
         CLAIM + "resource_link": dict, CLAIM + "roles": list,
         DEEP + "deep_linking_settings": dict, AGS: dict}
INNER = {(CLAIM + "context", "id"): str, (CLAIM + "resource_link", "id"): str,
         (CLAIM + "launch_presentation", "locale"): str, (AGS, "lineitem"): str, (AGS, "lineitems"): str, (AGS, "scope"): list,
         (DEEP + "deep_linking_settings", "deep_link_return_url"): str}


def _typed(claims: dict) -> dict:
    """``claims``, each one the tool reads of the type it reads it as (LtiError if not)."""
    for name, kind in TYPES.items():
        if claims.get(name) is not None and not isinstance(claims[name], kind):
            raise LtiError(Text("lti.token", why=Text("lti.why_claim", claim=name.rsplit("/", 1)[-1])))
    for (name, part), kind in INNER.items():
        value = (claims.get(name) or {}).get(part)
        if value is not None and not isinstance(value, kind):
            raise LtiError(Text("lti.token", why=Text("lti.why_claim", claim=f"{name.rsplit('/', 1)[-1]}.{part}")))
    custom = claims.get(CLAIM + "custom") or {}
    if not all(isinstance(v, (str, int, float, bool)) for v in custom.values()):
        raise LtiError(Text("lti.token", why=Text("lti.why_claim", claim="custom")))
    if not all(isinstance(role, str) for role in claims.get(CLAIM + "roles") or []):
        raise LtiError(Text("lti.token", why=Text("lti.why_claim", claim="roles")))
    return claims


def _launch(found: Platform, claims: dict, nonce: str) -> Launch:
    """The claims of a signed, unexpired token for this tool, held to LTI's rules."""
    if claims.get("nonce") != nonce:
        raise LtiError(Text("lti.token", why=Text("lti.why_nonce")))
    sub = identifier(claims["sub"], "sub")
    azp = claims.get("azp")
    if azp is not None and azp != found.client_id:
        raise LtiError(Text("lti.token", why=Text("lti.why_azp")))
    deployment = identifier(str(claims.get(CLAIM + "deployment_id", "")), "deployment_id")
    if deployment not in found.deployments:
        raise LtiError(Text("lti.deployment", deployment=deployment or "—"))
    if claims.get(CLAIM + "version") != "1.3.0":
        raise LtiError(Text("lti.token", why=Text("lti.why_version")))
    kind = claims.get(CLAIM + "message_type")
    if kind not in (RESOURCE, DEEP_LINKING):
        raise LtiError(Text("lti.token", why=Text("lti.why_message", kind=str(kind)[:40])))
    roles = claims.get(CLAIM + "roles") or []
    context = (claims.get(CLAIM + "context") or {}).get("id")
    context = "" if context is None else identifier(context, "context.id")
    link = (claims.get(CLAIM + "resource_link") or {}).get("id")
    if kind == RESOURCE and not link:
        raise LtiError(Text("lti.token", why=Text("lti.why_link")))
    link = "" if link is None else identifier(link, "resource_link.id")
    deep = claims.get(DEEP + "deep_linking_settings") or {}
    if deep.get("deep_link_return_url") is not None:
        web_address(deep["deep_link_return_url"], "deep_link_return_url")
    ags = claims.get(AGS) or {}
    for name in ("lineitem", "lineitems"):
        if ags.get(name) is not None:
            web_address(ags[name], name)
    return Launch(found, deployment, kind, sub,
                  any(role in INSTRUCTOR for role in roles), str(context), str(link),
                  {k: str(v) for k, v in (claims.get(CLAIM + "custom") or {}).items()},
                  ags.get("lineitem"),
                  ags.get("lineitems") if LINEITEM_SCOPE in (ags.get("scope") or []) else None,
                  deep.get("deep_link_return_url"), deep.get("data"),
                  "sr" if _locale(claims).startswith(("sr", "bs", "hr", "me")) else "en")


def _locale(claims: dict) -> str:
    """The user's language: the launch presentation's locale (where Moodle puts it), or
    OpenID's ``locale``."""
    shown = (claims.get(CLAIM + "launch_presentation") or {}).get("locale")
    return str(shown or claims.get("locale") or "").lower()
