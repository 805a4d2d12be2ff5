"""The join link a lecturer projects names an address phones can reach, or says why it
cannot (issue 69: behind deploy/start.sh's nginx on 127.0.0.1 it named the network
address, where nothing answered, and said phones could use it)."""

import pytest

from ui.joinpanel import phones_base
from ui.i18n import t


@pytest.mark.parametrize("url, listens, address, base, said", [
    ("http://10.0.0.5:8080/class", "127.0.0.1", "10.0.0.5", "http://10.0.0.5:8080/class", ()),
    ("http://localhost:8501/class", "0.0.0.0", "10.0.0.5", "http://10.0.0.5:8501/class",
     ("class.localhost", "class.localhost_offer")),
    ("http://localhost:8080/class", "127.0.0.1", "10.0.0.5", "http://localhost:8080/class",
     ("class.localhost", "class.localhost_listens")),
    ("http://127.0.0.1:8080/class", "localhost", "10.0.0.5", "http://127.0.0.1:8080/class",
     ("class.localhost", "class.localhost_listens")),
    ("http://localhost:8501/class", "0.0.0.0", None, "http://localhost:8501/class",
     ("class.localhost", "class.localhost_none")),
])
def test_the_join_link_names_an_address_the_server_listens_on(url, listens, address, base, said):
    assert phones_base(url, listens, address) == (base, said)


def test_a_server_on_loopback_alone_says_how_to_open_it_to_phones():
    text = t("class.localhost_listens", listens="127.0.0.1")
    assert "HOST=0.0.0.0 deploy/start.sh" in text and "127.0.0.1" in text
