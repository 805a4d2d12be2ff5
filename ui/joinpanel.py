"""What a lecturer projects once a class is started — the join code, link and QR code — and
the lecturer's link, kept. After "Start" the page's own address is the lecturer's link
(``?class=CODE&key=KEY&made=1``), so a rerun (the language, projector mode) or a reload of
that browser keeps all of it on screen until the lecturer hides the join code; the link can
also be downloaded. A QR code must reach the phones: an app opened as ``localhost`` gets
this computer's network address in its join link instead, and says so."""

from __future__ import annotations

import io
import ipaddress
import os
import socket
from urllib.parse import urlsplit, urlunsplit

import segno
import streamlit as st

from ui.i18n import t

MADE = "made"  # the query parameter that shows the join panel above the class's results
LOCAL = ("localhost", "ip6-localhost")  # and any name under localhost


def page_url() -> str:
    """The class page's address as the browser sees it, without a query (its path alone
    where the browser's is not known)."""
    url = getattr(st.context, "url", "") or ""
    return url.split("?")[0].rstrip("/") or "/class"


def network_address() -> str | None:
    """This computer's address on its network (the interface a packet out would leave by;
    a UDP socket's connect sends nothing), or None where it has none but loopback."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        try:
            probe.connect(("10.254.254.254", 9))
            address = probe.getsockname()[0]
        except OSError:
            return None
    return None if ipaddress.ip_address(address).is_loopback else address


def is_local(host: str) -> bool:
    """Whether ``host`` names this computer only (a phone cannot reach it by that name)."""
    if host.lower() in LOCAL or host.lower().endswith(".localhost"):
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


def listening() -> str:
    """The address phones would reach the app on: the proxy's (deploy/start.sh names it in
    ``MEHANIZMI_PROXY_HOST``), else this process's own (Streamlit's ``server.address``;
    every interface when unset)."""
    return os.environ.get("MEHANIZMI_PROXY_HOST") or st.get_option("server.address") or "0.0.0.0"


def phones_base(url: str, listens: str, address: str | None) -> tuple[str, tuple[str, ...]]:
    """The class page's address for phones, and what the lecturer is told about it: ``url``
    itself when its host is reachable; with a local host replaced by this computer's network
    ``address`` when the server listens there; ``url`` with a warning when it cannot be."""
    parts = urlsplit(url)
    if not is_local(parts.hostname or ""):
        return url, ()
    if is_local(listens):  # (nginx on 127.0.0.1: nothing answers on the network address)
        return url, ("class.localhost", "class.localhost_listens")
    if address is None:
        return url, ("class.localhost", "class.localhost_none")
    netloc = address + (f":{parts.port}" if parts.port else "")
    return urlunsplit(parts._replace(netloc=netloc)), ("class.localhost", "class.localhost_offer")


def join_base(url: str) -> str:
    """The class page's address for phones (``phones_base``), the lecturer told why."""
    listens = listening()
    base, said = phones_base(url, listens, network_address())
    if said:
        host = urlsplit(url).hostname or ""
        icon = ":material/wifi:" if said[-1] == "class.localhost_offer" else ":material/wifi_off:"
        st.warning(" ".join(t(key, host=host, listens=listens) for key in said), icon=icon)
    return base


def join_panel(code: str, key: str) -> None:
    """The join code, link and QR code to project, and the lecturer's link to keep."""
    here = page_url()
    join = f"{join_base(here)}?join={code}"
    lecturer = f"{here}?class={code}&key={key}"
    st.markdown(f"## {t('class.code_is')}: `{code}`")
    left, right = st.columns([2, 1])
    with left:
        st.caption(t("class.join_link"))
        st.code(join, language=None)
        st.info(t("class.key_keep"), icon=":material/key:")
        with st.expander(t("class.key_show")):
            st.code(lecturer, language=None)
        st.download_button(t("class.key_download"), f"{lecturer}\n".encode(),
                           f"class-{code}-lecturer.txt", mime="text/plain", on_click="ignore",
                           icon=":material/download:")
        st.button(t("class.close_panel"), icon=":material/visibility_off:",
                  on_click=lambda: st.query_params.pop(MADE, None))
    with right:
        qr = io.BytesIO()
        segno.make(join, error="m").save(qr, kind="png", scale=12, border=2)
        st.image(qr.getvalue(), caption=t("class.qr"), width="stretch")  # large, to project
