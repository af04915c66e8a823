#!/usr/bin/env python3
"""Writes src/langnav/data/english_words.txt.gz: the lowercase English words of SCOWL's size-70 lists as Debian
ships them (packages wbritish-large and wamerican-large: /usr/share/dict/british-english-large and
american-english-large), one a line. (Size 70 rather than the usual 50: it holds the rarer words of way and
place, "abeam", "athwart", "aslant", "upwind", "downfield", "widdershins", which must never be taken for a
particle of another language; size 80 holds foreign words, "basta", "po", "lah", and is no English test.)

Proper nouns, abbreviations in capitals and possessives are left out (only words written all in lowercase
letters are kept): the offline reading asks "is this token an English word at all?" of words it does not
know (langnav.language.offline.english). SCOWL's licence (permission to use, copy, modify, distribute and
sell, with its notice kept) is in src/langnav/data/english_words.LICENSE.

Run (deterministic): apt-get install wbritish-large wamerican-large && python3 tools/make_english_words.py
"""
import gzip
import re
import sys
from pathlib import Path

SOURCES = (Path("/usr/share/dict/british-english-large"), Path("/usr/share/dict/american-english-large"))
OUT = Path(__file__).resolve().parents[1] / "src" / "langnav" / "data" / "english_words.txt.gz"
WORD = re.compile(r"[a-z]+")


def main() -> int:
    missing = [str(p) for p in SOURCES if not p.exists()]
    if missing:
        print(f"missing {', '.join(missing)}: apt-get install wbritish-large wamerican-large", file=sys.stderr)
        return 1
    words = sorted({w for p in SOURCES for w in p.read_text(encoding="utf-8").split() if WORD.fullmatch(w)})
    data = ("\n".join(words) + "\n").encode()
    OUT.write_bytes(gzip.compress(data, compresslevel=9, mtime=0))
    print(f"{len(words)} words, {OUT.stat().st_size} bytes -> {OUT}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
