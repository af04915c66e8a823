"""Whether a word is an English word at all: the lowercase words of SCOWL's size-70 lists (about 115,000, with
their inflections), as Debian's wbritish-large and wamerican-large ship them, in ``langnav/data/english_words.txt.gz``
(made by ``tools/make_english_words.py``; licence beside it). Proper nouns and capitalised abbreviations are
not in it, so "po", "konti" or "yalla" (Tagalog and Arabic particles) are not English words here; "lang" (Scots
for "long") and "ja" are.

The offline reading knows a few hundred words; a word it does not know may still be English ("diagonally",
"uphill", "easy"), and an English word it does not know may say which way or how far: such a word is never
taken for a particle of another language (``particles``).
"""

from __future__ import annotations

import gzip
from functools import lru_cache
from importlib import resources
from typing import Final

#: The word list inside the package.
WORDS_FILE: Final = "english_words.txt.gz"


@lru_cache(maxsize=1)
def english_words() -> frozenset[str]:
    """The lowercase English words (read once per process)."""
    data = (resources.files("langnav") / "data" / WORDS_FILE).read_bytes()
    return frozenset(gzip.decompress(data).decode("utf-8").split())


def is_english(word: str) -> bool:
    """Whether ``word`` (any case) is an English word written in lowercase letters in SCOWL's lists."""
    return word.lower() in english_words()
