"""A choice widget whose value lives in the URL as its plain code (``?lang=sr``, ``?scene=zbirka-1.3``).

Streamlit's own ``bind="query-params"`` keeps a choice's *displayed label* in the URL, which
would put translated text and long titles in shared links, and a link would break when
the language changes. These choices keep the option itself instead.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import streamlit as st


def url_choice(widget: Callable, label: str, options: Sequence[str], key: str,
               default: str | None = None, **kwargs) -> str:
    """``widget`` (st.selectbox, st.radio, …) seeded from ``?key=`` and writing it back."""
    default = options[0] if default is None else default
    if key not in st.session_state or st.session_state[key] not in options:
        wanted = st.query_params.get(key)
        st.session_state[key] = wanted if wanted in options else default
    value = widget(label, options, key=key, **kwargs)
    st.query_params[key] = value
    return value


def seed(defaults: dict[str, object], scene: str) -> None:
    """Give the page's widgets their values for ``scene``, before they are drawn.

    On the first run a value may come from the link (``?omega=5``) and is kept; when the
    user picks another scene, every widget takes that scene's default, so a link never
    carries one scene's lengths into another. Widgets are then created without ``value=``.
    """
    previous = st.session_state.get("_seeded_for")
    st.session_state["_seeded_for"] = scene
    changed = previous is not None and previous != scene
    for key, value in defaults.items():
        if changed or (key not in st.session_state and key not in st.query_params):
            st.session_state[key] = value
