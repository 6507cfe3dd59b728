"""The fingerprint of the paper's source that quotes are checked against (obslib.claims.quotes):
windows hashed independently here, contiguity, word boundaries."""

import hashlib

import pytest

from obslib.claims import quotes


def test_fingerprint_is_sha256_of_every_four_word_window():
    text = "alpha beta % a comment\\n gamma\n\\% delta epsilon  zeta"
    ws = ["alpha", "beta", "gamma", "\\%", "delta", "epsilon", "zeta"]
    # the comment runs to the end of its line; an escaped percent sign is a word
    text = "alpha beta % a comment\n gamma \\% delta epsilon  zeta"
    assert quotes.words(text, latex=True) == ws
    want = [hashlib.sha256(" ".join(ws[i:i + 4]).encode()).hexdigest()[:8] for i in range(4)]
    assert quotes.fingerprint(text) == want


def test_quotes_are_contiguous_whole_words_of_the_paper():
    assert quotes.found("Around $k=50$, the best pair changes frequently")
    # the same words out of order, a word changed, a word cut short: not the paper's
    assert not quotes.found("the best pair changes frequently Around $k=50$,")
    assert not quotes.found("Around $k=50$, the best pair changes rarely")
    assert not quotes.found("Around $k=50$, the best pair changes freq")
    # white space does not matter
    assert quotes.found("Around   $k=50$,\n the best pair changes   frequently")
    # commented-out text of the source is not the paper's
    assert not quotes.found("We first consider the simple case when the target")


def test_a_quote_has_four_words():
    with pytest.raises(ValueError, match="at least 4 words"):
        quotes.found("the best pair")


def test_the_data_file_states_its_provenance():
    head = quotes.DATA.read_text().splitlines()[:6]
    assert any("arXiv:1706.00871" in line for line in head)
    assert any("python -m obslib.claims.quotes" in line for line in head)
