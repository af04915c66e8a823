"""Words of another language said with an English instruction: discourse particles and fillers.

People who speak English as one of several languages carry the small words of their other language into it:
politeness and stance particles at the end of a request (Tagalog "po", "lang", "pala", "muna"; Arabic "yalla";
Malay and Singapore "lah", "lor"; Korean "yo"; Hindi "na"; Japanese "ne"), and fillers where an English
speaker says "um" (Tagalog "ano", Japanese "eto", Arabic "yani"). Such a word asks for nothing: it does not
change where or how far the robot goes. A person listening to "turn around po" hears "turn around".

The rule, stated for any language: a word said (it has a vowel) that is neither a word the reading knows nor an English word
(``english``), nor a slip of one (a typo, a word with one letter changed, a word cut short), nor a compass
abbreviation, is a particle

1. when it ends a clause (one or two of them) whose other words read as a whole instruction, with its
   amount said, nothing left unread and nothing to ask ("turn around po", "go forward two metres yalla";
   "go back konti, a little": the amount said next completes the move; "turn right cuarenta" asks, as the
   word stands where the amount goes), and it does not stand where a place, an object, a unit or a corrected word goes:
   right after a verb ("get konti"), "the", "to", "your", a number, or a correction ("no", "sorry"); or
2. when it is said alone between an instruction and its amount ("go forward, ano, one and a half metres"),
   as a filler is -- only a known filler of another language (``FOREIGN_FILLERS``), as also after a move or
   turn whose amount comes next: an unknown word there may be the way or the amount itself.

Anything else stays, and is read, or asked about, as before: a word standing where the place or the unit goes
("go to the konti", "take konti", "go forward three konti"), a word after a correction ("turn left, no, derecha"), a word
said alone ("basta"), an English word the reading does not know ("go forward two metres diagonally").
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from typing import Final

from langnav.language.intent import Amount
from langnav.language.offline import lexicon as lx
from langnav.language.offline.ask import SPATIAL_WORDS
from langnav.language.offline.english import is_english
from langnav.language.offline.normalize import normalize
from langnav.language.offline.numbers import NUMBER_WORD_LIST, find_quantities
from langnav.language.offline.reading import ASK_DISTANCE, Reading
from langnav.language.offline.vocabulary import VOCABULARY

#: The hesitation words of other languages, where English says "um" (a closed class in each language: Tagalog
#: "ano", Japanese "eto" / "ano", Arabic "yani", Hindi "matlab", Spanish "este" / "pues", Portuguese "tipo",
#: Italian "cioe", German "aeh" / "halt", French "euh" / "bah", Polish "znaczy", Russian "nu", Korean "eum" /
#: "geu"). Only these are taken for a filler where a word stands BETWEEN an instruction and its amount, or
#: after an instruction with no amount of its own: any other unknown word there may be the way or the amount
#: said in the speaker's other language ("move, atras, two metres": Spanish "back"; "turn left, migi, forty
#: five": Japanese "right"; "go back konti, a little"), and the robot asks.
#: (Spanish and Portuguese "este" is also "east": a word that names a way in a common language is never taken for a
#: filler.)
FOREIGN_FILLERS: Final = frozenset({"ano", "eto", "etto", "ettoo", "yani", "yaani", "matlab", "pues", "tipo",
                                    "cioe", "aeh", "halt", "euh", "bah", "znaczy", "nu", "eum", "geu", "ehm"})
#: Reads one clause on its own (the parser's ``read_clause``).
ClauseReader = Callable[[str], Reading]
#: At most this many particles end one clause ("turn around sige po"); more unknown words are no particles.
MAX_PARTICLES: Final = 2
#: A particle has at least this many letters: a single letter may be an abbreviation ("l", "r", "n", "f").
MIN_PARTICLE_LEN: Final = 2
#: A word this long or longer that is one letter away from a word of where or how far is that word misheard
#: or mistyped ("twnety", "metrs"), never a particle; shorter words have too many neighbours ("po" / "to").
MIN_NEIGHBOUR_LEN: Final = 3
#: The compass points abbreviated, as people type them ("go 3 m ne"): a way, never a particle.
COMPASS_ABBREVIATIONS: Final = frozenset({"n", "s", "e", "w", "ne", "nw", "se", "sw", "nne", "ene", "ese", "sse", "ssw",
                                          "wsw", "wnw", "nnw"})
#: Words after which the next word is a place, a unit, or the word a correction puts right: no particle there.
_SLOT_WORDS: Final = frozenset({
    "the", "a", "an", "this", "that", "these", "those", "to", "into", "onto", "towards", "toward", "at", "by", "near",
    "past", "through", "thru", "from", "of", "in", "on", "my", "your", "his", "her", "our", "their", "its", "no",
    "not", "sorry", "mean", "meant", "actually", "rather", "or", "correction", "called", "named",
})
#: Words of where and how far a particle must not be a slip of.
#: (English words only: a particle one letter away from a way word of another language, "pala" / "para", is
#: still a particle; the way words themselves are none, see ``is_particle_word``.)
_WHERE_AND_HOW_FAR: Final = frozenset((SPATIAL_WORDS - lx.FOREIGN_WAY_WORDS) | set(NUMBER_WORD_LIST))
#: The everyday words of side, way, number and unit: a word cut off after two letters may be one of them
#: ("turn left ri": right?). (Rarer words, "port" or "positive", are not recognised from two letters; a place's
#: name cut short, "po" of "post", is no worry where a particle stands, with no "to the" before it.)
_WAYS_AND_AMOUNTS: Final = frozenset(
    {"left", "right", "forward", "forwards", "back", "backward", "backwards", "ahead", "straight", "around", "round",
     "reverse", "sideways", "north", "south", "east", "west", "clockwise", "counterclockwise", "anticlockwise",
     "metre", "metres", "meter", "meters", "feet", "foot", "inch", "inches", "yard", "yards", "degree", "degrees",
     "centimetre", "centimetres", "centimeter", "centimeters", "half", "quarter", "hundred"} | set(NUMBER_WORD_LIST))
#: How the question "how far?" of a move with no amount begins.
_ASK_DISTANCE_START: Final = ASK_DISTANCE.split("{", 1)[0]
_LETTERS: Final = re.compile(r"[a-z]+")
_VOWELS: Final = re.compile(r"[aeiouy]")
#: Verbs of going and turning, said as one word: the word right after one is where its place, its object or its
#: way goes ("go konti", "take konti", "get konti"), never a particle.
_VERBS: Final = frozenset(w for verb in (*lx.GO_VERBS, *lx.ROTATE_VERBS) if " " not in verb for w in (verb,))
_MARKS: Final = ",.;:!?\"'"


def is_particle_word(word: str, known_names: Sequence[str] = ()) -> bool:
    """Whether ``word`` may be a particle of another language (the first half of the rule: what the word is)."""
    bare = word.lower().strip(_MARKS)
    if not _LETTERS.fullmatch(bare) or len(bare) < MIN_PARTICLE_LEN or not _VOWELS.search(bare):
        return False  # (a word said has a vowel: "bbbbb", "xkcd" are noise or typing, not speech)
    if bare in VOCABULARY or bare in lx.STOPWORDS or bare in lx.TYPOS or bare in COMPASS_ABBREVIATIONS:
        return False
    if bare in lx.FOREIGN_WAY_WORDS:
        return False  # a way said in another language ("turn around izquierda"): never a particle
    if any(bare == name.lower() or bare in name.lower().split() for name in known_names):
        return False  # a place the user named
    if is_english(bare) or normalize(bare) != bare:
        return False  # an English word, or one the reading repairs into a word it knows (a typo)
    return not _near_where_or_how_far(bare)


def _near_where_or_how_far(word: str) -> bool:
    """A slip of a word of where or how far: one letter changed, added, dropped or two swapped, or the word's
    start ("lef", "thir"): misheard or mistyped, it may be that word."""
    if any(known.startswith(word) for known in _WAYS_AND_AMOUNTS):
        return True
    return len(word) >= MIN_NEIGHBOUR_LEN and any(
        known.startswith(word) or _one_edit(word, known) for known in _WHERE_AND_HOW_FAR)


def _one_edit(a: str, b: str) -> bool:
    if abs(len(a) - len(b)) > 1:
        return False
    if len(a) == len(b):
        diff = [i for i in range(len(a)) if a[i] != b[i]]
        return len(diff) == 1 or (len(diff) == 2 and diff[1] == diff[0] + 1 and a[diff[0]] == b[diff[1]]
                                  and a[diff[1]] == b[diff[0]])
    short, long_ = (a, b) if len(a) < len(b) else (b, a)
    i = 0
    while i < len(short) and short[i] == long_[i]:
        i += 1
    return short[i:] == long_[i + 1:]


def without_particles(clauses: list[str], read: ClauseReader, known_names: Sequence[str] = ()) -> list[str]:
    """``clauses`` (a prompt split into its instructions) without the particles of another language (module
    docstring): the instructions as the speaker meant them."""
    out: list[str] = []
    for i, clause in enumerate(clauses):
        words = clause.split()
        following = clauses[i + 1] if i + 1 < len(clauses) else None
        if len(words) == 1:
            if out and following is not None and words[0].lower().strip(_MARKS) in FOREIGN_FILLERS \
                    and is_particle_word(words[0], known_names) and _amount_only(following):
                continue  # rule 2: a filler between an instruction and its amount
            out.append(clause)
            continue
        inner = _inner_filler(words, read, known_names)
        if inner is not None:
            words = words[:inner] + words[inner + 1:]  # rule 2 inside one clause: "go back yani two meter"
            clause = " ".join(words)
        keep = len(words)
        while len(words) - keep < MAX_PARTICLES and keep > 1 and is_particle_word(words[keep - 1], known_names):
            keep -= 1
        if keep < len(words) and _particle_slot(words[keep - 1]) \
                and _whole(" ".join(words[:keep]), following, read, words[keep:]):
            out.append(" ".join(words[:keep]))  # rule 1
            continue
        out.append(clause)
    return out


def _inner_filler(words: list[str], read: ClauseReader, known_names: Sequence[str]) -> int | None:
    """Where a known filler of another language stands between an instruction and its amount inside one clause,
    said with no pause marked ("go back yani two meter"): rule 2 as with commas around it."""
    for j in range(1, len(words) - 1):
        if words[j].lower().strip(_MARKS) in FOREIGN_FILLERS and is_particle_word(words[j], known_names) \
                and _amount_only(" ".join(words[j + 1:])) and read(" ".join(words[:j])).steps:
            return j
    return None


def _particle_slot(before: str) -> bool:
    """The word before is no word after which a place, a unit or a corrected word comes."""
    bare = before.lower().strip(_MARKS)
    return bare not in _SLOT_WORDS and bare not in _VERBS and bare not in NUMBER_WORD_LIST \
        and not any(ch.isdigit() for ch in bare)


def _whole(rest: str, following: str | None, read: ClauseReader, particles: Sequence[str] = ()) -> bool:
    """``rest`` reads as a whole instruction: steps, nothing unread, nothing to ask; a move or turn missing its
    amount only when the next clause gives an amount and the words dropped are fillers (``FOREIGN_FILLERS``:
    "go back, ano, a little")."""
    reading = read(rest)
    if not reading.steps or reading.problem is not None or reading.unread:
        return False
    if any(s.amount == Amount.DEFAULT for s in reading.steps) or reading.asks:
        # a move or turn with no amount said ("turn right", "go back"): the word after it stands where the amount
        # goes, and may be it in the speaker's other language ("turn right cuarenta"); only with the amount said
        # next ("go back konti, a little") is the instruction whole without it
        return following is not None and _amount_only(following) \
            and all(q.startswith(_ASK_DISTANCE_START) for q in reading.asks) \
            and all(w.lower().strip(_MARKS) in FOREIGN_FILLERS for w in particles)
    return True


def _amount_only(clause: str) -> bool:
    """An amount with nothing of a way in it ("one and a half metres", "a little", "ninety")."""
    norm = normalize(clause)
    words = norm.split()
    has_amount = bool(find_quantities(norm)) or any(w in NUMBER_WORD_LIST for w in words) or norm in (
        "a little", "a bit", "a little bit", "a touch", "a tad")
    sides = {"left", "right", "forward", "forwards", "back", "backward", "backwards", "ahead", "around", "round",
             "clockwise", "counterclockwise", "anticlockwise", "north", "south", "east", "west"}
    return has_amount and not any(w in sides for w in words)
