"""What a lecturer projects once a class is started — the join code, link and QR code — and
the lecturer's link, kept. After "Start" the page's own address is the lecturer's link
(``?class=CODE&key=KEY&made=1``), so a rerun (the language, projector mode) or a reload of
that browser keeps all of it on screen until the lecturer hides the join code; the link can
also be downloaded. A QR code must reach the phones: an app opened as ``localhost`` gets
this computer's network address in its join link instead, and says so."""

from __future__ import annotations

import io
import ipaddress
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


def join_base(url: str) -> str:
    """The class page's address for phones: ``url`` itself, or with a local host replaced by
    this computer's network address (the lecturer is told either way)."""
    parts = urlsplit(url)
    host = parts.hostname or ""
    if not is_local(host):
        return url
    address = network_address()
    if address is None:
        st.warning(t("class.localhost", host=host) + " " + t("class.localhost_none", host=host),
                   icon=":material/wifi_off:")
        return url
    st.warning(t("class.localhost", host=host) + " " + t("class.localhost_offer"),
               icon=":material/wifi:")
    netloc = address + (f":{parts.port}" if parts.port else "")
    return urlunsplit(parts._replace(netloc=netloc))


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
