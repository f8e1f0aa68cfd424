"""A scheduler address that fails leaves nothing behind: the half-built
client is stopped at once, so no "Exception ignored in Client.__del__"
traceback follows the one-line error 10 s later at exit (the command's
__del__ finds it closed); --help says how long the command waits."""

import gc

import pytest

from deathsphere import cluster
from deathsphere.params import ParameterError

distributed = pytest.importorskip("distributed", reason="the distributed extra is not installed")


def _clients() -> dict:
    return {id(o): o for o in gc.get_objects() if isinstance(o, distributed.Client)}


@pytest.mark.parametrize("address, words", [
    ("http://x", "is not a scheduler address"),
    ("bad address", "missing port"),
])
def test_a_bad_address_is_one_line_and_its_client_is_closed(address, words):
    before = _clients()
    with pytest.raises(ParameterError, match=words) as caught:
        cluster.connect(address)
    assert "\n" not in str(caught.value)
    left = [c for i, c in _clients().items() if i not in before]
    assert left and all(c.status == "closed" for c in left)


def test_help_says_how_long_it_waits(run):
    out = " ".join(run("sweep", "--help").output.split())
    assert f"within {cluster.CONNECT_TIMEOUT_S} s" in out
