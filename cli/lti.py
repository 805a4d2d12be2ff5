"""``python -m solvers lti platform add | list | remove`` and ``lti tool``: the app as an LTI
1.3 tool (docs/lti.md) — a Moodle site registered once, and what to paste into its
"Manage tools" form."""

from __future__ import annotations

import json

from lti import keys
from lti import store as lti


def add(sub) -> None:
    """The ``lti`` command and its subcommands."""
    p = sub.add_parser("lti", help="the app as an LTI 1.3 tool: platforms, and the tool's "
                                   "URLs for Moodle (docs/lti.md)")
    verbs = p.add_subparsers(dest="verb", required=True)
    v = verbs.add_parser("platform", help="register, list or remove a platform (a Moodle site)")
    what = v.add_subparsers(dest="what", required=True)
    a = what.add_parser("add", help="register a platform, or add a deployment to one")
    for name, text in (("issuer", "the platform's issuer (Moodle: its wwwroot)"),
                       ("client-id", "the client ID Moodle gave the tool"),
                       ("deployment", "the deployment ID Moodle gave the tool"),
                       ("auth-url", "Moodle: …/mod/lti/auth.php"),
                       ("token-url", "Moodle: …/mod/lti/token.php"),
                       ("jwks-url", "Moodle: …/mod/lti/certs.php")):
        a.add_argument(f"--{name}", required=True, help=text)
    a.set_defaults(run=_add)
    listed = what.add_parser("list", help="the platforms registered, as JSON lines")
    listed.set_defaults(run=_list)
    r = what.add_parser("remove", help="forget a platform and its links (their classes expire)")
    r.add_argument("--issuer", required=True)
    r.add_argument("--client-id", required=True)
    r.set_defaults(run=_remove)
    t = verbs.add_parser("tool", help="what to paste into Moodle's Manage tools")
    t.add_argument("--base-url", required=True, help="the app's address as users reach it")
    t.add_argument("--json", action="store_true")
    t.set_defaults(run=_tool)


def _add(args) -> int:
    found = lti.add_platform(args.issuer, args.client_id, args.deployment, args.auth_url,
                             args.token_url, args.jwks_url)
    print(f"registered {found.issuer} (client {found.client_id}); deployments: "
          f"{', '.join(found.deployments)}")
    return 0


def _list(args) -> int:
    for found in lti.all_platforms():
        print(json.dumps({"issuer": found.issuer, "client_id": found.client_id,
                          "deployments": list(found.deployments), "auth_url": found.auth_url,
                          "token_url": found.token_url, "jwks_url": found.jwks_url}))
    return 0


def _remove(args) -> int:
    if not lti.remove_platform(args.issuer, args.client_id):
        print(f"no platform {args.issuer} with client {args.client_id}")
        return 2
    print(f"removed {args.issuer} (client {args.client_id})")
    return 0


def _tool(args) -> int:
    base = args.base_url.rstrip("/")
    said = {"Tool URL": f"{base}/lti/launch", "Initiate login URL": f"{base}/lti/login",
            "Redirection URI(s)": f"{base}/lti/launch", "Public keyset URL": f"{base}/lti/jwks",
            "Supports Deep Linking (Content-Item Message)": "yes",
            "Content Selection URL": f"{base}/lti/launch", "kid": keys.kid()}
    if args.json:
        print(json.dumps(said))
    else:
        for name, value in said.items():
            print(f"{name}: {value}")
    return 0
