"""The tool's routes, mounted beside the app on its own server (``asgi.py``):

- ``GET /lti/jwks``: the tool's public key (lti/keys.py);
- ``GET|POST /lti/login``: OIDC third-party initiated login — a one-use state and nonce,
  then to the platform's authorisation URL;
- ``POST /lti/launch``: the ``id_token`` checked (lti/launch.py); a learner goes (303) to
  the method's page, practice on in the link's class; an instructor to the class's live
  view; a deep-linking request to a form where the task and method are picked;
- ``POST /lti/deeplink``: the picked link, signed by the tool, posted back to the platform.

A refusal is a short page in words (Serbian and English: no language is known before a
launch is checked), with a 4xx status; nothing is stored for it.
"""

from __future__ import annotations

import functools
import html
import json
import logging
import os
import secrets
import urllib.parse
from collections.abc import Awaitable, Callable

import jwt
from starlette.datastructures import FormData
from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, RedirectResponse, Response
from starlette.routing import Route

from classes.steps import practice_link
from classes.store import METHODS, ClassError, StoreDown, find
from mechanisms import SceneError, load_preset, preset_ids
from mechanisms.messages import KEEP, Text, strings
from methods.practice_steps import steps_for

from . import keys, store
from .launch import CLAIM, DEEP, DEEP_LINKING, LONG, MOST, Launch, checked, identifier
from .store import LtiError

MAX_BODY = 256 * 1024  # bytes a platform's form may have (a launch's id_token is a few kB)
MAX_FIELDS = 40  # fields a platform's form may have (a launch sends two)
PICKED = "plans"  # the picker's method until the lecturer chooses another
_LOG = logging.getLogger(__name__)
PICKER_STYLE = ("body{font-family:'Source Sans Pro',system-ui,sans-serif;max-width:44rem;"
                "margin:2rem auto;padding:0 1rem;color:#262730}h1{font-size:1.5rem}"
                "label{display:block;font-weight:600}select{display:block;width:100%;"
                "margin-top:.3rem;padding:.4rem;font:inherit;font-weight:400}button{background:#ff4b4b;"
                "color:#fff;border:0;border-radius:.5rem;padding:.5rem 1.2rem;font:inherit}")


def base_url(request: Request) -> str:
    """The tool's address as users reach it: ``MEHANIZMI_BASE_URL`` where it is set, else
    the address the proxy says the user reached (``X-Forwarded-Proto``/``-Host``, port
    included: deploy/nginx.conf.in sends ``$http_host``), else the request's own."""
    if os.environ.get("MEHANIZMI_BASE_URL"):
        return os.environ["MEHANIZMI_BASE_URL"].rstrip("/")
    host = request.headers.get("x-forwarded-host", "").split(",")[0].strip()
    proto = request.headers.get("x-forwarded-proto", "").split(",")[0].strip()
    if host and proto in ("http", "https") and not any(c in host for c in "/\\@ "):
        return f"{proto}://{host}"
    return str(request.base_url).rstrip("/")


def refused(said: Text | str, status: int = 400, language: str | None = None) -> HTMLResponse:
    """A refusal in words: in the user's language once a launch said it, else in Serbian and
    in English (no language is known before a launch is checked)."""
    def said_in(language: str) -> str:
        if isinstance(said, str):
            return said
        return said.render(lambda key: KEEP.sub(r"\1", strings(language)[key]),
                           comma=language == "sr")
    languages = (language,) if language in ("sr", "en") else ("sr", "en")
    body = "".join(f"<p>{html.escape(said_in(language))}</p>" for language in languages)
    return HTMLResponse(f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>Mehanizmi</title>"
                        f"</head><body>{body}</body></html>", status_code=status)


class Refused(Exception):
    """A request refused before it is read: its answer, in words."""

    def __init__(self, answer: HTMLResponse):
        super().__init__(answer.status_code)
        self.answer = answer


