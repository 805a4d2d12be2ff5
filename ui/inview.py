"""Bring what a tap just changed into view: on a phone, a typed step's verdict grew under the
Check button past the screen's bottom (and, put above the button, it landed above the
screen's top: the browser keeps what the thumb touched in place)."""

from __future__ import annotations

import json

import streamlit as st

_JS = """
export default function ({ data }) {
  const { selector, token } = JSON.parse(data);
  if (window.__mehanizmiInView === token) return;
  window.__mehanizmiInView = token;
  requestAnimationFrame(() => {
    const target = document.querySelector(selector);
    if (target) target.scrollIntoView({ block: "nearest" });
  });
}
"""
_render = st.components.v2.component("mehanizmi_in_view", js=_JS)


def into_view(selector: str, token: str, key: str) -> None:
    """Scroll the element ``selector`` just into view, once per ``token`` (a new token: a
    new event to show; the same token again, as every other rerun sends it, does nothing)."""
    _render(key=key, data=json.dumps({"selector": selector, "token": token}))