async def form_of(request: Request) -> FormData:
    """The request's form, read within bounds: a body over ``MAX_BODY`` (said by its length
    or found while reading), more than ``MAX_FIELDS`` fields, a file, or a form that cannot
    be parsed is refused in words (``Refused``), never in the server's plain text."""
    length = request.headers.get("content-length", "")
    if length and (not length.isdigit() or int(length) > MAX_BODY):
        raise Refused(refused(Text("lti.too_large", kb=MAX_BODY // 1024), 413))
    body = b""
    async for chunk in request.stream():
        body += chunk
        if len(body) > MAX_BODY:
            raise Refused(refused(Text("lti.too_large", kb=MAX_BODY // 1024), 413))

    async def replay() -> dict:
        return {"type": "http.request", "body": body, "more_body": False}

    try:
        return await Request(request.scope, replay).form(max_fields=MAX_FIELDS, max_files=0,
                                                         max_part_size=MAX_BODY)
    except (HTTPException, ValueError, KeyError) as exc:
        _LOG.warning("a form refused: %s", exc)
        raise Refused(refused(Text("lti.form_bad"), 400)) from None


def answered(route: Callable[[Request], Awaitable[Response]]) -> Callable[[Request], Awaitable[Response]]:
    """``route`` with a request refused while being read (``Refused``) answered in words."""
    @functools.wraps(route)
    async def answer(request: Request) -> Response:
        try:
            return await route(request)
        except Refused as exc:
            return exc.answer
    return answer


async def jwks(request: Request) -> Response:
    return JSONResponse(keys.jwks(), headers={"Cache-Control": "public, max-age=3600"})


async def login(request: Request) -> Response:
    given = dict(request.query_params)
    if request.method == "POST":
        given.update(dict(await form_of(request)))
    issuer, hint = given.get("iss", ""), given.get("login_hint", "")
    if not issuer or not hint:
        return refused(Text("lti.login_missing"))
    try:
        for name, most in (("iss", MOST), ("client_id", MOST), ("login_hint", LONG),
                           ("lti_message_hint", LONG)):
            if name in given:
                identifier(given[name], name, most)
        found = store.platform(issuer, given.get("client_id"))
        state, nonce = store.new_state(found)
    except LtiError as exc:
        return refused(exc.args[0])
    except StoreDown as exc:
        return refused(exc.args[0], 503)
    query = {"scope": "openid", "response_type": "id_token", "response_mode": "form_post",
             "prompt": "none", "client_id": found.client_id,
             "redirect_uri": f"{base_url(request)}/lti/launch", "login_hint": hint,
             "state": state, "nonce": nonce}
    if given.get("lti_message_hint"):
        query["lti_message_hint"] = given["lti_message_hint"]
    joiner = "&" if "?" in found.auth_url else "?"
    return RedirectResponse(f"{found.auth_url}{joiner}{urllib.parse.urlencode(query)}", 302)


async def launch(request: Request) -> Response:
    form = await form_of(request)
    id_token, state = str(form.get("id_token", "")), str(form.get("state", ""))
    if not id_token or not state:
        return refused(Text("lti.launch_missing"))
    try:
        said = checked(id_token, state)
    except LtiError as exc:
        return refused(exc.args[0], STATUS.get(exc.args[0].key, 400))
    except StoreDown as exc:
        return refused(exc.args[0], 503)
    try:  # (a checked launch: its refusals in the user's language alone)
        return picker(request, said) if said.kind == DEEP_LINKING else go(request, said)
    except StoreDown as exc:
        return refused(exc.args[0], 503, said.locale)
    except ClassError as exc:  # the link's task, or a closed test's new learner
        return refused(exc.args[0], STATUS.get(exc.args[0].key, 400), said.locale)


# a launch's refusals that are not the platform's or the user's request being wrong
STATUS = {"lti.token": 401, "lti.state": 401, "lti.keys": 502}


def go(request: Request, said: Launch) -> Response:
    """A resource link's launch: its class (made at its first launch), then a learner to
    practise, an instructor to the class's live view."""
    task, method = said.custom.get("task", ""), said.custom.get("method", "")
    scene, _ = practised(task, method)
    test = str(said.custom.get("test", "")).lower() in ("1", "true", "yes")
    link = store.link_class(said.platform, said.context, said.resource_link, task, method, test=test)
    if said.lineitem is None and said.lineitems:  # (added by hand: its grades need a line item)
        store.wants_lineitem(link, said.lineitems, activity_name(scene, method, said.locale == "sr"))
    base = base_url(request)
    if said.instructor:
        query = urllib.parse.urlencode({"class": link.class_code, "key": link.key,
                                        "lang": said.locale})
        return RedirectResponse(f"{base}/class?{query}", 303)
    token = store.learner(link, said.sub, said.lineitem)
    page, params = practice_link(find(link.class_code), token, said.locale)
    return RedirectResponse(f"{base}/{page}?{urllib.parse.urlencode(params)}", 303)


def practised(task: str, method: str) -> tuple[object, list]:
    """A link's task (its scene) and the steps its method has there; LtiError in words
    when they cannot be practised."""
    if method not in METHODS:
        raise LtiError(Text("lti.no_method", method=method or "—", methods=", ".join(METHODS)))
    if task not in preset_ids():
        raise LtiError(Text("lti.no_task", task=shortened(task) or "—", why=Text("lti.why_no_preset")))
    scene = load_preset(task)
    steps = _steps(scene, method)
    if not steps:
        raise LtiError(Text("lti.no_task", task=task, why=Text("lti.why_no_steps")))
    return scene, steps


def shortened(text: str, most: int = 60) -> str:
    """What a platform or a user sent, as a refusal quotes it: cut to ``most`` characters."""
    return text if len(text) <= most else text[:most] + "…"


def _steps(scene, method: str) -> list:
    """``method``'s steps on ``scene``; none when the scene is not of the method's kind."""
    try:
        return steps_for(scene, method)
    except SceneError:  # (a gear train has no plans)
        return []


@functools.cache
def pairs() -> dict[str, tuple[str, ...]]:
    """Each task's methods that have steps there: all the picker offers (worked out once,
    about 2 s, at the first deep linking)."""
    return {task: tuple(m for m in METHODS if _steps(load_preset(task), m)) for task in preset_ids()}


def picker(request: Request, said: Launch) -> Response:
    """Deep linking: the instructor picks a task and a method; the platform's return URL,
    deployment and data travel signed by the tool (a changed field is refused)."""
    if not said.instructor or not said.deep_return:
        return refused(Text("lti.deep_not_allowed"), 403)
    context = keys.sign({"platform": said.platform.id, "deployment": said.deployment,
                         "return": said.deep_return, "data": said.deep_data,
                         "locale": said.locale}, lifetime=3600)
    sr = said.locale == "sr"
    offered = {task: methods for task, methods in pairs().items() if methods}
    titles = {p: title(load_preset(p), sr) for p in offered}
    tasks = "".join(f"<option value='{html.escape(p)}'>{html.escape(titles[p])}</option>"
                    for p in sorted(titles))
    first = offered[min(titles)]
    methods = "".join(f"<option value='{m}'{' selected' if m == PICKED else ''}>"
                      f"{html.escape(method_name(m, sr))}</option>" for m in first)
    names = {m: method_name(m, sr) for m in METHODS}
    words = strings("sr" if sr else "en")
    # the method list follows the task: only pairs that have steps (the server refuses others)
    follow = ("<script>const pairs=" + json.dumps(offered) + ",names=" + json.dumps(names) +
              ";const t=document.querySelector('[name=task]'),m=document.querySelector('[name=method]');"
              "t.addEventListener('change',()=>{const was=m.value;m.replaceChildren(...pairs[t.value]"
              ".map(v=>new Option(names[v],v,false,v===was||(v==='" + PICKED + "'&&!pairs[t.value]"
              ".includes(was)))))});</script>")
    return HTMLResponse(
        "<!DOCTYPE html><html><head><meta charset='utf-8'><title>Mehanizmi</title>"
        f"<meta name='viewport' content='width=device-width'><style>{PICKER_STYLE}</style></head><body>"
        f"<h1>{html.escape(words['lti.pick_title'])}</h1>"
        f"<form method='post' action='{base_url(request)}/lti/deeplink'>"
        f"<input type='hidden' name='context' value='{context}'>"
        f"<p><label>{html.escape(words['lti.pick_task'])} <select name='task'>{tasks}</select></label></p>"
        f"<p><label>{html.escape(words['lti.pick_method'])} <select name='method'>{methods}</select></label></p>"
        f"<p><label><input type='checkbox' name='test' value='1'> {html.escape(words['lti.pick_test'])}</label></p>"
        f"<p><button type='submit'>{html.escape(words['lti.pick_add'])}</button></p>"
        f"</form>{follow}</body></html>")


def title(scene, serbian: bool) -> str:
    """"id — title" of a preset, in Serbian where it has a Serbian title."""
    return f"{scene.id} — {(scene.title_sr if serbian and getattr(scene, 'title_sr', '') else scene.title)}"


def activity_name(scene, method: str, serbian: bool) -> str:
    """An activity's name and its grade's label: "method: id — title"."""
    return f"{method_name(method, serbian)}: {title(scene, serbian)}"


def method_name(method: str, serbian: bool) -> str:
    return KEEP.sub(r"\1", strings("sr" if serbian else "en")[f"class.method_{method}"])


async def deeplink(request: Request) -> Response:
    """The picked task and method, back to the platform as a signed deep-linking response:
    one ``ltiResourceLink`` with them as custom parameters, and a line item for its grade."""
    form = await form_of(request)
    try:
        context = jwt.decode(str(form.get("context", "")), keys.private_key().public_key(),
                             algorithms=[keys.ALGORITHM])
        found = store.platform_by_id(int(context["platform"]))
    except (jwt.PyJWTError, KeyError, ValueError):
        return refused(Text("lti.deep_context"), 400)
    except LtiError as exc:
        return refused(exc.args[0])
    task, method = str(form.get("task", "")), str(form.get("method", ""))
    test = form.get("test") == "1"
    serbian = context.get("locale") == "sr"
    try:
        scene, steps = practised(task, method)
    except LtiError:  # (the picker offers only pairs that work: a changed form)
        return refused(Text("lti.deep_pair", task=shortened(task) or "—",
                            method=Text(f"class.method_{method}") if method in METHODS
                            else shortened(method, 20) or "—"), language="sr" if serbian else "en")
    name = activity_name(scene, method, serbian)
    claims = {"iss": found.client_id, "aud": found.issuer, "azp": found.client_id,
              "nonce": secrets.token_urlsafe(16),
              CLAIM + "message_type": "LtiDeepLinkingResponse", CLAIM + "version": "1.3.0",
              CLAIM + "deployment_id": context["deployment"],
              DEEP + "content_items": [{
                  "type": "ltiResourceLink", "title": name,
                  "url": f"{base_url(request)}/lti/launch",
                  "custom": {"task": task, "method": method, **({"test": "1"} if test else {})},
                  "lineItem": {"scoreMaximum": len(steps), "label": name}}]}
    if context.get("data"):
        claims[DEEP + "data"] = context["data"]
    response = keys.sign(claims)
    return HTMLResponse(
        "<!DOCTYPE html><html><head><meta charset='utf-8'><title>Mehanizmi</title></head>"
        "<body onload='document.forms[0].submit()'>"
        f"<form method='post' action='{html.escape(context['return'])}'>"
        f"<input type='hidden' name='JWT' value='{response}'>"
        "<noscript><button type='submit'>OK</button></noscript></form></body></html>")


async def too_large(request: Request) -> Response:
    """What nginx shows for an LTI form over its limit (deploy/nginx.conf.in's error page)."""
    return refused(Text("lti.too_large", kb=MAX_BODY // 1024), 413)


async def posted_only(request: Request) -> Response:
    """A launch or deep-linking address opened as a page (GET): said in words, 405 — not
    the app's blank page."""
    return refused(Text("lti.method"), 405)


class Unknown:
    """Any other address under /lti/, or a method no route of its address takes (OPTIONS,
    an unknown verb): said in words, 404 or 405 — not the app's page (a GET once answered
    200 with it), not the server's plain text. An ASGI app rather than a function, so that
    its route takes every method (a function's route takes only those it names)."""

    async def __call__(self, scope, receive, send) -> None:
        known = {route.path for route in ROUTES if route.path != "/lti/{rest:path}"}
        answer = (refused(Text("lti.not_this_method", method=scope["method"][:12]), 405)
                  if scope["path"] in known else refused(Text("lti.unknown"), 404))
        await answer(scope, receive, send)


ROUTES = [Route("/lti/jwks", jwks, methods=["GET"]),
          Route("/lti/login", answered(login), methods=["GET", "POST"]),
          Route("/lti/login", posted_only, methods=["PUT", "DELETE", "PATCH"]),
          Route("/lti/too-large", too_large, methods=["GET", "POST"]),
          Route("/lti/launch", answered(launch), methods=["POST"]),
          Route("/lti/launch", posted_only, methods=["GET", "HEAD", "PUT", "DELETE", "PATCH"]),
          Route("/lti/deeplink", answered(deeplink), methods=["POST"]),
          Route("/lti/deeplink", posted_only, methods=["GET", "HEAD", "PUT", "DELETE", "PATCH"]),
          Route("/lti/{rest:path}", Unknown())]
